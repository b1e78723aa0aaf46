// Syntax errors in scene files are reported where the fix goes: a missing comma after the value
// it belongs after, a trailing comma at the comma, an unclosed string at its opening quote, an
// unclosed brace at the end of the last value, naming where the brace was opened.

#include <gtest/gtest.h>

#include <string>

#include "../test_util.h"
#include "raylab/io/scene_json.h"

namespace raylab {
namespace {

std::string error_of(const std::string& text) {
  return test::thrown_message([&] { (void)parse_scene_json(text, "scene.json", ".", {}); });
}

TEST(JsonSyntaxError, MissingCommaInAnObjectIsReportedAfterThePreviousValue) {
  // The parser stops at "height" on line 3; the comma belongs after 640 on line 2 (cols 23 to 25).
  EXPECT_EQ(error_of("{\"version\": 1,\n  \"render\": {\"width\": 640\n    \"height\": 480}}"),
            "scene.json:2:26: expected ',' or '}' after the value of \"width\"");
  // After a nested object or a string with an escaped quote, the same.
  EXPECT_EQ(error_of("{\"a\": {\"b\": 1} \"c\": 2}"), "scene.json:1:15: expected ',' or '}' after the value of \"a\"");
  EXPECT_EQ(error_of("{\"a\": \"x\\\"y\" \"c\": 2}"), "scene.json:1:13: expected ',' or '}' after the value of \"a\"");
}

TEST(JsonSyntaxError, MissingCommaInAnArrayIsReportedAfterThePreviousElement) {
  EXPECT_EQ(error_of("{\"vertices\": [[0, 0, 0],\n  [1, 0, 0]\n  [0, 1, 0]]}"),
            "scene.json:2:12: expected ',' or ']' after an element of \"vertices\"");
  EXPECT_EQ(error_of("[[1] [2]]"), "scene.json:1:5: expected ',' or ']' after an array element");
}

TEST(JsonSyntaxError, TrailingCommaIsReportedAtTheComma) {
  EXPECT_EQ(error_of("{\"version\": 1,\n}"),
            "scene.json:1:14: a ',' must be followed by another member (JSON allows no comma before '}')");
  EXPECT_EQ(error_of("{\"a\": [1, 2,\n]}"),
            "scene.json:1:12: a ',' must be followed by another element (JSON allows no comma before ']')");
}

TEST(JsonSyntaxError, UnclosedStringIsReportedAtItsOpeningQuote) {
  EXPECT_EQ(error_of("{\"version\": 1,\n  \"description\": \"a ball\n}"),
            "scene.json:2:18: this string is not closed: it needs a '\"' before the end of the line");
  EXPECT_EQ(error_of("{\"a\": \"abc"),
            "scene.json:1:7: this string is not closed: it needs a '\"' before the end of the line");
}

TEST(JsonSyntaxError, UnclosedBraceAtEndOfFileNamesTheOpeningBrace) {
  EXPECT_EQ(error_of("{\"version\": 1,\n  \"render\": {\"spp\": 4\n\n"),
            "scene.json:2:22: expected ',' or '}' after the value of \"spp\"; the '{' at line 2, column 13 is "
            "never closed");
  EXPECT_EQ(error_of("{\"a\": [1, 2\n"),
            "scene.json:1:12: expected ',' or ']' after an element of \"a\"; the '[' at line 1, column 7 is never "
            "closed");
}

TEST(JsonSyntaxError, MissingColonAndEmptyFileSayWhatIsMissing) {
  EXPECT_EQ(error_of("{\"version\" 1}"), "scene.json:1:11: expected ':' after the key \"version\"");
  EXPECT_EQ(error_of(" \n"), "scene.json:1:1: the file is empty (a scene file is a JSON object)");
}

TEST(JsonSyntaxError, OtherErrorsKeepTheParsersWordsAtTheOffendingCharacter) {
  EXPECT_EQ(error_of("{\"a\": tru}").rfind("scene.json:1:10: JSON ", 0), 0u) << error_of("{\"a\": tru}");
}

}  // namespace
}  // namespace raylab
