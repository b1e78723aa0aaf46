// The instruction set of the kernels from the command line: `--isa`, RAYLAB_ISA, and what
// `--version` and `bench` say about it. A set the CPU lacks, or an unknown name, is a usage error
// (exit 2) naming the option or the variable.

#include <gtest/gtest.h>

#include <string>

#include "cli_fixture.h"
#include "raylab/core/isa.h"

namespace raylab {
namespace {

using namespace cli_test;

TEST_F(Cli, VersionNamesTheActiveSetAndEveryForcedOne) {
  for (Isa isa : usable_isas()) {
    const std::string name = isa_name(isa);
    const CliResult by_option = run("--isa " + name + " --version");
    EXPECT_EQ(by_option.code, 0) << by_option.err;
    EXPECT_NE(by_option.out.find("kernels: " + name + " (built: "), std::string::npos) << by_option.out;
    const CliResult bench = run("bench demo --against none --repeats 1 --width 8 --height 8 --isa " + name);
    EXPECT_EQ(bench.code, 0) << bench.err;
    EXPECT_NE(bench.out.find("our kernels: " + name + "\n"), std::string::npos) << bench.out;
    const CliResult by_variable = run("--version", "RAYLAB_ISA=" + name);
    EXPECT_EQ(by_variable.code, 0) << by_variable.err;
    EXPECT_NE(by_variable.out.find("kernels: " + name + " (built: "), std::string::npos) << by_variable.out;
  }
}

TEST_F(Cli, UnknownSetIsAUsageErrorNamingTheOptionOrTheVariable) {
  const CliResult option = run("--isa sse9 info demo");
  EXPECT_EQ(option.code, 2);
  EXPECT_NE(option.err.find("--isa sse9: not an instruction set (expected baseline, avx2 or avx512)"),
            std::string::npos)
      << option.err;
  const CliResult variable = run("info demo", "RAYLAB_ISA=sse9");
  EXPECT_EQ(variable.code, 2);
  EXPECT_NE(variable.err.find("RAYLAB_ISA=sse9: not an instruction set"), std::string::npos) << variable.err;
}

TEST_F(Cli, ASetTheCpuLacksIsRefusedWithWhatIsMissing) {
  // Play a CPU without AVX-512F (the load-time check's switch): the widest set is then avx2 at
  // most, and asking for avx512 names what is missing.
  const std::string pretend = "RAYLAB_CPU_CHECK_PRETEND_MISSING=avx512f";
  const CliResult r = run("--isa avx512 info demo", pretend);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--isa avx512: "), std::string::npos) << r.err;
  const bool built = isa_unusable_reason(Isa::avx512).find("built without") == std::string::npos;
  if (built) {
    EXPECT_NE(r.err.find("this CPU lacks avx512f"), std::string::npos) << r.err;
  }
  const CliResult version = run("--version", pretend);
  EXPECT_EQ(version.code, 0) << version.err;
  EXPECT_EQ(version.out.find("kernels: avx512"), std::string::npos) << version.out;
}

TEST_F(Cli, BenchSaysWhichSetItMeasured) {
  for (Isa isa : usable_isas()) {
    const std::string name = isa_name(isa);
    const CliResult r = run("bench spd:balls?size=1 --against none --repeats 1 --width 32 --height 24 --isa " + name);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("our kernels: " + name + "\n"), std::string::npos) << r.out;
  }
}

}  // namespace
}  // namespace raylab
