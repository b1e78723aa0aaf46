// `raylab diff`'s exit codes and messages through the real binary: 1 only when the images differ
// beyond the threshold, 5 (its own code) with a plain message when they cannot be compared.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli_fixture.h"
#include "raylab/io/image_io.h"
#include "raylab/render/film.h"

namespace raylab {
namespace {

using namespace cli_test;

constexpr int kImagesDiffer = 1;
constexpr int kCannotCompare = 5;

class DiffCli : public Cli {
 protected:
  // A `w` x `h` image of one grey `v` (linear), written into the work folder as `name`.
  std::string image(const std::string& name, int w, int h, float v) const {
    Film f(w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) f.at(x, y) = {v, v, v};
    }
    const std::string path = (work() / name).string();
    write_image(f, path);
    return path;
  }
  CliResult diff(const std::string& a, const std::string& b, const std::string& flags = "") const {
    return run("diff '" + a + "' '" + b + "' " + flags);
  }
};

TEST_F(DiffCli, OneOnlyWhenTheImagesDifferBeyondTheThreshold) {
  const std::string a = image("a.png", 4, 3, 0.f), b = image("b.png", 4, 3, 1.f);
  EXPECT_EQ(diff(a, b, "--max-rmse 0.5").code, kImagesDiffer);
  EXPECT_EQ(diff(a, b, "--max-rmse 255").code, 0);  // 255 steps apart: not beyond
  EXPECT_EQ(diff(a, b).code, 0);                    // no threshold: a report only
  EXPECT_EQ(diff(a, a, "--max-rmse 0").code, 0);
}

TEST_F(DiffCli, MissingFileIsNotADifference) {
  const std::string a = image("a.png", 4, 3, 0.f);
  const std::string missing = (work() / "missing.png").string();
  const CliResult r = diff(missing, a, "--max-rmse 1");
  EXPECT_EQ(r.code, kCannotCompare);
  EXPECT_EQ(r.err, missing + ": cannot read: no such file\n");
  EXPECT_EQ(r.out, "");  // no rmse line for a comparison that did not happen
  EXPECT_EQ(diff(a, missing).code, kCannotCompare);
}

TEST_F(DiffCli, FolderIsNotAnImage) {
  const std::string a = image("a.png", 4, 3, 0.f);
  const CliResult r = diff(a, work().string());
  EXPECT_EQ(r.code, kCannotCompare);
  EXPECT_EQ(r.err, work().string() + ": cannot read: it is a folder\n");
}

TEST_F(DiffCli, FileThatIsNotAnImageSaysSoPlainly) {
  const std::string a = image("a.png", 4, 3, 0.f);
  for (const std::string name : {"text.png", "text.exr", "text.pfm"}) {
    write_text(work() / name, "not an image at all\n");
    const CliResult r = diff(a, (work() / name).string());
    EXPECT_EQ(r.code, kCannotCompare) << name;
    EXPECT_EQ(r.err.find("fopen"), std::string::npos) << r.err;              // no decoder's own words
    EXPECT_EQ(r.err.rfind((work() / name).string() + ":", 0), 0u) << r.err;  // names the file first
    EXPECT_NE(r.err.find(": not a"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one line
  }
}

TEST_F(DiffCli, SizesThatDifferNameBothSizes) {
  const std::string a = image("a.png", 10, 10, 0.f), b = image("b.pfm", 20, 20, 0.f);
  const CliResult r = diff(a, b);
  EXPECT_EQ(r.code, kCannotCompare);
  EXPECT_EQ(r.err, a + ": size 10x10 differs from " + b + "'s 20x20\n");
}

// Like every output, an --image that cannot be written is refused before the work: a usage
// error, not the answer "they differ".
TEST_F(DiffCli, UnwritableDifferenceImageIsAUsageErrorNotADifference) {
  const std::string a = image("a.png", 4, 3, 0.f), b = image("b.png", 4, 3, 1.f);
  const CliResult r = diff(a, b, "--image '" + out_file("none/d.png") + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  expect_out_empty();
}

TEST_F(DiffCli, UsageErrorsStayTwo) {
  const std::string a = image("a.png", 4, 3, 0.f);
  EXPECT_EQ(diff(a, a, "--max-rmse -1").code, 2);
  EXPECT_EQ(run("diff '" + a + "'").code, 2);
}

}  // namespace
}  // namespace raylab
