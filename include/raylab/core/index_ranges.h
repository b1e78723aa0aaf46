#pragma once
/// \file
/// Lists of indices for messages: "3, 5-9, 12" rather than nine numbers.

#include <string>
#include <vector>

namespace raylab {

/// `indices` sorted and written as comma-separated runs ("3, 5-9, 12"); empty for none.
std::string index_ranges(std::vector<int> indices);

}  // namespace raylab
