#pragma once
// Shared by the tests of every folder: the message an error carries, the words a message must
// hold, and element-by-element checks of two lists.

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/core/error.h"

namespace raylab::test {

/// The message of the `Error` that `call()` throws, or "no error" when it throws none (which
/// then fails any check for the words the message should hold).
template <class Error = InputError, class Call>
std::string thrown_message(Call call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

/// Expects `message` to contain each of `words`.
template <class Words>
void expect_contains_all(const std::string& message, const Words& words) {
  for (std::string_view word : words) {
    EXPECT_NE(message.find(word), std::string::npos) << "no '" << word << "' in: " << message;
  }
}

/// Expects `message` to contain each of `words`, written out at the call.
inline void expect_contains_all(const std::string& message, std::initializer_list<std::string_view> words) {
  expect_contains_all<std::initializer_list<std::string_view>>(message, words);
}

/// Expects `got` and `want` to be as long, then runs `expect(got[i], want[i])` for each i, traced
/// as "`what` i".
template <class T, class Expect>
void expect_each(const std::vector<T>& got, const std::vector<T>& want, const std::string& what, Expect expect) {
  ASSERT_EQ(got.size(), want.size()) << what << "s";
  for (std::size_t i = 0; i < got.size(); ++i) {
    SCOPED_TRACE(what + " " + std::to_string(i));
    expect(got[i], want[i]);
  }
}

}  // namespace raylab::test
