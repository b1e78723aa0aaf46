// How the lab's JSON reports are written: nlohmann's layout (two-space indent), six significant
// digits for every floating-point number.

#include "report_json.h"

#include <fmt/format.h>

#include <cmath>

namespace raylab::detail {
namespace {

constexpr int kIndent = 2;

// A scalar or a key as nlohmann writes it, invalid UTF-8 replaced.
std::string scalar_text(const ReportJson& value) {
  return value.dump(-1, ' ', false, ReportJson::error_handler_t::replace);
}

void write(const ReportJson& value, int depth, std::string& out) {
  const bool object = value.is_object();
  if (value.is_number_float()) {
    const double v = value.get<double>();
    out += std::isfinite(v) ? fmt::format("{:.6g}", v) : "null";
    return;
  }
  if (!object && !value.is_array()) {
    out += scalar_text(value);
    return;
  }
  if (value.empty()) {
    out += object ? "{}" : "[]";
    return;
  }
  out += object ? "{\n" : "[\n";
  const std::string inner(static_cast<std::size_t>((depth + 1) * kIndent), ' ');
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (it != value.begin()) out += ",\n";
    out += inner;
    if (object) out += scalar_text(it.key()) + ": ";
    write(it.value(), depth + 1, out);
  }
  out += "\n" + std::string(static_cast<std::size_t>(depth * kIndent), ' ') + (object ? "}" : "]");
}

}  // namespace

std::string report_text(const ReportJson& doc) {
  std::string out;
  write(doc, 0, out);
  return out + "\n";
}

}  // namespace raylab::detail
