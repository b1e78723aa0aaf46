#pragma once
/// \file
/// The width of the terminal that text is printed to, so that help and progress lines fit it.

namespace raylab {

/// Columns of the terminal on file descriptor `fd` when it is one (TIOCGWINSZ), else the
/// COLUMNS environment variable when it holds a number, else 80; never fewer than 20, so that
/// a silly setting still leaves room for a word per line.
int terminal_columns(int fd);

/// terminal_columns with the COLUMNS text given instead of read (null: unset): the rule without
/// the terminal, for tests.
int columns_from_environment(const char* columns);

}  // namespace raylab
