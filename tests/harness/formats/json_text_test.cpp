// JSON text with limits: a syntax error at its line and column; nesting just within the limit
// read, one level more refused at its pointer, a million levels refused without exhausting the
// stack; a key given twice refused at its pointer (in an object inside an array too); a number
// beyond a double's range refused at its line and column.
#include "harness/formats/json_text.h"

#include <gtest/gtest.h>

#include <string>

namespace cc::harness {
namespace {

// The place and message a text is refused with; "(read)" when it is not.
std::pair<std::string, std::string> refusal(const std::string& text) {
  try {
    parse_json_text(text);
  } catch (const JsonTextError& e) {
    return {e.place(), e.what()};
  }
  return {"(read)", ""};
}

std::string nested(std::size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }

TEST(JsonText, ASyntaxErrorAtItsLineAndColumn) {
  const auto [place, message] = refusal("{\n  \"a\": 1,\n  \"b\": }");
  EXPECT_EQ(place, "line 3, column 8");
  EXPECT_NE(message.find("syntax error"), std::string::npos) << message;
}

TEST(JsonText, NestingUpToTheLimitIsReadOneMoreLevelIsNot) {
  EXPECT_EQ(refusal(nested(kMaxJsonDepth)).first, "(read)");
  const auto [place, message] = refusal(nested(kMaxJsonDepth + 1));
  EXPECT_EQ(place, "/0" + [] {
    std::string p;
    for (std::size_t i = 1; i < kMaxJsonDepth; ++i) p += "/0";
    return p;
  }());
  EXPECT_EQ(message, "nested deeper than 64 levels");
  EXPECT_EQ(refusal(nested(1'000'000)).second, "nested deeper than 64 levels");
  EXPECT_EQ(refusal(std::string(1'000'000, '[')).second, "nested deeper than 64 levels");
}

TEST(JsonText, AKeyGivenTwiceIsRefusedAtItsPointer) {
  EXPECT_EQ(refusal(R"({"a": 1, "b": {"c": 1, "c": 2}})"),
            (std::pair<std::string, std::string>{"/b/c", "the key \"c\" is given twice"}));
  EXPECT_EQ(refusal(R"({"list": [1, {"x": 0}, {"y": 1, "y": 1}]})").first, "/list/2/y");
  EXPECT_EQ(refusal(R"({"a": {"c": 1}, "b": {"c": 2}})").first, "(read)");  // the same key in two objects
}

TEST(JsonText, ANumberBeyondADoublesRangeAtItsLineAndColumn) {
  EXPECT_EQ(refusal("{\n  \"x\": 1e400\n}"),
            (std::pair<std::string, std::string>{"line 2, column 8", "the number 1e400 is beyond the range of a double"}));
  EXPECT_EQ(parse_json_text("[1e308, 4.9e-324, 1e-400]").size(), 3u);  // within range, or rounding to 0
}

}  // namespace
}  // namespace cc::harness
