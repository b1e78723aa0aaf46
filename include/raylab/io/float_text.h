#pragma once
/// \file
/// Decimal text for floats that every raylab reader turns back into the same float.

#include <initializer_list>
#include <string>

namespace raylab {

/// The shortest decimal text of `v` that reads back to `v` bit for bit, both when parsed as a
/// float and when parsed as a double and then rounded to float (as the NFF and JSON readers
/// do). Non-finite values are written as to_chars writes them ("inf", "nan").
std::string float_text(float v);

/// Appends float_text(v) to `out` (no allocation for the common case).
void append_float_text(std::string& out, float v);

/// Appends the line "KEYWORD v1 v2 ..." with each value as float_text writes it: the line of
/// the OBJ and MTL writers.
void append_float_line(std::string& out, const char* keyword, std::initializer_list<float> values);

}  // namespace raylab
