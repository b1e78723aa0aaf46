#include "raylab/core/error.h"

#include <sstream>

namespace raylab {
namespace {

// "file:line:col: message", dropping the parts that are unknown.
std::string format_input_error(const std::string& file, int line, int col, const std::string& message) {
  std::string out = file;
  if (line > 0) {
    out += ':' + std::to_string(line);
    if (col > 0) out += ':' + std::to_string(col);
  }
  if (!out.empty()) out += ": ";
  return out + message;
}

}  // namespace

InputError::InputError(std::string file, int line, int col, const std::string& message)
    : std::runtime_error(format_input_error(file, line, col, message)),
      m_file(std::move(file)),
      m_line(line),
      m_col(col) {}

InputError InputError::at_byte(std::string file, std::uint64_t offset, const std::string& message) {
  // A stream rather than string concatenation, which trips GCC 12's -Wrestrict false positive.
  std::ostringstream text;
  text << "byte " << offset << ": " << message;
  return InputError(std::move(file), 0, 0, text.str());
}

}  // namespace raylab
