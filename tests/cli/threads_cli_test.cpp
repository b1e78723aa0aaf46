// --threads above the core count (issue 21, item 7): no raw "TBB Warning" on stderr, at most one
// note of raylab's own, for render, compare, quality and bench; the image is the same.

#include "cli_fixture.h"
#include "raylab/core/thread_count.h"

namespace raylab::cli_test {
namespace {

std::size_t count_of(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

TEST_F(Cli, ThreadsAboveTheCoresGiveOneNoteAndNoTbbWarning) {
  const std::string expected_note = "note: " + thread_count_notice(64) + "\n";
  ASSERT_NE(thread_count_notice(64), "") << "a machine of 64 cores or more: nothing to test";
  for (const std::string& args :
       {std::string("render demo --width 32 --height 24 -o ") + out_file("x.png"),
        std::string("compare spd:balls?size=1 --width 16 --height 16 --accels bvh,grid"),
        "quality demo --width 16 --height 12 --budgets 1 --seeds 1 --reference-spp 4 --samplers jittered "
        "--cache-dir " +
            out_file("cache"),
        std::string("bench spd:balls?size=1 --width 16 --height 8 --rays primary --repeats 1")}) {
    const CliResult r = run(args + " --threads 64");
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find("TBB"), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(count_of(r.err, expected_note), 1u) << args << "\n" << r.err;
  }
}

TEST_F(Cli, ThreadsAboveTheCoresRenderTheSameImage) {
  ASSERT_EQ(run("render demo --width 32 --height 24 -q --threads 64 -o " + out_file("many.pfm")).code, 0);
  ASSERT_EQ(run("render demo --width 32 --height 24 -q --threads 1 -o " + out_file("one.pfm")).code, 0);
  EXPECT_EQ(read_text(out_file("many.pfm")), read_text(out_file("one.pfm")));
}

TEST(ThreadCount, UsableThreadsCapsAtTheCores) {
  const int cores = available_cores();
  EXPECT_GE(cores, 1);
  EXPECT_EQ(usable_threads(0), cores);
  EXPECT_EQ(usable_threads(1), 1);
  EXPECT_EQ(usable_threads(cores + 5), cores);
  EXPECT_EQ(thread_count_notice(cores), "");
  EXPECT_EQ(thread_count_notice(cores + 1), "--threads " + std::to_string(cores + 1) + " is more than this machine's " +
                                                std::to_string(cores) + (cores == 1 ? " core" : " cores") + "; using " +
                                                std::to_string(cores));
}

}  // namespace
}  // namespace raylab::cli_test
