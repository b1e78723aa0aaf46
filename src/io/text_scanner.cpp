#include "raylab/io/text_scanner.h"

#include <charconv>
#include <cmath>

#include "raylab/core/error.h"

namespace raylab {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

}  // namespace

std::string quoted(std::string_view text) {
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  }
  if (text.size() > 40) out += "...";
  return out + "'";
}

bool parse_finite(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return false;  // "+-1" is not a number
  }
  if (text.empty()) return false;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && ptr == text.data() + text.size() && std::isfinite(value);
}

TextScanner::TextScanner(std::string file, std::string_view text, char comment)
    : m_file(std::move(file)), m_text(text), m_comment(comment) {}

void TextScanner::skip_space_and_comments(bool cross_newlines) {
  while (m_pos < m_text.size()) {
    const char c = m_text[m_pos];
    if (c == '\n') {
      if (!cross_newlines) return;
      ++m_pos;
      ++m_line;
      m_line_start = m_pos;
    } else if (is_space(c)) {
      ++m_pos;
    } else if (m_comment != 0 && c == m_comment) {
      while (m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
    } else {
      return;
    }
  }
}

bool TextScanner::at_end() {
  skip_space_and_comments(true);
  return m_pos >= m_text.size();
}

Token TextScanner::peek(std::string_view what) {
  const std::size_t pos = m_pos, line_start = m_line_start;
  const int line = m_line;
  const Token t = next(what);
  m_pos = pos;
  m_line = line;
  m_line_start = line_start;
  return t;
}

Token TextScanner::next(std::string_view what) {
  skip_space_and_comments(true);
  if (m_pos >= m_text.size()) fail_here("unexpected end of file, expected " + std::string(what));
  Token t;
  t.line = m_line;
  t.col = static_cast<int>(m_pos - m_line_start) + 1;
  const std::size_t start = m_pos;
  while (m_pos < m_text.size() && !is_space(m_text[m_pos])) ++m_pos;
  t.text = m_text.substr(start, m_pos - start);
  return t;
}

Token TextScanner::next_on_line() {
  skip_space_and_comments(false);
  Token t;
  t.line = m_line;
  t.col = static_cast<int>(m_pos - m_line_start) + 1;
  if (m_pos >= m_text.size() || m_text[m_pos] == '\n') return t;
  const std::size_t start = m_pos;
  while (m_pos < m_text.size() && !is_space(m_text[m_pos])) ++m_pos;
  t.text = m_text.substr(start, m_pos - start);
  return t;
}

void TextScanner::skip_line() {
  while (m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
  if (m_pos < m_text.size()) {
    ++m_pos;
    ++m_line;
    m_line_start = m_pos;
  }
}

double TextScanner::number(std::string_view what) {
  const Token t = next(what);
  double value = 0.0;
  if (!parse_finite(t.text, value))
    fail(t, "expected " + std::string(what) + " (a finite number), found " + quoted(t.text));
  return value;
}

std::int64_t TextScanner::integer(std::string_view what, std::int64_t lo, std::int64_t hi) {
  const Token t = next(what);
  std::string_view text = t.text;
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  std::int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) {
    fail(t, "expected " + std::string(what) + " (an integer), found " + quoted(t.text));
  }
  if (value < lo || value > hi) {
    fail(t, std::string(what) + " " + std::to_string(value) + " is out of range [" + std::to_string(lo) + ", " +
                std::to_string(hi) + "]");
  }
  return value;
}

void TextScanner::expect(std::string_view keyword) {
  const Token t = next("'" + std::string(keyword) + "'");
  if (t.text != keyword) fail(t, "expected '" + std::string(keyword) + "', found " + quoted(t.text));
}

void TextScanner::fail(const Token& token, const std::string& message) const {
  throw InputError(m_file, token.line, token.col, message);
}

void TextScanner::fail_here(const std::string& message) const {
  throw InputError(m_file, m_line, static_cast<int>(m_pos - m_line_start) + 1, message);
}

}  // namespace raylab
