// The path integrator and the environment light through the real binary: the options' errors,
// and a path-traced render interrupted and resumed that gives the bytes of one never stopped.

#include <signal.h>

#include <chrono>
#include <thread>

#include "../test_paths.h"
#include "background_process.h"
#include "cli_fixture.h"

namespace raylab::cli_test {
namespace {

class PathCli : public Cli {};

TEST_F(PathCli, UnknownIntegratorIsAUsageErrorListingTheValidOnes) {
  const CliResult r = run("render demo --integrator photon -o " + out_file("x.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("whitted"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("path"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out_file("x.png")));
}

TEST_F(PathCli, BadEnvironmentsAreRefusedNamingTheOption) {
  const CliResult colour = run("render demo --integrator path --env 1,2 -o " + out_file("x.png"));
  EXPECT_EQ(colour.code, 2);
  EXPECT_NE(colour.err.find("--env: '1,2'"), std::string::npos) << colour.err;
  const CliResult rotate = run("render demo --integrator path --env-rotate 30 -o " + out_file("x.png"));
  EXPECT_EQ(rotate.code, 2);
  EXPECT_NE(rotate.err.find("--env-rotate"), std::string::npos) << rotate.err;
  // An image file that is not one: an input error, naming the file.
  const std::string bad = out_file("sky.exr");
  write_text(bad, "not an image");
  const CliResult file = run("render demo --integrator path --env " + bad + " -o " + out_file("x.png"));
  EXPECT_EQ(file.code, 1);
  EXPECT_NE(file.err.find("sky.exr"), std::string::npos) << file.err;
  EXPECT_FALSE(fs::exists(out_file("x.png")));
}

TEST_F(PathCli, EnvironmentLightsThePathTracedImage) {
  const std::string dark = out_file("dark.pfm"), lit = out_file("lit.pfm");
  ASSERT_EQ(run("render demo --integrator path --width 24 --height 16 --spp 4 --env 0,0,0 -q -o " + dark).code, 0);
  ASSERT_EQ(run("render demo --integrator path --width 24 --height 16 --spp 4 --env 2,2,2 -q -o " + lit).code, 0);
  EXPECT_NE(read_text(dark), read_text(lit));
}

TEST_F(PathCli, InterruptedAndResumedPathRenderGivesTheSameBytes) {
  const std::string settings =
      "render cornell --integrator path --width 64 --height 64 --spp 64 --passes 4 --threads 2 -q";
  const std::string reference = out_file("reference.pfm");
  ASSERT_EQ(run(settings + " -o " + reference).code, 0);
  const std::string image = out_file("resumed.pfm"), checkpoint = out_file("resumed.ckpt");
  {
    // Interrupted once a first checkpoint exists (or finished before: then nothing to resume).
    const Background render(
        split(settings + " -o " + image + " --checkpoint " + checkpoint + " --checkpoint-every 0.01"),
        work() / "stderr.txt");
    for (int i = 0; i < 2000 && !fs::exists(checkpoint); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    render.signal(SIGINT);
    const int code = render.wait();
    ASSERT_TRUE(code == 0 || code == 130) << read_text(work() / "stderr.txt");
  }
  if (fs::exists(checkpoint)) {
    ASSERT_EQ(run(settings + " -o " + image + " --resume " + checkpoint).code, 0);
  }
  EXPECT_EQ(read_text(image), read_text(reference));
}

}  // namespace
}  // namespace raylab::cli_test
