// Atomic output when the disk refuses: a write that fails part-way (here the file-size limit,
// RLIMIT_FSIZE, which fails write() with EFBIG just as a full disk fails it with ENOSPC) leaves the
// previous file byte for byte, no temporary beside it, and a message that says why; through the
// command line too, for an image and a checkpoint. (Refused permissions cannot be tested here: the
// tests run as root, whom permissions do not stop.)

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <span>
#include <string>
#include <vector>

#include "../cli/cli_fixture.h"
#include "../test_paths.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/image_io.h"
#include "raylab/render/film.h"

namespace raylab {
namespace {

using cli_test::entries;
using cli_test::read_text;
using cli_test::write_text;

class AtomicWrite : public cli_test::Cli {};

TEST_F(AtomicWrite, AWriteTheDiskRefusesKeepsThePreviousFile) {
  const std::string target = out_file("image.bin");
  write_text(target, "the previous, complete file");
  const pid_t child = ::fork();
  if (child == 0) {
    // In the child only: writes beyond 4 KiB fail (EFBIG) instead of raising SIGXFSZ.
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    const std::vector<unsigned char> big(1 << 20, 0x5A);
    try {
      write_file_atomically(target, big);
    } catch (const InputError& e) {
      const std::string message = e.what();
      // Says which file and why.
      ::_exit(message.find("image.bin") != std::string::npos && message.find("write failed") != std::string::npos ? 0
                                                                                                                  : 2);
    }
    ::_exit(1);  // no error at all: wrong
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: the write did not fail; 2: the message does not say what and why";
  EXPECT_EQ(read_text(target), "the previous, complete file");
  EXPECT_EQ(entries(out()), std::vector<std::string>{"image.bin"}) << "no temporary left beside it";
}

TEST_F(AtomicWrite, ARenderWhoseImageCannotBeWrittenKeepsThePreviousImage) {
  const std::string image = out_file("render.pfm");
  ASSERT_EQ(run("render demo --width 16 --height 8 -q -o " + image).code, 0);
  const std::string previous = read_text(image);
  // 64x64 floats need 48 KiB; the shell's file-size limit allows 8 KiB.
  const std::string command = "ulimit -f 8; '" + raylab::test::raylab_binary() +
                              "' render demo --width 64 --height 64 -q -o '" + image + "' 2>'" +
                              (work() / "err.txt").string() + "'";
  const int status = std::system(("bash -c \"" + command + "\"").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string err = read_text(work() / "err.txt");
  EXPECT_NE(err.find("render.pfm"), std::string::npos) << err;
  EXPECT_NE(err.find("File too large"), std::string::npos) << err;
  EXPECT_EQ(read_text(image), previous);
  EXPECT_EQ(entries(out()), std::vector<std::string>{"render.pfm"});
}

// Pieces go out in order, where they lie: more of them than one gathered write takes (IOV_MAX,
// 1024 on Linux), empty ones among them, and a large one.
TEST_F(AtomicWrite, PiecesAreWrittenInOrder) {
  std::vector<std::string> texts;
  for (int i = 0; i < 3000; ++i) texts.push_back(i % 7 == 0 ? std::string() : std::to_string(i) + ",");
  texts.push_back(std::string(1 << 20, 'z'));
  std::vector<std::span<const unsigned char>> pieces;
  std::string want;
  for (const std::string& t : texts) {
    pieces.emplace_back(reinterpret_cast<const unsigned char*>(t.data()), t.size());
    want += t;
  }
  const std::string target = out_file("pieces.bin");
  write_pieces_atomically(target, pieces);
  EXPECT_EQ(read_text(target), want);
  EXPECT_EQ(entries(out()), std::vector<std::string>{"pieces.bin"});
}

// A PFM goes out from the film's rows, not through encode_image: the two give the same bytes.
TEST_F(AtomicWrite, APfmWrittenFromTheFilmIsItsEncoding) {
  Film film(7, 5);
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) film.at(x, y) = {0.5f * x, 0.25f * y, x == y ? -1.f : 3.f};
  }
  const std::string target = out_file("image.pfm");
  write_image(film, target);
  const std::vector<unsigned char> encoded = encode_image(film, ".pfm");
  EXPECT_EQ(read_text(target), std::string(encoded.begin(), encoded.end()));
  write_image(Film(0, 0), target);  // an empty film: the header alone
  const std::vector<unsigned char> empty = encode_image(Film(0, 0), ".pfm");
  EXPECT_EQ(read_text(target), std::string(empty.begin(), empty.end()));
}

}  // namespace
}  // namespace raylab
