// Reading a reply's fields as a tolerant reader: a whole number may come as 13.0, not as 13.5.

#include <catch2/catch.hpp>

#include "exercises/reply_fields.hpp"

using namespace numlab::exercises;

TEST_CASE("A whole number may be written with a fraction of zero, but not with another", "[reply]") {
  const nlohmann::json reply = nlohmann::json::parse(
      R"({"a": 13, "b": 13.0, "c": -2.0, "d": 13.5, "e": "13", "f": 1e300, "g": 0.0})");
  CHECK(integer_field(reply, "a") == 13);
  CHECK(integer_field(reply, "b") == 13);
  CHECK(integer_field(reply, "c") == -2);
  CHECK(integer_field(reply, "g") == 0);
  CHECK_THROWS_WITH(integer_field(reply, "d"), "\"d\" is 13.5, not a whole number");
  CHECK_THROWS_WITH(integer_field(reply, "e"), "\"e\" is string, not a whole number");
  CHECK_THROWS_WITH(integer_field(reply, "f"), "\"f\" is 1e+300, not a whole number");
  CHECK_THROWS_WITH(integer_field(reply, "h"), "the reply has no \"h\"");
}
