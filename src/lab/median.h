#pragma once
// Internal to the render module: the median the reports use for timings (robust to the odd
// slow run on a shared machine).

#include <algorithm>
#include <vector>

namespace raylab::detail {

/// The median of `v` (the mean of the two middle values for an even count); 0 when empty.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace raylab::detail
