#pragma once
// Syntax errors in a scene file's JSON, reported where the fix goes. The parser notices a
// missing comma only at the next key, and an unclosed string or brace only where the text
// ends; these functions move the report back to the value the comma belongs after, the quote
// that opened the string, and name the bracket that was never closed.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "json_document.h"

namespace raylab {

// Maps byte offsets of a text to 1-based line and column.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);
  TextPosition at(std::size_t offset) const;

 private:
  std::vector<std::size_t> m_starts;
};

// The innermost container open when the error came.
struct OpenContainer {
  bool object = true;           // else an array
  std::size_t open_offset = 0;  // of its '{' or '['
  std::string key;              // object: the last key read (whose value came last)
  std::string name;             // how to call it: its key in the parent, empty for the root or an element
};

// Throws InputError `file:line:col: message` for the syntax error that nlohmann reported with
// `parser_message` (its text after "parse error at line L, column C: ") after reading
// `position` characters of `text`. `open` is the innermost open container, if any.
[[noreturn]] void throw_json_syntax_error(std::string_view text, const LineIndex& lines, const std::string& file,
                                          std::size_t position, std::string parser_message,
                                          const std::optional<OpenContainer>& open);

}  // namespace raylab
