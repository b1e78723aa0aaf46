// `raylab --version`: the version of the library the program loaded.

#include <gtest/gtest.h>

#include <string>

#include "cli_fixture.h"
#include "raylab/version.h"

namespace raylab {
namespace {

using namespace cli_test;

TEST_F(Cli, VersionPrintsTheLibraryVersion) {
  const CliResult r = run("--version");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "raylab " RAYLAB_VERSION_STRING "\n");
  EXPECT_EQ(r.out, std::string("raylab ") + version() + "\n");
}

}  // namespace
}  // namespace raylab
