#pragma once
/// \file
/// Whitespace-separated tokens of a text file, each with its line and column, for the project's
/// own text parsers (NFF, OFF, PLY headers and ASCII bodies, ASCII STL).

#include <cstdint>
#include <string>
#include <string_view>

namespace raylab {

/// One token and where it starts (1-based line and column).
struct Token {
  std::string_view text;
  int line = 0;
  int col = 0;
};

/// Reads tokens from text held in memory. Errors are thrown as InputError with the token's
/// `file:line:col`. `comment` (0 for none) starts a comment that runs to the end of the line.
class TextScanner {
 public:
  /// Scans `text` (which must outlive the scanner) of file `file` (used in messages).
  TextScanner(std::string file, std::string_view text, char comment = '#');

  /// True when only whitespace and comments remain.
  bool at_end();
  /// The next token without consuming it; throws "unexpected end of file, expected `what`".
  Token peek(std::string_view what);
  /// The next token; throws "unexpected end of file, expected `what`".
  Token next(std::string_view what);
  /// The next token if it starts on the current line (does not cross a newline), else an empty
  /// token with the position of the line's end. For line-oriented formats.
  Token next_on_line();
  /// Skips to the start of the next line.
  void skip_line();
  /// The next token as a finite number; `what` names it in messages ("sphere radius").
  double number(std::string_view what);
  /// The next token as a finite float.
  float real(std::string_view what) { return static_cast<float>(number(what)); }
  /// The next token as an integer in [lo, hi].
  std::int64_t integer(std::string_view what, std::int64_t lo, std::int64_t hi);
  /// Consumes the next token and checks that it is `keyword`.
  void expect(std::string_view keyword);

  /// Throws InputError at `token`.
  [[noreturn]] void fail(const Token& token, const std::string& message) const;
  /// Throws InputError at the current position (after the last token read).
  [[noreturn]] void fail_here(const std::string& message) const;
  /// File name used in messages.
  const std::string& file() const { return m_file; }
  /// Byte offset of the scan position (after the last token read).
  std::size_t offset() const { return m_pos; }
  /// Current 1-based line.
  int line() const { return m_line; }

 private:
  void skip_space_and_comments(bool cross_newlines);

  std::string m_file;
  std::string_view m_text;
  char m_comment;
  std::size_t m_pos = 0;
  int m_line = 1;
  std::size_t m_line_start = 0;
};

/// A token quoted for a message: cut to 40 characters, non-printable bytes shown as '?' (binary
/// garbage must not reach the terminal raw).
std::string quoted(std::string_view text);

/// Parses `text` as a finite number (accepting a leading '+'); false if it is not one.
bool parse_finite(std::string_view text, double& value);

}  // namespace raylab
