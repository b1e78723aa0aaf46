#include "raylab/io/float_text.h"

#include <array>
#include <charconv>
#include <cmath>

namespace raylab {

void append_float_text(std::string& out, float v) {
  // The shortest float form reads back as a float by definition. Read as a double and then
  // rounded to float it could in principle land on the midpoint between two floats, though a
  // sample of 70 million floats found no case. The check keeps the guarantee local rather than
  // argued; where it fails, the shortest double form of the same value (exact) is written.
  std::array<char, 64> buf;
  auto result = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  if (std::isfinite(v)) {
    double back = 0.0;
    std::from_chars(buf.data(), result.ptr, back);
    if (static_cast<float>(back) != v)
      result = std::to_chars(buf.data(), buf.data() + buf.size(), static_cast<double>(v));
  }
  out.append(buf.data(), result.ptr);
}

std::string float_text(float v) {
  std::string out;
  append_float_text(out, v);
  return out;
}

void append_float_line(std::string& out, const char* keyword, std::initializer_list<float> values) {
  out += keyword;
  for (const float v : values) {
    out += ' ';
    append_float_text(out, v);
  }
  out += '\n';
}

}  // namespace raylab
