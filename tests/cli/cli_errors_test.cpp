// The command line's contract on failure: exit code 2 for a bad request (with a message that
// names the option or lists the valid values), 1 for bad input data (with file:line:col where
// there is one), and never an output or temporary file left behind. Also write_file_atomically.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_fixture.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

using namespace cli_test;

// A tiny render of the demo with `flags` appended, writing into the output folder.
std::string demo_with(const std::string& flags, const std::string& output) {
  return "render demo --width 8 --height 6 --spp 1 -q -o '" + output + "' " + flags;
}

TEST_F(Cli, UsageErrorsExitWithTwoAndNameTheOption) {
  struct Case {
    std::string flags;
    std::vector<std::string> must_mention;
  };
  const Case cases[] = {
      {"--bogus", {"--bogus"}},
      {"--width 0", {"--width"}},
      {"--width abc", {"--width"}},
      {"--height -5", {"--height"}},
      {"--spp -1", {"--spp"}},
      {"--spp 0", {"--spp"}},
      {"--threads -3", {"--threads"}},
      {"--max-depth 0", {"--max-depth"}},
      {"--seed -1", {"--seed"}},  // would wrap to 2^64 - 1 in an unsigned option
      {"--accel nope", {"--accel", "bvh", "brute"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.flags);
    const CliResult r = run(demo_with(c.flags, out_file("x.png")));
    EXPECT_EQ(r.code, 2);
    for (const std::string& word : c.must_mention) EXPECT_NE(r.err.find(word), std::string::npos) << r.err;
    expect_out_empty();
  }
}

TEST_F(Cli, MissingSubcommandOrArgumentsIsAUsageError) {
  EXPECT_EQ(run("").code, 2);
  EXPECT_EQ(run("frobnicate").code, 2);
  EXPECT_EQ(run("diff").code, 2);
}

TEST_F(Cli, UnknownSceneListsTheBuiltIns) {
  const CliResult r = run("render no-such-scene -q -o '" + out_file("x.png") + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no-such-scene"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("demo"), std::string::npos) << r.err;
  expect_out_empty();
}

TEST_F(Cli, UnknownOutputExtensionListsTheFormats) {
  for (const std::string name : {"out.jpg", "out", "out.png.bak"}) {
    SCOPED_TRACE(name);
    const CliResult r = run(demo_with("", out_file(name)));
    EXPECT_EQ(r.code, 2);
    for (const char* ext : {".png", ".exr", ".pfm"}) EXPECT_NE(r.err.find(ext), std::string::npos) << r.err;
  }
  expect_out_empty();
}

TEST_F(Cli, MissingObjFileIsAnInputError) {
  const std::string missing = (work() / "no-such-mesh.obj").string();
  const CliResult r = run("render '" + missing + "' -q -o '" + out_file("x.png") + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  expect_out_empty();
}

TEST_F(Cli, OutputFolderThatDoesNotExistIsAUsageError) {
  const CliResult r = run(demo_with("", "/nonexistent/dir/x.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/nonexistent/dir"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists("/nonexistent"));
}

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

// Each bad OBJ fails with exit code 1 and `file:line:col:` pointing at the offending token.
TEST_F(Cli, BadObjFilesReportLineAndColumn) {
  struct Case {
    std::string name, text, position;
  };
  const Case cases[] = {
      {"past_end.obj", std::string(kTriangle) + "f 1 2 9\n", ":4:7: "},
      {"negative.obj", std::string(kTriangle) + "f -1 -2 -5\n", ":4:9: "},
      {"zero.obj", std::string(kTriangle) + "f 0 1 2\n", ":4:3: "},
      {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", ":2:3: "},
      {"inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n", ":3:7: "},
      {"overflow.obj", "v 0 0 0\nv 1 1e999 0\nv 0 1 0\nf 1 2 3\n", ":2:5: "},
      // A face of two corners (which the reader drops) before the bad one must not shift the line.
      {"after_short_face.obj", std::string(kTriangle) + "f 1 2\n  f 1 2 3 4\n", ":5:11: "},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = obj(c.name, c.text);
    const CliResult r = run("render '" + path + "' --width 8 --height 6 -q -o '" + out_file("x.png") + "'");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(path + c.position), std::string::npos) << r.err;
    expect_out_empty();
  }
}

// A tetrahedron renders to every format, and each file reads back at the requested size.
TEST_F(Cli, ValidObjRendersToEveryFormat) {
  const std::string mesh = obj("tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  for (const std::string ext : {".png", ".exr", ".pfm"}) {
    SCOPED_TRACE(ext);
    const std::string output = out_file("tetra" + ext);
    const CliResult r = run("render '" + mesh + "' --width 24 --height 16 --spp 1 -q -o '" + output + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    const Film film = read_image(output);
    EXPECT_EQ(film.width(), 24);
    EXPECT_EQ(film.height(), 16);
    // The mesh is framed by the fitted camera, so the image is not just the background.
    bool varied = false;
    for (const Color& c : film.pixels()) varied = varied || !(c == film.pixels()[0]);
    EXPECT_TRUE(varied);
  }
  // Only the three images: no temporary file survived a successful write either.
  EXPECT_EQ(entries(out()).size(), 3u);
}

TEST_F(Cli, DiffExitCodes) {
  Film black(6, 4), white(6, 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 6; ++x) white.at(x, y) = {1.f, 1.f, 1.f};
  }
  const std::string a = (work() / "a.pfm").string(), a2 = (work() / "a2.png").string();
  const std::string b = (work() / "b.exr").string(), small = (work() / "small.pfm").string();
  write_image(black, a);
  write_image(black, a2);
  write_image(white, b);
  write_image(Film(3, 2), small);

  CliResult r = run("diff '" + a + "' '" + a2 + "'");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rmse 0.0000"), std::string::npos) << r.out;
  EXPECT_EQ(run("diff '" + a + "' '" + a2 + "' --max-rmse 0").code, 0);

  r = run("diff '" + a + "' '" + b + "' --max-rmse 0.5");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("rmse 255.0000"), std::string::npos) << r.out;  // every channel 0 vs 255
  EXPECT_EQ(run("diff '" + a + "' '" + b + "'").code, 0);              // no threshold: report only

  // Identical dark values (sRGB's linear segment) are no difference at all, even at threshold 0.
  Film dark(2, 1);
  dark.at(0, 0) = {1e-30f, 1e-3f, 0.002f};
  dark.at(1, 0) = {0.5f, 0.003f, 1e-6f};
  const std::string d = (work() / "dark.pfm").string();
  write_image(dark, d);
  EXPECT_EQ(run("diff '" + d + "' '" + d + "' --max-rmse 0").code, 0);

  EXPECT_EQ(run("diff '" + a + "' '" + small + "'").code, 5);  // sizes differ: cannot compare
  EXPECT_EQ(run("diff '" + a + "' '" + (work() / "missing.pfm").string() + "'").code, 5);
  EXPECT_EQ(run("diff '" + a + "' '" + b + "' --max-rmse -1").code, 2);

  // --image writes where they differ (here everywhere, white); an unwritable one is refused first.
  r = run("diff '" + a + "' '" + b + "' --image '" + out_file("d.png") + "' --scale 4");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(image_rmse(read_image(out_file("d.png")), white), 0.0);
  r = run("diff '" + a + "' '" + b + "' --image '" + out_file("none/d.png") + "'");
  EXPECT_EQ(r.code, 2) << r.err;  // refused before the images are read
  EXPECT_EQ(r.out.find("rmse"), std::string::npos) << r.out;
}

std::vector<unsigned char> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

TEST_F(Cli, AtomicWriteIntoMissingFolderThrowsAndCreatesNothing) {
  const fs::path target = out() / "missing" / "x.bin";
  EXPECT_THROW(write_file_atomically(target.string(), bytes_of("data")), InputError);
  EXPECT_THROW(check_writable(target.string()), UsageError);  // the check before the work
  EXPECT_FALSE(fs::exists(out() / "missing"));
  expect_out_empty();
}

TEST_F(Cli, AtomicWriteOntoAFolderThrowsAndLeavesItAlone) {
  fs::create_directories(out() / "dir");
  write_text(out() / "dir" / "keep.txt", "kept");
  EXPECT_THROW(write_file_atomically((out() / "dir").string(), bytes_of("data")), InputError);
  EXPECT_EQ(read_text(out() / "dir" / "keep.txt"), "kept");
  EXPECT_EQ(entries(out()).size(), 1u);
}

TEST_F(Cli, AtomicWriteReplacesOldContentAndLeavesNoTemporary) {
  const std::string target = out_file("file.bin");
  write_file_atomically(target, bytes_of("old content that is longer"));
  write_file_atomically(target, bytes_of("new"));
  EXPECT_EQ(read_text(target), "new");
  EXPECT_EQ(entries(out()), std::vector<std::string>{"file.bin"});
  write_file_atomically(target, {});  // an empty file is a file too
  EXPECT_TRUE(fs::exists(target));
  EXPECT_EQ(fs::file_size(target), 0u);
}

// A name near NAME_MAX (255) is valid; the temporary next to it must still have a valid name.
TEST_F(Cli, AtomicWriteHandlesLongFileNames) {
  const std::string target = out_file(std::string(250, 'n') + ".bin");
  ASSERT_NO_THROW(write_file_atomically(target, bytes_of("long")));
  EXPECT_EQ(read_text(target), "long");
  EXPECT_EQ(entries(out()).size(), 1u);
}

}  // namespace
}  // namespace raylab
