#pragma once
// Internal to the render module: the two JSON value spellings the SPD protocol's report needs
// (it writes its JSON by hand: render must not depend on io; the lab's reports, a layer above,
// use nlohmann-json).

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <string_view>

namespace raylab::detail {

/// `s` as a JSON string literal: quotes and backslashes escaped, control characters as \uXXXX.
inline std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
    } else {
      out += c;
    }
  }
  return out + "\"";
}

/// A finite number for JSON, else null (JSON has no infinity or NaN).
inline std::string json_number(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "null"; }

}  // namespace raylab::detail
