#pragma once
/// \file
/// The two kinds of error a user can cause, and how they are reported.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace raylab {

/// Bad input data (a scene file, a mesh, an unreadable or unwritable file). Reported as
/// `file:line:col: message` when a position is known; the command line exits with code 1.
class InputError : public std::runtime_error {
 public:
  /// An error at a position in a file; `line` and `col` are 1-based, 0 when unknown.
  InputError(std::string file, int line, int col, const std::string& message);
  /// An error about a file as a whole (no position).
  InputError(std::string file, const std::string& message) : InputError(std::move(file), 0, 0, message) {}

  /// An error at byte `offset` of a binary file: `file: byte N: message`.
  static InputError at_byte(std::string file, std::uint64_t offset, const std::string& message);

  /// The file the error is about (may be empty).
  const std::string& file() const { return m_file; }
  /// 1-based line, or 0 when not known.
  int line() const { return m_line; }
  /// 1-based column, or 0 when not known.
  int column() const { return m_col; }

 private:
  std::string m_file;
  int m_line;
  int m_col;
};

/// A bad request from the user (an unknown name, an out-of-range flag value). The message lists
/// the valid values where there is a finite set; the command line exits with code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace raylab
