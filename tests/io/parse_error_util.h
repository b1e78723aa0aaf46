#pragma once
// Shared by the parser tests: the message a parse must fail with, and where a truncated text's
// error is reported.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "../test_util.h"
#include "raylab/core/error.h"
#include "raylab/geometry/geometry.h"

namespace raylab::test {

/// The message of the InputError that `parse(bytes, file, geometry, 0)` throws, or "no error".
template <class Parse>
std::string parse_error(Parse parse, const std::string& bytes, const std::string& file) {
  Geometry g;
  return thrown_message([&] { parse(bytes, file, g, 0); });
}

/// Expects `message` to start with `prefix` (the position) and to contain `words`.
inline void expect_message(const std::string& message, const std::string& prefix, const std::string& words) {
  EXPECT_EQ(message.rfind(prefix, 0), 0u) << "message: " << message << "\nexpected prefix: " << prefix;
  EXPECT_NE(message.find(words), std::string::npos) << "message: " << message << "\nexpected words: " << words;
}

/// "file:line:col: " of the position just past the end of `text`.
inline std::string end_position(const std::string& file, const std::string& text) {
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  const std::size_t last = text.rfind('\n');
  const std::size_t col = text.size() - (last == std::string::npos ? 0 : last + 1) + 1;
  return file + ":" + std::to_string(line) + ":" + std::to_string(col) + ": ";
}

}  // namespace raylab::test
