// The version the headers announce is the version of the library the tests loaded.

#include "raylab/version.h"

#include <gtest/gtest.h>

#include <string>

namespace raylab {
namespace {

TEST(Version, LibraryMatchesHeaders) { EXPECT_STREQ(version(), RAYLAB_VERSION_STRING); }

TEST(Version, StringIsMajorMinorPatch) {
  const std::string parts = std::to_string(RAYLAB_VERSION_MAJOR) + "." + std::to_string(RAYLAB_VERSION_MINOR) + "." +
                            std::to_string(RAYLAB_VERSION_PATCH);
  EXPECT_EQ(parts, RAYLAB_VERSION_STRING);
}

}  // namespace
}  // namespace raylab
