// The embedded task statements (task_texts.hpp): the entries CMakeLists.txt generates from tasks/*.md.
#include "exercises/task_texts.hpp"

#include <map>
#include <stdexcept>

namespace numlab::exercises {
namespace {

struct TaskEntry {
  const char* name;
  const char* text;
};

// {"NAME", R"task(the Markdown of tasks/NAME.md)task"}, one for each task file.
constexpr TaskEntry task_entries[] = {
#include "exercises/task_texts.inc"
};

}  // namespace

const std::string& task_text(const std::string& name) {
  static const std::map<std::string, std::string> texts = [] {
    std::map<std::string, std::string> map;
    for (const TaskEntry& entry : task_entries) map.emplace(entry.name, entry.text);
    return map;
  }();
  const auto found = texts.find(name);
  if (found == texts.end())
    throw std::logic_error("no task for exercise '" + name + "': labs/exercises/tasks/" + name + ".md was not embedded");
  return found->second;
}

}  // namespace numlab::exercises
