#pragma once
/// \file
/// Reading a whole input file into memory, with a clear error when that is not possible.

#include <string>

namespace raylab {

/// The bytes of file `path`. Throws InputError naming the file when it cannot be opened or read
/// (missing, a directory, no permission).
std::string read_file(const std::string& path);

}  // namespace raylab
