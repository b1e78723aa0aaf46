#include "test_paths.h"

// tests/CMakeLists.txt defines both macros for this file only.
namespace raylab::test {

std::string source_dir() { return RAYLAB_SOURCE_DIR; }

std::string raylab_binary() { return RAYLAB_BINARY; }

}  // namespace raylab::test
