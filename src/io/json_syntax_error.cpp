#include "json_syntax_error.h"

#include <algorithm>
#include <cctype>

#include "raylab/core/error.h"

namespace raylab {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Offset of the first character of the token whose last character is at `last`: a string
// back to its opening quote, a number or literal back over its characters, else `last` itself.
std::size_t token_start(std::string_view text, std::size_t last) {
  if (last >= text.size()) return text.size();
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-'; };
  std::size_t start = last;
  if (text[last] == '"') {
    while (start > 0 && !(text[start - 1] == '"' && (start < 2 || text[start - 2] != '\\'))) --start;
    return start > 0 ? start - 1 : 0;
  }
  if (!is_word(text[last])) return last;
  while (start > 0 && is_word(text[start - 1])) --start;
  return start;
}

// Offset just after the last non-space character before `offset` (0 when there is none).
std::size_t end_of_previous(std::string_view text, std::size_t offset) {
  std::size_t p = std::min(offset, text.size());
  while (p > 0 && is_space(text[p - 1])) --p;
  return p;
}

// The opening quote of the string that is still open at `offset`: the last unescaped '"' before
// it (the string holds no line break, or the parser would have stopped there).
std::size_t opening_quote(std::string_view text, std::size_t offset) {
  std::size_t p = std::min(offset, text.size());
  while (p > 0) {
    --p;
    if (text[p] == '"' && (p == 0 || text[p - 1] != '\\')) return p;
  }
  return 0;
}

[[noreturn]] void fail_at(const LineIndex& lines, const std::string& file, std::size_t offset,
                          const std::string& message) {
  const TextPosition pos = lines.at(offset);
  throw InputError(file, pos.line, pos.col, message);
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// "the value of "width"" or "an element of "vertices"".
std::string last_value(const OpenContainer& c) {
  if (c.object) return c.key.empty() ? std::string("the value") : "the value of " + quoted(c.key);
  return c.name.empty() ? std::string("an array element") : "an element of " + quoted(c.name);
}

}  // namespace

LineIndex::LineIndex(std::string_view text) {
  m_starts.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') m_starts.push_back(i + 1);
}

TextPosition LineIndex::at(std::size_t offset) const {
  const auto it = std::upper_bound(m_starts.begin(), m_starts.end(), offset);
  const std::size_t line = static_cast<std::size_t>(it - m_starts.begin());  // >= 1
  return {static_cast<int>(line), static_cast<int>(offset - m_starts[line - 1]) + 1};
}

void throw_json_syntax_error(std::string_view text, const LineIndex& lines, const std::string& file,
                             std::size_t position, std::string parser_message,
                             const std::optional<OpenContainer>& open) {
  // `position` counts the characters read, the offending one included.
  const std::size_t last = std::min(position > 0 ? position - 1 : 0, text.size());
  const auto fail = [&](std::size_t offset, const std::string& message) { fail_at(lines, file, offset, message); };
  if (parser_message.starts_with("syntax error while parsing ")) parser_message = parser_message.substr(27);
  const auto says = [&](std::string_view part) { return parser_message.find(part) != std::string::npos; };

  if (says("invalid string: control character U+000A") || says("invalid string: missing closing quote")) {
    fail(opening_quote(text, last), "this string is not closed: it needs a '\"' before the end of the line");
  }
  if (end_of_previous(text, text.size()) == 0) fail(0, "the file is empty (a scene file is a JSON object)");
  if (open && open->object && says("expected ':'")) {
    fail(end_of_previous(text, token_start(text, last)), "expected ':' after the key " + quoted(open->key));
  }
  if (open) {
    const char close = open->object ? '}' : ']';
    const TextPosition opened = lines.at(open->open_offset);
    const std::string expected = std::string("expected ',' or '") + close + "' after " + last_value(*open);
    if (says("unexpected end of input")) {
      fail(end_of_previous(text, text.size()), expected + "; the '" + std::string(1, open->object ? '{' : '[') +
                                                   "' at line " + std::to_string(opened.line) + ", column " +
                                                   std::to_string(opened.col) + " is never closed");
    }
    const std::size_t start = token_start(text, last);
    const std::size_t before = end_of_previous(text, start);
    const bool after_comma = before > 0 && text[before - 1] == ',';
    if (after_comma && start < text.size() && text[start] == close) {
      fail(before - 1, "a ',' must be followed by another " + std::string(open->object ? "member" : "element") +
                           " (JSON allows no comma before '" + close + "')");
    }
    const bool wanted_separator = says(std::string("expected '") + close + "'");
    if (wanted_separator && before > 0 && !after_comma) fail(before, expected);
  }
  fail_at(lines, file, last, "JSON " + parser_message);
}

}  // namespace raylab
