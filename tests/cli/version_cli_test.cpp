// `raylab --version`, and the load-time CPU check seen from the command line: a CPU without the
// extensions the build uses gets a message naming them and exit status 1, never SIGILL.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli_fixture.h"
#include "raylab/core/cpu_features.h"
#include "raylab/core/isa.h"
#include "raylab/version.h"

namespace raylab {
namespace {

using namespace cli_test;

bool build_requires(const std::string& feature) {
  const std::vector<std::string> required = required_cpu_features();
  return std::find(required.begin(), required.end(), feature) != required.end();
}

TEST_F(Cli, VersionPrintsTheLibraryVersion) {
  const CliResult r = run("--version");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "raylab " RAYLAB_VERSION_STRING "\n" + isa_summary() + "\n");
  EXPECT_EQ(r.out.rfind(std::string("raylab ") + version() + "\nkernels: ", 0), 0u) << r.out;
}

TEST_F(Cli, MissingCpuExtensionIsNamedWithExitOne) {
  if (!build_requires("avx2")) GTEST_SKIP() << "this build (-march=" << build_cpu_arch() << ") does not use AVX2";
  const CliResult r = run("--version", "RAYLAB_CPU_CHECK_PRETEND_MISSING=avx2");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "") << "the check must stop the program before it runs";
  EXPECT_NE(r.err.find("this CPU lacks: avx2; rebuild with -DRAYLAB_ARCH=x86-64\n"), std::string::npos) << r.err;
  if (std::string(build_cpu_arch()) == "x86-64-v3") {
    EXPECT_EQ(r.err,
              "raylab: this build needs a CPU with AVX2 and FMA (x86-64-v3); this CPU lacks: avx2; rebuild with "
              "-DRAYLAB_ARCH=x86-64\n");
  }
}

TEST_F(Cli, EveryMissingCpuExtensionIsListed) {
  if (!build_requires("avx2") || !build_requires("fma")) GTEST_SKIP() << "this build does not use AVX2 and FMA";
  // Names the build does not use (sse4a is not in the table at all) change nothing.
  const CliResult r = run("--version", "RAYLAB_CPU_CHECK_PRETEND_MISSING=fma,sse4a,avx2");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("this CPU lacks: avx2 fma;"), std::string::npos) << r.err;
}

TEST_F(Cli, PretendingAnUnusedExtensionIsMissingChangesNothing) {
  const CliResult r = run("--version", "RAYLAB_CPU_CHECK_PRETEND_MISSING=sse4a");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "raylab " RAYLAB_VERSION_STRING "\n" + isa_summary() + "\n");
}

}  // namespace
}  // namespace raylab
