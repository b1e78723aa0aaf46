// Long renders through the real binary: renders killed at random moments (SIGINT, SIGTERM, twice
// SIGINT, SIGKILL) and resumed until done give the bytes of an uninterrupted render; no signal
// leaves a half-written image or a stray temporary; a second signal ends the run at once; passes
// write the image after each pass; a checkpoint of other settings is refused, naming them.

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <random>
#include <thread>

#include "../test_paths.h"
#include "background_process.h"
#include "cli_fixture.h"

namespace raylab::cli_test {
namespace {

class LongRender : public Cli {
 protected:
  // Names in `out` that look like temporaries of an atomic write.
  std::vector<std::string> temporaries() const {
    std::vector<std::string> t;
    for (const std::string& n : entries(out())) {
      if (n.ends_with(".tmp")) t.push_back(n);
    }
    return t;
  }
  // A whole PFM of width x height: header, then exactly the pixels.
  void expect_whole_pfm(const std::string& path, int width, int height) const {
    const std::string bytes = read_text(path);
    const std::string header = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + std::size_t(width) * height * 12) << path;
    EXPECT_EQ(bytes.substr(0, header.size()), header);
  }
};

TEST_F(LongRender, KilledAtRandomMomentsAndResumedGivesTheSameBytes) {
  const std::string settings = "render demo --width 96 --height 54 --spp 36 --threads 2 -q";
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run(settings + " -o '" + out_file("reference.pfm") + "'").code, 0);
  // Signals land at random moments over the whole run, start-up included, as long as it takes
  // on this machine (under a sanitizer, start-up alone can take 0.2 s).
  const auto whole_run =
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start);
  const auto moments = static_cast<unsigned>(std::max<std::int64_t>(whole_run.count(), 50000));
  const std::string reference = read_text(out_file("reference.pfm"));
  std::mt19937 random(20261202);
  const int kSignals[] = {SIGINT, SIGTERM, SIGKILL, 0 /* SIGINT twice */};
  int interruptions = 0, resumes = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const std::string image = out_file("trial.pfm"), checkpoint = out_file("trial.ckpt");
    fs::remove(image);
    fs::remove(checkpoint);
    const std::string passes = trial % 2 == 0 ? "1" : "3";
    bool started = false;
    // Interrupted up to 8 times, then left to finish (under a sanitizer a render is ten times slower).
    for (int attempt = 0; attempt < 9; ++attempt) {
      std::string command = settings + " --passes " + passes + " -o " + image + " --checkpoint " + checkpoint +
                            " --checkpoint-every 0.02";
      if (started && fs::exists(checkpoint)) {
        command += " --resume " + checkpoint;
        ++resumes;
      }
      started = true;
      const Background render(split(command), work() / "stderr.txt");
      const int sig = kSignals[random() % 4];
      if (attempt == 8) {
        ASSERT_EQ(render.wait(), 0) << read_text(work() / "stderr.txt");
        break;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(random() % moments));
      render.signal(sig == 0 ? SIGINT : sig);
      if (sig == 0) render.signal(SIGINT);
      const int code = render.wait();
      if (code == 0) break;  // finished before the signal
      ++interruptions;
      const int expected = sig == SIGKILL ? 128 + SIGKILL : sig == SIGTERM ? 143 : 130;
      EXPECT_EQ(code, expected) << read_text(work() / "stderr.txt");
      if (sig == SIGKILL) {
        for (const std::string& t : temporaries()) fs::remove(out() / t);  // nothing can clean up after SIGKILL
      } else {
        EXPECT_TRUE(temporaries().empty()) << "after signal " << sig << ": " << temporaries().front();
      }
      // Whatever the moment, the image is either absent or whole, never half written.
      if (fs::exists(image)) expect_whole_pfm(image, 96, 54);
    }
    ASSERT_TRUE(fs::exists(image)) << "trial " << trial << " never finished";
    EXPECT_EQ(read_text(image), reference) << "trial " << trial;
    EXPECT_FALSE(fs::exists(checkpoint)) << "a complete render removes its checkpoint";
  }
  // Not a figure to assert on (timing decides), but the test is only worth something if it
  // interrupted renders and resumed some.
  EXPECT_GT(interruptions, 0);
  EXPECT_GT(resumes, 0);
  std::printf("interruptions %d, resumes %d\n", interruptions, resumes);
}

// A render whose single tile takes long (one thread, 1024 samples per pixel: over a second): a first SIGINT waits
// for the tile and saves; a second one ends the run at once, writing nothing.
TEST_F(LongRender, ASecondSignalEndsTheRunAtOnce) {
  const std::string image = out_file("slow.pfm");
  const std::string command = "render demo --width 16 --height 16 --spp 1024 --threads 1 -q -o " + image;
  {
    const Background render(split(command), work() / "stderr.txt");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const auto start = std::chrono::steady_clock::now();
    render.signal(SIGINT);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    render.signal(SIGINT);
    EXPECT_EQ(render.wait(), 130);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.25);
    EXPECT_TRUE(entries(out()).empty()) << "left behind: " << entries(out()).front();
  }
  {
    // One signal: the tile under way finishes; the image (complete: there is one tile) and a
    // checkpoint are written.
    const Background render(split(command), work() / "stderr.txt");
    std::this_thread::sleep_for(std::chrono::milliseconds(600));  // well into the tile
    render.signal(SIGINT);
    const int code = render.wait();
    const std::string err = read_text(work() / "stderr.txt");
    if (code == 130) {  // the tile had not started yet when the signal came (a very slow machine)
      EXPECT_NE(err.find("interrupted by SIGINT"), std::string::npos) << err;
    } else {
      EXPECT_EQ(code, 0) << err;
    }
    expect_whole_pfm(image, 16, 16);
  }
}

TEST_F(LongRender, PassesWriteTheImageAfterEachPassAndEndWithTheSameBytes) {
  ASSERT_EQ(run("render demo --width 48 --height 32 --spp 9 -q -o " + out_file("one.pfm")).code, 0);
  const CliResult r = run("render demo --width 48 --height 32 --spp 9 --passes 3 -o " + out_file("three.pfm"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("pass 1/3: wrote"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("pass 2/3: wrote"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(out_file("three.pfm")), read_text(out_file("one.pfm")));
  EXPECT_EQ(run("render demo --spp 4 --passes 5 -o " + out_file("x.pfm")).code, 2);
  EXPECT_EQ(run("render demo --sampler adaptive --passes 2 -o " + out_file("x.pfm")).code, 2);
}

TEST_F(LongRender, ACheckpointOfOtherSettingsOrDamagedIsRefused) {
  const std::string image = out_file("slow.pfm"), checkpoint = out_file("slow.ckpt");
  // A signal before the render has started ends the run with nothing to save; wait longer until
  // one lands during the render (start-up takes 0.2 s under a sanitizer on a loaded machine).
  for (int wait_ms = 200; wait_ms <= 3200 && !fs::exists(checkpoint); wait_ms *= 2) {
    const Background render(split("render demo --width 64 --height 16 --spp 1024 --threads 1 -q -o " + image),
                            work() / "e.txt");
    std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
    render.signal(SIGTERM);
    ASSERT_EQ(render.wait(), 143);
  }
  ASSERT_TRUE(fs::exists(checkpoint)) << "the default checkpoint sits beside the output";
  const CliResult other = run("render demo --width 64 --height 16 --spp 256 -o " + image + " --resume " + checkpoint);
  EXPECT_EQ(other.code, 1);
  EXPECT_NE(other.err.find("spp: 1024 in the checkpoint, 256 now"), std::string::npos) << other.err;
  const CliResult scene = run("render cornell -o " + image + " --resume " + checkpoint);
  EXPECT_EQ(scene.code, 1);
  EXPECT_NE(scene.err.find("scene: 'demo' in the checkpoint, 'cornell' now"), std::string::npos) << scene.err;
  write_text(work() / "cut.ckpt", read_text(checkpoint).substr(0, 200));
  const CliResult cut = run("render --resume '" + (work() / "cut.ckpt").string() + "' -o " + image);
  EXPECT_EQ(cut.code, 1);
  EXPECT_NE(cut.err.find("cut.ckpt: byte"), std::string::npos) << cut.err;
}

}  // namespace
}  // namespace raylab::cli_test
