#pragma once
// Where the tests find the source tree and the command-line binary. Defined in one translation
// unit (test_paths.cpp) so that the paths, which differ from clone to clone, do not reach the
// other test sources: those stay byte-identical between clones and ccache can reuse them.

#include <string>

namespace raylab::test {

/// The root of the source tree (the folder with the top CMakeLists.txt), absolute.
std::string source_dir();

/// The raylab command-line binary of this build, absolute.
std::string raylab_binary();

}  // namespace raylab::test
