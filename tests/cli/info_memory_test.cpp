// `raylab info` reports the bytes a scene's data really holds (in use, not reserved), through
// the real binary: exactly the hand-computed figure for a tiny OBJ, and in proportion to the
// triangle count for meshes of different sizes.

#include <gtest/gtest.h>

#include <string>

#include "cli_fixture.h"
#include "raylab/scene/scene.h"

namespace raylab {
namespace {

using namespace cli_test;

// The exact figure of the "memory ... in use (N bytes" line.
std::size_t used_bytes(const std::string& info) {
  const std::size_t at = info.find(" in use (");
  EXPECT_NE(at, std::string::npos) << info;
  return at == std::string::npos ? 0 : std::stoull(info.substr(at + 9));
}

// An n x n grid of squares, two triangles each, as OBJ text.
std::string grid_obj(int n) {
  std::string text;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) text += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
  auto at = [&](int x, int y) { return std::to_string(y * (n + 1) + x + 1); };
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      text += "f " + at(x, y) + " " + at(x + 1, y) + " " + at(x + 1, y + 1) + "\n";
      text += "f " + at(x, y) + " " + at(x + 1, y + 1) + " " + at(x, y + 1) + "\n";
    }
  }
  return text;
}

TEST_F(Cli, InfoMemoryOfATinyObjIsTheHandComputedFigure) {
  const CliResult r = run("info '" + obj("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  // Two triangles of 3 float vertices and their object ids; one object ("t.obj", short enough
  // to live inside its string), one material (the grey default), and the two fitted lights.
  const std::size_t geometry = 2 * (9 * sizeof(float) + sizeof(std::uint32_t));
  EXPECT_EQ(geometry, 80u);
  EXPECT_EQ(used_bytes(r.out), geometry + sizeof(SceneObject) + sizeof(Material) + 2 * sizeof(Light)) << r.out;
  EXPECT_NE(r.out.find("geometry 80 B, normals and uvs 0 B"), std::string::npos) << r.out;
}

TEST_F(Cli, InfoMemoryGrowsInProportionToTheTriangles) {
  const CliResult small = run("info '" + obj("small.obj", grid_obj(50)) + "'");   // 5,000 triangles
  const CliResult large = run("info '" + obj("large.obj", grid_obj(100)) + "'");  // 20,000 triangles
  ASSERT_EQ(small.code, 0) << small.err;
  ASSERT_EQ(large.code, 0) << large.err;
  const double ratio = static_cast<double>(used_bytes(large.out)) / static_cast<double>(used_bytes(small.out));
  // Four times the triangles: four times the bytes, but for a few hundred fixed ones.
  EXPECT_NEAR(ratio, 4.0, 0.01) << small.out << large.out;
  EXPECT_GE(used_bytes(large.out), 20000u * 40u);
}

}  // namespace
}  // namespace raylab
