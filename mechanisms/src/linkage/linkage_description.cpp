// The reader of linkage description files (docs/linkage-files.md): TOML parsed by toml++ (header-only,
// here and nowhere else, so that the fuzzer instruments the parser too), then every section checked
// strictly, top to bottom, the first problem thrown as "FILE:LINE:COLUMN: problem".

#include "numlab/mechanisms/linkage/linkage_description.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "numlab/linalg/matrix_file.hpp"
#include "numlab/printable_text.hpp"

// toml++ 3.3 states a precondition of its key parser as an assertion that malformed input breaks
// ("[%", "[[[1]]]": marzer/tomlplusplus issue 294, fixed upstream by pull request 301; found here by
// fuzz_linkage_description). With assertions on it aborts; with NDEBUG under clang it becomes
// __builtin_assume, undefined behaviour. With the check skipped, as in a GCC release build, the
// parser goes on to report the input as a syntax error at the right place. So its internal checks
// are skipped in every build, and NDEBUG is hidden while it is included so that none of them can
// turn into an assumption. Everything else is included first, untouched by this.
#pragma push_macro("NDEBUG")
#undef NDEBUG
#define TOML_ASSERT(expr) static_cast<void>(0)
#define TOML_HEADER_ONLY 1
#include <toml++/toml.h>
#pragma pop_macro("NDEBUG")

namespace numlab::mechanisms {

namespace {

// A description has at most this many joints: far beyond any teaching linkage, and it keeps the
// pairwise checks of a body's local points quick on any file up to the 16 MiB input limit.
constexpr std::size_t max_joints = 1000;
constexpr std::size_t max_joint_name = 32;
constexpr std::size_t max_linkage_name = 64;
constexpr std::size_t max_title = 200;
constexpr double max_magnitude = 1e150, min_length = 1e-150;  // squares stay normal numbers
// Two local points of a body closer than this times the body's size coincide; all its points
// within it of one line are collinear (the size: the largest distance between two of its points).
constexpr double body_relative_tolerance = 1e-9;

int clamped(toml::source_index index) { return static_cast<int>(std::min<toml::source_index>(index, INT_MAX)); }

SourcePlace place_of(const toml::source_region& region) {
  return {clamped(region.begin.line), clamped(region.begin.column)};
}
SourcePlace place_of(const toml::node& node) { return place_of(node.source()); }
SourcePlace place_of(const toml::key& key) { return place_of(key.source()); }

bool before(SourcePlace a, SourcePlace b) { return std::pair{a.line, a.column} < std::pair{b.line, b.column}; }

std::string quoted(std::string_view text) { return linalg::quoted_token(text); }

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

bool is_name_char(char c, bool dash_allowed) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         (dash_allowed && c == '-');
}

bool valid_name(std::string_view name, std::size_t max_length, bool dash_allowed) {
  return !name.empty() && name.size() <= max_length &&
         std::all_of(name.begin(), name.end(), [&](char c) { return is_name_char(c, dash_allowed); });
}

// The keys of a table in the order the file writes them (toml++ keeps a sorted map).
std::vector<std::pair<const toml::key*, const toml::node*>> in_file_order(const toml::table& table) {
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  for (const auto& [key, node] : table) entries.emplace_back(&key, &node);
  std::stable_sort(entries.begin(), entries.end(),
                   [](const auto& a, const auto& b) { return before(place_of(*a.first), place_of(*b.first)); });
  return entries;
}

// Does a line of the text start the linkage table ("[linkage]", "linkage = {", "linkage.name = ")?
// Decides whether a file TOML cannot parse is reported as a linkage with a syntax error or as
// something that is not a linkage at all.
bool mentions_linkage_table(std::string_view text) {
  text = linalg::without_byte_order_mark(text);
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    std::string_view line = text.substr(begin, end - begin);
    begin = end + 1;
    const auto skip = [&](std::string_view characters) {
      line.remove_prefix(std::min(line.find_first_not_of(characters), line.size()));
    };
    skip(" \t");
    if (line.starts_with('[')) line.remove_prefix(1);
    skip(" \t\"'");
    constexpr std::string_view key = "linkage";
    if (line.starts_with(key) && (line.size() == key.size() || !is_name_char(line[key.size()], true))) return true;
  }
  return false;
}

// toml++ 3.3's table of non-ASCII blanks reaches __builtin_unreachable (undefined behaviour) for the
// code points below, wherever its parser asks whether one is a blank: upstream issues 190 and 295,
// fixed by pull request 305; found here by fuzz_linkage_description. Checked exhaustively under UBSan:
// every other code point is safe. The first such character in the text, with its place, or nothing.
struct UnsafeCharacter {
  char32_t code = 0;
  SourcePlace place;
};

bool unsafe_for_toml(char32_t c) {
  return (c >= 0xA1 && c <= 0x499) || (c >= 0x2C5E && c <= 0x3057 && c != 0x3000) || (c >= 0xFB26 && c <= 0xFEFE);
}

std::optional<UnsafeCharacter> first_unsafe_character(std::string_view text) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < text.size(); ++column) {
    const auto lead = static_cast<unsigned char>(text[i++]);
    if (lead == '\n') {
      ++line;
      column = 0;
      continue;
    }
    // Decoded leniently (toml++ refuses ill-formed UTF-8 itself): a lead byte and its continuations.
    const int extra = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
    char32_t code = extra == 0 ? lead : lead & (0x3Fu >> extra);
    for (int k = 0; k < extra && i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0u) == 0x80u; ++k) {
      code = (code << 6) | (static_cast<unsigned char>(text[i++]) & 0x3Fu);
    }
    if (unsafe_for_toml(code)) return UnsafeCharacter{code, {line, column}};
  }
  return std::nullopt;
}

std::string code_point_text(char32_t code) {
  static constexpr char hex[] = "0123456789ABCDEF";
  std::string digits = "U+";
  for (int shift = 12; shift >= 0; shift -= 4) digits += hex[(code >> shift) & 0xFu];
  return digits;
}

// toml++ 3.3 parses dotted keys ("a.a.a... = 1") and table headers ("[a.a.a...]") by recursion with no
// limit of its own: nested 200,000 deep they overflow the stack. So the raw text is scanned first and
// refused at the first key part or array bracket deeper than this: far beyond any linkage file.
constexpr int max_nesting = 64;

// A small TOML lexer, just enough to count nesting: strings and comments are skipped (a dot or a bracket
// in them counts for nothing), the parts of each key are counted, and arrays and inline tables are
// tracked. A level is a key part or an array: under "[t.u]", "a.b = [[1]]" puts the 1 at level 6.
class NestingScan {
 public:
  explicit NestingScan(std::string_view text) : text_(text) {
    if (text_.starts_with("\xEF\xBB\xBF")) index_ = 3;  // a byte-order mark: not a column
  }

  // The place of the first key part or array bracket nested deeper than max_nesting, or nothing.
  std::optional<SourcePlace> first_too_deep() {
    while (!too_deep_ && index_ < text_.size()) step();
    return too_deep_;
  }

 private:
  struct Frame {
    char bracket;  // '[' an array, '{' an inline table
    int depth;     // an array: the level of its items; an inline table: the level of the table itself
  };

  char peek(std::size_t ahead = 0) const { return index_ + ahead < text_.size() ? text_[index_ + ahead] : '\0'; }

  void advance() {
    if (text_[index_] == '\n') {
      ++line_;
      column_ = 0;
    }
    ++index_;
    // Columns count code points: a UTF-8 continuation byte is part of the character before it.
    if (index_ < text_.size() && (static_cast<unsigned char>(text_[index_]) & 0xC0u) != 0x80u) ++column_;
  }

  SourcePlace place() const { return {line_, column_}; }

  void check_level(int level) {
    if (level > max_nesting && !too_deep_) too_deep_ = place();
  }

  void step() {
    const char c = peek();
    if (c == ' ' || c == '\t' || c == '\r') return advance();
    if (c == '\n') {
      advance();
      if (frames_.empty()) expecting_key_ = true;  // a new line of the root table: a key or a header
      return;
    }
    if (c == '#') return skip_comment();
    if (expecting_key_) return step_in_key_position(c);
    step_in_value(c);
  }

  void step_in_key_position(char c) {
    expecting_key_ = false;
    if (frames_.empty() && c == '[') return read_header();
    if (!frames_.empty() && c == '}') return close_bracket();
    const int base = frames_.empty() ? header_depth_ : frames_.back().depth;
    value_depth_ = base + read_key_parts(base, '=');
  }

  void step_in_value(char c) {
    if (c == '"' || c == '\'') return skip_string();
    if (c == '[') {
      const int items = (frames_.empty() || frames_.back().bracket == '{' ? value_depth_ : frames_.back().depth) + 1;
      check_level(items);
      frames_.push_back({'[', items});
    } else if (c == '{') {
      const int table = frames_.empty() || frames_.back().bracket == '{' ? value_depth_ : frames_.back().depth;
      frames_.push_back({'{', table});
      expecting_key_ = true;
    } else if (c == ']' || c == '}') {
      return close_bracket();
    } else if (c == ',' && !frames_.empty() && frames_.back().bracket == '{') {
      expecting_key_ = true;
    }
    advance();
  }

  void close_bracket() {
    if (!frames_.empty()) {
      value_depth_ = frames_.back().bracket == '[' ? frames_.back().depth - 1 : frames_.back().depth;
      frames_.pop_back();
    }
    advance();
  }

  // "[a.b]" or "[[a.b]]" at the start of a line: the keys below it start at its number of parts.
  void read_header() {
    advance();
    if (peek() == '[') advance();
    header_depth_ = read_key_parts(0, ']');
  }

  // The parts of a key (bare, quoted, separated by dots), up to the end character (consumed) or the
  // end of the line; each part checked at its first character, on top of the base level.
  int read_key_parts(int base, char end) {
    int parts = 0;
    bool part_expected = true;
    while (!too_deep_ && index_ < text_.size() && peek() != '\n') {
      const char c = peek();
      if (c == end) {
        advance();
        break;
      }
      if (c == '.') {
        part_expected = true;
        advance();
        continue;
      }
      if (c != ' ' && c != '\t' && part_expected) {
        part_expected = false;
        check_level(base + ++parts);
      }
      if (c == '"' || c == '\'') skip_string();
      else advance();
    }
    return std::max(parts, 1);
  }

  void skip_comment() {
    while (index_ < text_.size() && peek() != '\n') advance();
  }

  // A string from its opening quote: '...' and "..." end at the line's end at the latest; '''...''' and
  // """...""" may span lines. In basic strings (") a backslash escapes the next character.
  void skip_string() {
    const char quote = peek();
    const bool multi_line = peek(1) == quote && peek(2) == quote;
    for (int k = 0; k < (multi_line ? 3 : 1); ++k) advance();
    while (index_ < text_.size()) {
      const char c = peek();
      if (c == '\n' && !multi_line) return;
      if (c == '\\' && quote == '"' && index_ + 1 < text_.size() && (multi_line || peek(1) != '\n')) {
        advance();
      } else if (c == quote && (!multi_line || (peek(1) == quote && peek(2) == quote))) {
        return close_string(quote, multi_line);
      }
      advance();
    }
  }

  // The closing quote or quotes; a multi-line string may end in up to two more, part of its text.
  void close_string(char quote, bool multi_line) {
    for (int k = 0; k < (multi_line ? 3 : 1); ++k) advance();
    for (int k = 0; multi_line && k < 2 && peek() == quote; ++k) advance();
  }

  std::string_view text_;
  std::size_t index_ = 0;
  int line_ = 1;
  int column_ = 1;
  bool expecting_key_ = true;
  int header_depth_ = 0;  // the number of parts of the last table header
  int value_depth_ = 0;   // the level of the value after the last key
  std::vector<Frame> frames_;
  std::optional<SourcePlace> too_deep_;
};

class Reader {
 public:
  Reader(const toml::table& root, const std::string& file) : root_(root), file_(file) {}

  LinkageDescription read() {
    description_.file = file_;
    const toml::node* linkage = root_.get("linkage");
    if (linkage == nullptr) fail({}, "not a linkage description: no [linkage] table");
    check_top_level_keys();
    read_linkage(table_of(*linkage, "[linkage]"));
    read_joints();
    for_each_table("link", [&](const toml::table& t) { read_link(t); });
    for_each_table("body", [&](const toml::table& t) { read_body(t); });
    for_each_table("slider", [&](const toml::table& t) { read_slider(t); });
    const toml::node* driver = root_.get("driver");
    if (driver == nullptr) fail({}, "no [driver] table: a linkage needs a driver ([driver]) or two ([[driver]] twice)");
    read_drivers(*driver);
    check_link_names();
    check_output();
    if (const toml::node* trace = linkage->as_table()->get("trace")) read_trace(*trace);
    const auto lines = link_lines(description_);
    for_each_table("load", [&](const toml::table& t) { read_load(t, lines); });
    return std::move(description_);
  }

 private:
  [[noreturn]] void fail(SourcePlace place, const std::string& problem) const {
    throw LinkageFileError(file_, place, problem);
  }

  // --- the pieces every section uses ---------------------------------------------------------

  const toml::table& table_of(const toml::node& node, const std::string& what) const {
    if (const toml::table* table = node.as_table()) return *table;
    fail(place_of(node), what + " must be a table");
  }

  // Every key of `table` must be one of `allowed`.
  void check_keys(const toml::table& table, std::initializer_list<std::string_view> allowed,
                  const std::string& where) const {
    for (const auto& [key, node] : in_file_order(table)) {
      if (std::find(allowed.begin(), allowed.end(), key->str()) == allowed.end()) {
        fail(place_of(*key), "unknown key " + quoted(key->str()) + " in " + where);
      }
    }
  }

  const toml::node& required(const toml::table& table, std::string_view key, const std::string& where) const {
    if (const toml::node* node = table.get(key)) return *node;
    fail(place_of(table), where + " needs " + quoted(key));
  }

  std::string_view string_of(const toml::node& node, const std::string& what) const {
    if (const auto* text = node.as_string()) return text->get();
    fail(place_of(node), what + " must be a string");
  }

  double number_of(const toml::node& node, const std::string& what) const {
    std::optional<double> value;
    if (const auto* integer = node.as_integer()) value = static_cast<double>(integer->get());
    if (const auto* floating = node.as_floating_point()) value = floating->get();
    if (!value) fail(place_of(node), what + " must be a number");
    if (!std::isfinite(*value)) fail(place_of(node), what + " must be finite, got " + number_text(*value));
    // The model squares distances: beyond 1e150 they overflow (and below 1e-150 a length's square
    // underflows, checked with the lengths).
    if (std::abs(*value) > max_magnitude) {
      fail(place_of(node), what + " is " + number_text(*value) + ": numbers must be at most 1e150 in size (their squares overflow)");
    }
    return *value;
  }

  Eigen::Vector2d point_of(const toml::node& node, const std::string& what) const {
    const toml::array* pair = node.as_array();
    if (pair == nullptr || pair->size() != 2) fail(place_of(node), what + " must be [x, y], two numbers");
    return {number_of(*pair->get(0), what + ": x"), number_of(*pair->get(1), what + ": y")};
  }

  // The joint a string names; it must exist.
  int joint_of(const toml::node& node, const std::string& what) const {
    const std::string_view name = string_of(node, what);
    const auto found = joint_indices_.find(name);
    if (found == joint_indices_.end()) fail(place_of(node), "unknown joint " + quoted(name));
    return found->second;
  }

  // Each table of the array of tables [[key]], if there is one.
  template <typename Read>
  void for_each_table(std::string_view key, Read read) const {
    const toml::node* node = root_.get(key);
    if (node == nullptr) return;
    for (const toml::node& item : *node->as_array()) read(table_of(item, "[[" + std::string(key) + "]]"));
  }

  // --- the sections, in the order they are checked ----------------------------------------------

  void check_top_level_keys() const {
    struct Section {
      std::string_view key;
      bool array_of_tables;
    };
    static constexpr Section sections[] = {{"linkage", false}, {"ground", false}, {"joints", false},
                                           {"link", true},     {"body", true},    {"slider", true},
                                           {"driver", false},  {"load", true}};
    for (const auto& entry : in_file_order(root_)) {
      const toml::key* key = entry.first;
      const toml::node* node = entry.second;
      const auto* section = std::find_if(std::begin(sections), std::end(sections),
                                         [&](const Section& s) { return s.key == key->str(); });
      const std::string name = printable(key->str().substr(0, 40));
      if (section == std::end(sections)) {
        const bool table = node->is_table();
        const bool tables = node->is_array_of_tables();
        fail(place_of(*key), table    ? "unknown table [" + name + "]"
                             : tables ? "unknown table [[" + name + "]]"
                                      : "unknown key " + quoted(key->str()));
      }
      if (section->array_of_tables && !node->is_array_of_tables()) {
        fail(place_of(*key), "write [[" + name + "]], one table per item");
      }
      if (section->key == "driver" && node->is_array_of_tables()) continue;  // [[driver]]: one or two drivers
      if (!section->array_of_tables && !node->is_table()) fail(place_of(*key), "[" + name + "] must be a table");
    }
  }

  void read_linkage(const toml::table& linkage) {
    check_keys(linkage, {"name", "title", "output", "gravity", "trace"}, "[linkage]");
    if (const toml::node* gravity = linkage.get("gravity")) {
      description_.gravity = number_of(*gravity, "the linkage's gravity");
      if (description_.gravity < 0.0) {
        fail(place_of(*gravity), "gravity is " + number_text(description_.gravity) +
                                     ": give its size in m/s^2 (it pulls along -y), at least 0");
      }
    }
    const toml::node& name_node = required(linkage, "name", "[linkage]");
    const std::string_view name = string_of(name_node, "the linkage's name");
    if (!valid_name(name, max_linkage_name, true)) {
      fail(place_of(name_node), "invalid linkage name " + quoted(name) + ": use 1 to " +
                                    std::to_string(max_linkage_name) + " letters, digits, '-' or '_'");
    }
    description_.name = name;
    if (const toml::node* title_node = linkage.get("title")) {
      const std::string_view title = string_of(*title_node, "the linkage's title");
      if (title.size() > max_title) fail(place_of(*title_node), "title longer than " + std::to_string(max_title) + " bytes");
      // printable() escapes C0 and C1 controls, DEL, the bidi controls (overrides, isolates), invisible marks.
      if (printable(title) != title) {
        fail(place_of(*title_node), "title has a control character: " + quoted(title));
      }
      description_.title = title;
    }
    if (const toml::node* output_node = linkage.get("output")) {
      description_.output = string_of(*output_node, "the linkage's output");
      description_.output_place = place_of(*output_node);
    }
  }

  // Link and body names become CSV columns (angle_NAME): no two alike, defaults included.
  void check_link_names() const {
    std::map<std::string, int, std::less<>> lines;  // name -> line of its item
    for (const LinkLine& line : link_lines(description_)) {
      if (const auto [it, added] = lines.emplace(line.name, line.place.line); !added) {
        fail(line.place, std::string(line.body ? "body" : "link") + " name " + quoted(line.name) +
                             " is already the name of the link or body at line " + std::to_string(it->second));
      }
    }
  }

  // `trace = ["P", ...]`: moving joints, each once, whose paths the drawing highlights.
  void read_trace(const toml::node& node) {
    const toml::array* names = node.as_array();
    if (names == nullptr || names->empty()) fail(place_of(node), "trace must be a list of moving joints' names, e.g. [\"P\"]");
    for (const toml::node& item : *names) {
      const int joint = joint_of(item, "a trace entry");
      if (description_.joints[static_cast<std::size_t>(joint)].ground) {
        fail(place_of(item), "trace names the ground joint " + joint_name(joint) + ", which has no path: name a moving joint");
      }
      if (std::find(description_.trace.begin(), description_.trace.end(), joint) != description_.trace.end()) {
        fail(place_of(item), "trace names " + joint_name(joint) + " twice");
      }
      description_.trace.push_back(joint);
    }
  }

  // `output` names a link, a body or a slider's joint.
  void check_output() const {
    if (description_.output.empty() && description_.output_place.line == 0) return;
    if (!find_output(description_, description_.output)) {
      fail(description_.output_place, "unknown output " + quoted(description_.output) + ": name one of the " +
                                          output_choices(description_));
    }
  }

  void read_joints() {
    read_joint_table("ground", true);
    read_joint_table("joints", false);
    const bool none_moving = std::none_of(description_.joints.begin(), description_.joints.end(),
                                          [](const JointSpec& joint) { return !joint.ground; });
    if (none_moving) {
      const toml::node* joints = root_.get("joints");
      fail(joints ? place_of(*joints) : SourcePlace{}, "no moving joints: list them in [joints]");
    }
  }

  void read_joint_table(std::string_view key, bool ground) {
    const toml::node* node = root_.get(key);
    if (node == nullptr) return;
    for (const auto& [name_key, value] : in_file_order(*node->as_table())) {
      const std::string_view name = name_key->str();
      const SourcePlace place = place_of(*name_key);
      if (!valid_name(name, max_joint_name, false)) {
        fail(place, "invalid joint name " + quoted(name) + ": use 1 to " + std::to_string(max_joint_name) +
                        " letters, digits or '_'");
      }
      if (const auto other = joint_indices_.find(name); other != joint_indices_.end()) {
        fail(place, "joint " + quoted(name) + " is already defined at line " +
                        std::to_string(description_.joints[static_cast<std::size_t>(other->second)].place.line));
      }
      if (description_.joints.size() == max_joints) fail(place, "more than " + std::to_string(max_joints) + " joints");
      const Eigen::Vector2d position = point_of(*value, "the position of joint " + quoted(name));
      joint_indices_.emplace(name, static_cast<int>(description_.joints.size()));
      description_.joints.push_back({std::string(name), ground, position, place});
    }
  }

  // The two joints of a link, or of a link-like pair: two names of existing, different joints.
  void read_link(const toml::table& link) {
    check_keys(link, {"name", "joints", "length"}, "[[link]]");
    const toml::node& joints_node = required(link, "joints", "[[link]]");
    const toml::array* joints = joints_node.as_array();
    if (joints == nullptr || joints->size() != 2) fail(place_of(joints_node), "a link's joints must be two joint names");
    LinkSpec spec;
    spec.place = place_of(link);
    spec.first = joint_of(*joints->get(0), "a link's joint");
    spec.second = joint_of(*joints->get(1), "a link's joint");
    const std::string& first_name = description_.joints[static_cast<std::size_t>(spec.first)].name;
    const std::string& second_name = description_.joints[static_cast<std::size_t>(spec.second)].name;
    if (spec.first == spec.second) fail(place_of(joints_node), "a link from joint " + quoted(first_name) + " to itself");
    const auto pair = std::minmax(spec.first, spec.second);
    if (const auto [it, added] = link_lines_.emplace(pair, spec.place.line); !added) {
      fail(place_of(joints_node), "a second link between " + quoted(first_name) + " and " + quoted(second_name) +
                                      " (the first is at line " + std::to_string(it->second) + ")");
    }
    if (const toml::node* name_node = link.get("name")) {
      const std::string_view name = string_of(*name_node, "a link's name");
      if (!valid_name(name, max_joint_name, true)) {
        fail(place_of(*name_node), "invalid link name " + quoted(name) + ": use 1 to " +
                                       std::to_string(max_joint_name) + " letters, digits, '-' or '_'");
      }
      spec.name = name;
      spec.name_place = place_of(*name_node);
    }
    const toml::node& length_node = required(link, "length", "[[link]]");
    spec.length = number_of(length_node, "a link's length");
    if (spec.length <= 0.0) {
      fail(place_of(length_node), "a link's length must be positive, got " + number_text(spec.length));
    }
    if (spec.length < min_length) {
      fail(place_of(length_node), "a link's length is " + number_text(spec.length) +
                                      ": lengths must be at least 1e-150 (their squares underflow)");
    }
    description_.links.push_back(spec);
  }

  void read_body(const toml::table& body) {
    check_keys(body, {"name", "joints", "local"}, "[[body]]");
    BodySpec spec;
    spec.place = place_of(body);
    spec.name = "body " + std::to_string(description_.bodies.size() + 1);
    if (const toml::node* name_node = body.get("name")) {
      const std::string_view name = string_of(*name_node, "a body's name");
      if (!valid_name(name, max_joint_name, true)) {
        fail(place_of(*name_node), "invalid body name " + quoted(name) + ": use 1 to " +
                                       std::to_string(max_joint_name) + " letters, digits, '-' or '_'");
      }
      spec.name = name;
    }
    const toml::node& joints_node = required(body, "joints", "[[body]]");
    const toml::array* joints = joints_node.as_array();
    if (joints == nullptr) fail(place_of(joints_node), "a body's joints must be a list of joint names");
    if (joints->size() < 3) {
      fail(place_of(joints_node), "a body needs at least 3 joints, got " + std::to_string(joints->size()) +
                                      " (two joints make a [[link]])");
    }
    std::vector<bool> in_body(description_.joints.size(), false);
    for (const toml::node& item : *joints) {
      const int joint = joint_of(item, "a body's joint");
      if (in_body[static_cast<std::size_t>(joint)]) {
        fail(place_of(item), "joint " + quoted(description_.joints[static_cast<std::size_t>(joint)].name) +
                                 " appears twice in the body");
      }
      in_body[static_cast<std::size_t>(joint)] = true;
      spec.joints.push_back(joint);
    }
    const toml::node& local_node = required(body, "local", "[[body]]");
    const toml::array* local = local_node.as_array();
    if (local == nullptr || local->size() != joints->size()) {
      fail(place_of(local_node), "'local' must give one [x, y] per joint: " + std::to_string(joints->size()) +
                                     " joints, " + (local ? std::to_string(local->size()) : std::string("no")) +
                                     " points");
    }
    for (std::size_t k = 0; k < local->size(); ++k) {
      spec.local.push_back(point_of(*local->get(k), "local point " + std::to_string(k + 1)));
    }
    spec.collinear = check_body_shape(spec, place_of(local_node));
    description_.bodies.push_back(std::move(spec));
  }

  // No two local points coincide (relative to the body's size). Returns whether all lie on one line:
  // a bar with points on it or on its extension, rigid all the same.
  bool check_body_shape(const BodySpec& body, SourcePlace place) const {
    const std::size_t n = body.local.size();
    double size = 0.0;
    std::size_t far_a = 0, far_b = 1;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        if (const double d = (body.local[i] - body.local[j]).norm(); d > size) {
          size = d;
          far_a = i;
          far_b = j;
        }
      }
    }
    if (size < min_length) {
      fail(place, "body " + quoted(body.name) + " is " + number_text(size) + " across: a body must be at least 1e-150 across "
                  "(its squared distances underflow)");
    }
    const double tolerance = body_relative_tolerance * size;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        if ((body.local[i] - body.local[j]).norm() <= tolerance) {
          fail(place, "local points of joints " + joint_name(body.joints[i]) + " and " + joint_name(body.joints[j]) +
                          " coincide in body " + quoted(body.name));
        }
      }
    }
    const Eigen::Vector2d axis = (body.local[far_b] - body.local[far_a]) / size;
    double height = 0.0;
    for (const Eigen::Vector2d& p : body.local) {
      const Eigen::Vector2d r = p - body.local[far_a];
      height = std::max(height, std::abs(axis.x() * r.y() - axis.y() * r.x()));
    }
    return height <= tolerance;
  }

  std::string joint_name(int index) const { return quoted(description_.joints[static_cast<std::size_t>(index)].name); }

  void read_slider(const toml::table& slider) {
    check_keys(slider, {"joint", "through", "angle", "line", "offset"}, "[[slider]]");
    SliderSpec spec;
    spec.place = place_of(slider);
    const toml::node& joint_node = required(slider, "joint", "[[slider]]");
    spec.joint = joint_of(joint_node, "a slider's joint");
    if (description_.joints[static_cast<std::size_t>(spec.joint)].ground) {
      fail(place_of(joint_node), "a slider on ground joint " + joint_name(spec.joint) + ": it cannot move");
    }
    for (const SliderSpec& other : description_.sliders) {
      if (other.joint == spec.joint) {
        fail(place_of(joint_node), "joint " + joint_name(spec.joint) + " already has a slider at line " +
                                       std::to_string(other.place.line));
      }
    }
    const toml::node* through = slider.get("through");
    const toml::node* line = slider.get("line");
    if ((through == nullptr) == (line == nullptr)) {
      fail(through != nullptr ? place_of(*line) : spec.place,
           "a [[slider]] runs on a fixed line (through = [x, y]) or on a moving link's line (line = [\"B\", \"C\"]): "
           "give one of the two");
    }
    spec.angle_place = spec.place;
    if (line != nullptr) return read_slider_on_link(slider, *line, spec);
    if (const toml::node* offset = slider.get("offset")) {
      fail(place_of(*offset), "a slider's offset goes with line = [\"B\", \"C\"]; a fixed line is placed by 'through'");
    }
    spec.through = point_of(*through, "a slider's 'through' point");
    if (const toml::node* angle = slider.get("angle")) {
      spec.angle_deg = number_of(*angle, "a slider's angle");
      spec.angle_place = place_of(*angle);
    }
    description_.sliders.push_back(spec);
  }

  // [[slider]] with line = ["B", "C"]: the joint in a slot along the line of two joints of one link or
  // body, `offset` to its left.
  void read_slider_on_link(const toml::table& slider, const toml::node& line_node, SliderSpec& spec) {
    if (const toml::node* angle = slider.get("angle")) {
      fail(place_of(*angle), "a slider on a link runs along its line B -> C: 'angle' goes with 'through' only");
    }
    const toml::array* line = line_node.as_array();
    if (line == nullptr || line->size() != 2) fail(place_of(line_node), "a slider's line must be two joint names, [\"B\", \"C\"]");
    spec.line_from = joint_of(*line->get(0), "a slider's line joint");
    spec.line_to = joint_of(*line->get(1), "a slider's line joint");
    for (const toml::node* item : {line->get(0), line->get(1)}) {
      if (joint_of(*item, "a slider's line joint") == spec.joint) {
        fail(place_of(*item), "the slider's joint " + joint_name(spec.joint) + " cannot also define its line");
      }
    }
    if (spec.line_from == spec.line_to) fail(place_of(line_node), "a slider's line needs two different joints");
    if (!linked(spec.line_from, spec.line_to)) {
      fail(place_of(line_node), "the slider's line " + joint_name(spec.line_from) + " -> " + joint_name(spec.line_to) +
                                    " is not on one [[link]] or [[body]]: name two joints of the link that carries the slot");
    }
    if (const toml::node* offset = slider.get("offset")) spec.offset = number_of(*offset, "a slider's offset");
    description_.sliders.push_back(spec);
  }

  // [[load]]: joint = "B" with force = [Fx, Fy] or mass = m; or link = "name" with torque = T.
  void read_load(const toml::table& load, const std::vector<LinkLine>& lines) {
    check_keys(load, {"joint", "link", "force", "torque", "mass"}, "[[load]]");
    LoadSpec spec;
    spec.place = place_of(load);
    const toml::node* joint = load.get("joint");
    const toml::node* link = load.get("link");
    if ((joint == nullptr) == (link == nullptr)) {
      fail(joint != nullptr ? place_of(*link) : spec.place,
           "a [[load]] acts on a joint (joint = \"B\") or on a link or body (link = \"name\"): give one of the two");
    }
    const auto refuse = [&](std::string_view key, const std::string& why) {
      if (const toml::node* node = load.get(key)) fail(place_of(*node), why);
    };
    if (link != nullptr) {
      const std::string_view name = string_of(*link, "a load's link");
      const auto found = std::find_if(lines.begin(), lines.end(), [&](const LinkLine& l) { return l.name == name; });
      if (found == lines.end()) {
        fail(place_of(*link), "unknown link or body " + quoted(name) + " for a torque: name one of the " +
                                  output_choices(description_).substr(0, 400));
      }
      refuse("force", "a force acts at a joint: write joint = \"...\", not link");
      refuse("mass", "a mass sits at a joint: write joint = \"...\", not link");
      spec.kind = LoadKind::torque;
      spec.line = static_cast<int>(found - lines.begin());
      spec.torque = number_of(required(load, "torque", "a [[load]] on a link"), "a load's torque");
    } else {
      spec.joint = joint_of(*joint, "a load's joint");
      refuse("torque", "a torque acts on a link or body: write link = \"name\", not joint");
      const toml::node* force = load.get("force");
      const toml::node* mass = load.get("mass");
      if ((force == nullptr) == (mass == nullptr)) {
        fail(force != nullptr ? place_of(*mass) : spec.place, "a [[load]] at a joint gives force = [Fx, Fy] or mass = m, one of the two");
      }
      if (force != nullptr) {
        spec.kind = LoadKind::force;
        spec.force = point_of(*force, "a load's force");
      } else {
        spec.kind = LoadKind::mass;
        spec.mass = number_of(*mass, "a load's mass");
        if (spec.mass < 0.0) fail(place_of(*mass), "a load's mass must be at least 0, got " + number_text(spec.mass));
      }
    }
    description_.loads.push_back(spec);
  }

  // [driver], or [[driver]] given once or twice: a mechanism of mobility 2 has two inputs.
  void read_drivers(const toml::node& node) {
    const toml::array* drivers = node.as_array();
    if (drivers == nullptr) return read_driver(table_of(node, "[driver]"), description_.driver);
    if (drivers->size() > 2) {
      fail(place_of(*drivers->get(2)), "a third [[driver]]: a linkage has one driver or two (" +
                                           std::to_string(drivers->size()) + " given)");
    }
    read_driver(table_of(*drivers->get(0), "[[driver]]"), description_.driver);
    if (drivers->size() < 2) return;
    DriverSpec& second = description_.second_driver.emplace();
    read_driver(table_of(*drivers->get(1), "[[driver]]"), second);
    if (second.kind == DriverKind::motor) {
      fail(second.place, "the second [[driver]] is a motor: a held second input may be a crank, a slider or an "
                         "actuator (list the motor first)");
    }
    if (second.joint == description_.driver.joint && second.kind == description_.driver.kind &&
        second.pivot == description_.driver.pivot && second.from == description_.driver.from) {
      fail(second.place, "the second [[driver]] drives what the first already drives");
    }
  }

  void read_driver(const toml::table& driver, DriverSpec& target) {
    reading_ = &target;
    DriverSpec& spec = target;
    spec.place = place_of(driver);
    const toml::node& type_node = required(driver, "type", "[driver]");
    const std::string_view type = string_of(type_node, "the driver's type");
    if (type == "crank") {
      check_keys(driver, {"type", "pivot", "joint", "angle"}, "a crank [driver]");
      read_crank(driver);
    } else if (type == "slider") {
      check_keys(driver, {"type", "joint", "travel"}, "a slider [driver]");
      read_slider_driver(driver);
    } else if (type == "actuator") {
      check_keys(driver, {"type", "joints", "length"}, "an actuator [driver]");
      read_actuator(driver);
    } else if (type == "motor") {
      check_keys(driver, {"type", "pivot", "from", "joint", "angle"}, "a motor [driver]");
      read_motor(driver);
    } else {
      fail(place_of(type_node),
           "unknown driver type " + quoted(type) + ": use \"crank\", \"slider\", \"actuator\" or \"motor\"");
    }
  }

  // An actuator: a driven distance between two joints that no link or body already holds apart.
  void read_actuator(const toml::table& driver) {
    DriverSpec& spec = *reading_;
    spec.kind = DriverKind::actuator;
    const toml::node& joints_node = required(driver, "joints", "[driver]");
    const toml::array* joints = joints_node.as_array();
    if (joints == nullptr || joints->size() != 2) fail(place_of(joints_node), "an actuator's joints must be two joint names");
    spec.from = joint_of(*joints->get(0), "an actuator's joint");
    spec.joint = joint_of(*joints->get(1), "an actuator's joint");
    if (spec.from == spec.joint) fail(place_of(joints_node), "an actuator from joint " + joint_name(spec.from) + " to itself");
    if (description_.joints[static_cast<std::size_t>(spec.from)].ground &&
        description_.joints[static_cast<std::size_t>(spec.joint)].ground) {
      fail(place_of(joints_node), "an actuator between two ground joints cannot move anything");
    }
    if (linked(spec.from, spec.joint)) {
      fail(place_of(joints_node), "an actuator between " + joint_name(spec.from) + " and " + joint_name(spec.joint) +
                                      ", which a [[link]] or [[body]] already holds at a fixed distance");
    }
    const toml::node& length_node = required(driver, "length", "[driver]");
    spec.reference = number_of(length_node, "the actuator's length");
    spec.reference_place = place_of(length_node);
    if (spec.reference <= 0.0) {
      fail(place_of(length_node), "the actuator's length must be positive, got " + number_text(spec.reference));
    }
  }

  // A motor: the angle from pivot -> from to pivot -> joint, the two on different links or bodies
  // that share the pivot.
  void read_motor(const toml::table& driver) {
    DriverSpec& spec = *reading_;
    spec.kind = DriverKind::motor;
    const toml::node& pivot_node = required(driver, "pivot", "[driver]");
    spec.pivot = joint_of(pivot_node, "the motor's pivot");
    const toml::node& from_node = required(driver, "from", "[driver]");
    spec.from = joint_of(from_node, "the motor's 'from' joint");
    const toml::node& joint_node = required(driver, "joint", "[driver]");
    spec.joint = joint_of(joint_node, "the motor's joint");
    for (const auto& [node, joint] : {std::pair{&from_node, spec.from}, std::pair{&joint_node, spec.joint}}) {
      if (joint == spec.pivot) fail(place_of(*node), "the motor's pivot " + joint_name(spec.pivot) + " cannot also be its 'from' or 'joint'");
      if (!linked(spec.pivot, joint)) {
        fail(place_of(*node), "the motor's joint " + joint_name(joint) + " is on no [[link]] or [[body]] with pivot " +
                                  joint_name(spec.pivot));
      }
    }
    if (spec.from == spec.joint || linked(spec.from, spec.joint)) {
      fail(place_of(joint_node), "the motor's 'from' " + joint_name(spec.from) + " and 'joint' " + joint_name(spec.joint) +
                                     " are on one link or body: a motor turns one link against another");
    }
    if (description_.joints[static_cast<std::size_t>(spec.from)].ground &&
        description_.joints[static_cast<std::size_t>(spec.pivot)].ground) {
      fail(place_of(from_node), "a motor against the ground: pivot and 'from' are both ground joints; write type = \"crank\"");
    }
    const toml::node& angle_node = required(driver, "angle", "[driver]");
    spec.reference = number_of(angle_node, "the motor's angle");
    spec.reference_place = place_of(angle_node);
  }

  void read_crank(const toml::table& driver) {
    DriverSpec& spec = *reading_;
    spec.kind = DriverKind::crank;
    const toml::node& pivot_node = required(driver, "pivot", "[driver]");
    spec.pivot = joint_of(pivot_node, "the crank's pivot");
    if (!description_.joints[static_cast<std::size_t>(spec.pivot)].ground) {
      fail(place_of(pivot_node), "a driver on a joint that is not grounded: the crank's pivot " +
                                     joint_name(spec.pivot) + " is a moving joint");
    }
    const toml::node& joint_node = required(driver, "joint", "[driver]");
    spec.joint = joint_of(joint_node, "the crank's joint");
    if (description_.joints[static_cast<std::size_t>(spec.joint)].ground) {
      fail(place_of(joint_node), "the crank's joint " + joint_name(spec.joint) + " is a ground joint, not a moving one");
    }
    if (!linked(spec.pivot, spec.joint)) {
      fail(place_of(joint_node), "the crank's joint " + joint_name(spec.joint) + " is on no [[link]] or [[body]] with pivot " +
                                     joint_name(spec.pivot));
    }
    const toml::node& angle_node = required(driver, "angle", "[driver]");
    spec.reference = number_of(angle_node, "the crank's angle");
    spec.reference_place = place_of(angle_node);
  }

  // Is there a link or a body with both joints?
  bool linked(int a, int b) const {
    const auto has = [](const std::vector<int>& joints, int j) {
      return std::find(joints.begin(), joints.end(), j) != joints.end();
    };
    return link_lines_.count(std::minmax(a, b)) > 0 ||
           std::any_of(description_.bodies.begin(), description_.bodies.end(),
                       [&](const BodySpec& body) { return has(body.joints, a) && has(body.joints, b); });
  }

  void read_slider_driver(const toml::table& driver) {
    DriverSpec& spec = *reading_;
    spec.kind = DriverKind::slider;
    const toml::node& joint_node = required(driver, "joint", "[driver]");
    spec.joint = joint_of(joint_node, "the slider driver's joint");
    const auto& sliders = description_.sliders;
    const auto slider = std::find_if(sliders.begin(), sliders.end(),
                                     [&](const SliderSpec& s) { return s.joint == spec.joint; });
    if (slider == sliders.end()) {
      fail(place_of(joint_node), "joint " + joint_name(spec.joint) + " has no [[slider]] for the slider driver to move");
    }
    if (slider->on_link()) {
      fail(place_of(joint_node), "joint " + joint_name(spec.joint) + " slides on a moving link: drive the distance with "
                                     "type = \"actuator\" instead of a slider driver");
    }
    spec.slider = static_cast<int>(slider - sliders.begin());
    const toml::node& travel_node = required(driver, "travel", "[driver]");
    spec.reference = number_of(travel_node, "the slider's travel");
    spec.reference_place = place_of(travel_node);
  }

  const toml::table& root_;
  const std::string& file_;
  LinkageDescription description_;
  std::map<std::string, int, std::less<>> joint_indices_;  // joint name -> index
  std::map<std::pair<int, int>, int> link_lines_;  // joint pair (smaller index first) -> line of its link
  DriverSpec* reading_ = nullptr;  // the driver read_driver is filling in (the first or the second)
};

}  // namespace

int LinkageDescription::joint_index(std::string_view joint_name) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == joint_name) return static_cast<int>(i);
  }
  return -1;
}

namespace {

std::string located(const std::string& file, SourcePlace place, const std::string& problem) {
  std::string where = printable(file);
  if (place.line > 0) where += ":" + std::to_string(place.line);
  if (place.line > 0 && place.column > 0) where += ":" + std::to_string(place.column);
  return where + ": " + problem;
}

}  // namespace

LinkageFileError::LinkageFileError(const std::string& file, SourcePlace place, const std::string& problem)
    : std::invalid_argument(located(file, place, problem)), problem_(problem), place_(place) {}

LinkageDescription parse_linkage_description(std::string_view toml_text, const std::string& file) {
  if (const auto unsafe = first_unsafe_character(toml_text)) {
    const std::string code = code_point_text(unsafe->code);
    throw LinkageFileError(file, unsafe->place,
                           "the character " + code + " is one toml++ 3.3 cannot read safely; in a string write it as \\u" +
                               code.substr(2));
  }
  if (const auto too_deep = NestingScan(toml_text).first_too_deep()) {
    throw LinkageFileError(file, *too_deep,
                           "keys, tables and arrays nested deeper than " + std::to_string(max_nesting) + " levels");
  }
  toml::table root;
  try {
    root = toml::parse(toml_text);
  } catch (const toml::parse_error& error) {
    // toml++ says "Error while parsing key-value pair: expected '=', saw 'N'" or "Encountered ...".
    const std::string_view description = error.description();
    constexpr std::string_view prefix = "Error while parsing ";
    const std::string detail = printable(description.starts_with(prefix)
                                             ? " in " + std::string(description.substr(prefix.size(), 160))
                                             : ": " + std::string(description.substr(0, 160)));
    throw LinkageFileError(file, place_of(error.source()),
                           mentions_linkage_table(toml_text)
                               ? "TOML syntax error" + detail
                               : "not a linkage description (no [linkage] table, and TOML syntax error" + detail + ")");
  }
  return Reader(root, file).read();
}

LinkageDescription read_linkage_description(const std::string& path) {
  std::string text;
  try {
    text = linalg::read_text_file(path);
  } catch (const std::invalid_argument& error) {
    // read_text_file says "FILE: problem"; keep the problem, LinkageFileError adds the file.
    std::string_view problem = error.what();
    if (const std::string prefix = printable(path) + ": "; problem.starts_with(prefix)) problem.remove_prefix(prefix.size());
    throw LinkageFileError(path, {}, std::string(problem));
  }
  return parse_linkage_description(text, path);
}

}  // namespace numlab::mechanisms
