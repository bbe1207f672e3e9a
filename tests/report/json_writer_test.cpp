#include "report/json_writer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>

namespace collide::report {
namespace {

TEST(JsonWriterTest, NestedStructureIsIndentedWithCommasBetweenItems) {
  std::ostringstream out;
  JsonWriter json(out);
  json.beginObject();
  json.key("n").value(3);
  json.key("list").beginArray().value(1.5).value("x").endArray();
  json.key("empty").beginArray().endArray();
  json.key("v").value(core::Vec2(1.0, -0.25));
  json.endObject();
  EXPECT_EQ(out.str(),
            "{\n  \"n\": 3,\n  \"list\": [\n    1.5,\n    \"x\"\n  ],\n  \"empty\": [],\n"
            "  \"v\": [1, -0.25]\n}\n");
}

TEST(JsonWriterTest, NumbersReadBackExactly) {
  for (double x : {0.1, 1.0 / 3.0, -1.6875, 6.02214076e23, 5e-324, 1e14}) {
    const std::string text = shortestDecimal(x);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
  }
  EXPECT_EQ(shortestDecimal(2.0), "2");
}

TEST(JsonWriterTest, NonFiniteNumbersBecomeNull) {
  std::ostringstream out;
  JsonWriter json(out);
  json.beginArray().value(std::numeric_limits<double>::infinity()).value(std::nan("")).endArray();
  EXPECT_EQ(out.str(), "[\n  null,\n  null\n]");
}

TEST(JsonWriterTest, StringsAreEscaped) {
  EXPECT_EQ(jsonQuoted("a\"b\\c\nd\x01"), "\"a\\\"b\\\\c\\nd\\u0001\"");
}

}  // namespace
}  // namespace collide::report
