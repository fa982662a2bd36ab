#include <catch2/catch.hpp>

#include "core/json.hpp"

using namespace nephele;

TEST_CASE("JSON values round-trip through write and parse", "[fast][json]") {
  json::Value v;
  v.set("name", "cover \"quoted\"\n");
  v.set("pi", 3.141592653589793);
  v.set("step", 0.006f);
  v.set("n", 42);
  v.set("flag", true);
  v.set("nothing", json::Value());
  v.set("list", json::Value::Array{1, "two", 3.5});
  const json::Value back = json::parse(json::write(v));
  CHECK(back.at("name").as_string() == "cover \"quoted\"\n");
  CHECK(back.at("pi").as_number() == 3.141592653589793);
  CHECK(back.at("step").as_number() == 0.006);  // floats keep their shortest decimal
  CHECK(back.at("n").as_number() == 42);
  CHECK(back.at("flag").as_bool());
  CHECK(back.at("nothing").is_null());
  CHECK(back.at("list").as_array().size() == 3);
  CHECK(json::write(json::Value(std::nan(""))) == "null\n");
}

TEST_CASE("malformed JSON is rejected with its line and column", "[fast][json]") {
  CHECK_THROWS_AS(json::parse("{\"a\": 1,}"), json::ParseError);
  CHECK_THROWS_AS(json::parse("[1, 2"), json::ParseError);
  CHECK_THROWS_AS(json::parse("{\"a\": 1, \"a\": 2}"), json::ParseError);
  CHECK_THROWS_AS(json::parse("01"), json::ParseError);
  CHECK_THROWS_AS(json::parse("\"\\ud800\""), json::ParseError);
  try {
    json::parse("{\n  \"a\": tru\n}");
    FAIL("no error");
  } catch (const json::ParseError& e) {
    CHECK(e.line == 2);
  }
  CHECK(json::parse("\"\\u00e9\\ud83d\\ude00\"").as_string() == "\xc3\xa9\xf0\x9f\x98\x80");
}
