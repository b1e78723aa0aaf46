// load_obj: triangulation, index resolution, normals and degenerate faces on small files written
// here, a real scanned mesh when present, and errors located at the exact line and column.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../test_paths.h"
#include "io_test_util.h"
#include "mesh_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/obj_loader.h"

namespace raylab {
namespace {

using test::expect_triangle;
using test::expect_vec;

namespace fs = std::filesystem;

class ObjLoader : public ::testing::Test {
 protected:
  void SetUp() override { m_object = m_scene.add_object("mesh", m_scene.add_material({})); }

  // Writes `text` to a file in the test's folder and loads it into the scene.
  MeshLoadReport load(const std::string& text) {
    m_path = test::write_text(m_dir.path() / "mesh.obj", text);
    return load_obj(m_path, m_scene, m_object);
  }

  // Loads `text`, which must fail; checks the position the InputError gives and its message form.
  void expect_error_at(const std::string& text, int line, int col) {
    try {
      load(text);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), m_path);
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_EQ(e.column(), col) << e.what();
      const std::string prefix = m_path + ":" + std::to_string(line) + ":" + std::to_string(col) + ": ";
      EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
    }
  }

  const Geometry& geometry() const { return m_scene.geometry; }

  Scene m_scene;
  std::uint32_t m_object = 0;
  test::TempDir m_dir{"obj"};
  std::string m_path;
};

constexpr const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST_F(ObjLoader, StanfordBunnyHasAllItsTriangles) {
  const std::string bunny = raylab::test::source_dir() + "/../shared/scenes/stanford-bunny.obj";
  if (!fs::exists(bunny)) GTEST_SKIP() << bunny << " is not present";
  const MeshLoadReport r = load_obj(bunny, m_scene, m_object);
  EXPECT_EQ(r.vertices, 35947u);
  EXPECT_EQ(r.triangles, 69451u);
  EXPECT_EQ(r.degenerate_dropped, 0u);
  EXPECT_EQ(geometry().triangles.size(), 69451u);
  EXPECT_TRUE(geometry().triangle_normals.empty());  // the file has no normals
  for (std::uint32_t obj : geometry().triangle_objects) ASSERT_EQ(obj, m_object);
  // The bunny is about 15 cm across, standing on y = 0.033.
  const Box3 b = geometry().bounds();
  EXPECT_NEAR(b.extent().x, 0.156, 0.002);
  EXPECT_NEAR(b.lo.y, 0.033, 0.001);
}

TEST_F(ObjLoader, QuadIsFanTriangulated) {
  const MeshLoadReport r = load(std::string(kSquare) + "f 1 2 3 4\n");
  EXPECT_EQ(r.vertices, 4u);
  ASSERT_EQ(r.triangles, 2u);
  ASSERT_EQ(geometry().triangles.size(), 2u);
  const Triangle& t0 = geometry().triangles[0];
  const Triangle& t1 = geometry().triangles[1];
  expect_triangle(t0, {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
  expect_triangle(t1, {0, 0, 0}, {1, 1, 0}, {0, 1, 0});
}

TEST_F(ObjLoader, PolygonOfNCornersGivesNMinusTwoTriangles) {
  const MeshLoadReport r = load("v 0 0 0\nv 2 0 0\nv 3 1 0\nv 2 2 0\nv 0 2 0\nv -1 1 0\nf 1 2 3 4 5 6\n");
  EXPECT_EQ(r.triangles, 4u);
  for (const Triangle& t : geometry().triangles) expect_vec(t.p0, {0, 0, 0});  // the fan's hub
}

// A negative index counts back from the last vertex read so far, not from the end of the file.
TEST_F(ObjLoader, NegativeIndicesAreRelativeToVerticesSoFar) {
  const MeshLoadReport r = load(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
      "v 5 5 5\nv 6 5 5\nv 5 6 5\nf -3 -2 -1\nf 1 -1 -2\n");
  ASSERT_EQ(r.triangles, 3u);
  expect_vec(geometry().triangles[0].p0, {0, 0, 0});
  expect_vec(geometry().triangles[0].p2, {0, 1, 0});
  expect_vec(geometry().triangles[1].p0, {5, 5, 5});
  expect_vec(geometry().triangles[1].p2, {5, 6, 5});
  expect_triangle(geometry().triangles[2], {0, 0, 0}, {5, 6, 5}, {6, 5, 5});
}

TEST_F(ObjLoader, VertexNormalsAreUsedWhenEveryCornerHasOne) {
  const MeshLoadReport r = load(std::string(kSquare) +
                                "vn 0 0 1\nvn 0.6 0 0.8\n"
                                "f 1 2 3\n"           // no normals: geometric
                                "f 1//1 3//2 4//1\n"  // all corners: used
                                "f 1//1 2 3\n");      // some corners only: geometric
  ASSERT_EQ(r.triangles, 3u);
  ASSERT_EQ(geometry().triangle_normals.size(), 3u);  // parallel to the triangles
  for (const Vec3& n : geometry().triangle_normals[0]) expect_vec(n, {0, 0, 0});
  expect_vec(geometry().triangle_normals[1][0], {0, 0, 1});
  expect_vec(geometry().triangle_normals[1][1], {0.6f, 0, 0.8f});
  expect_vec(geometry().triangle_normals[1][2], {0, 0, 1});
  for (const Vec3& n : geometry().triangle_normals[2]) expect_vec(n, {0, 0, 0});
}

TEST_F(ObjLoader, DegenerateFacesAreCountedAndDropped) {
  const MeshLoadReport r = load(std::string(kSquare) +
                                "v 2 0 0\n"
                                "f 1 2 2\n"      // repeated corner
                                "f 1 2 5\n"      // collinear
                                "f 1 2 3\n"      // fine
                                "f 1 2 2 3\n");  // quad with a repeated corner: one triangle
  EXPECT_EQ(r.degenerate_dropped, 3u);
  EXPECT_EQ(r.triangles, 2u);
  EXPECT_EQ(geometry().triangles.size(), 2u);
}

// What does not change the geometry must not change line numbers either: comments, blank lines,
// indentation, CRLF line ends, groups and objects, '+' signs and leading dots.
TEST_F(ObjLoader, TolerantOfOrdinaryFileVariations) {
  const MeshLoadReport r = load(
      "# comment\r\n\r\n  v +1 -2 .5\r\nv 1e1 0 0\r\n\tv 0 1 0\r\no first\r\ng part\r\nf 1 2 3\r\n"
      "o second\r\nf 3 2 1\r\n");
  EXPECT_EQ(r.triangles, 2u);
  expect_vec(geometry().triangles[0].p0, {1.f, -2.f, 0.5f});
  expect_vec(geometry().triangles[0].p1, {10.f, 0.f, 0.f});
}

TEST_F(ObjLoader, IndexPastTheEnd) { expect_error_at(std::string(kSquare) + "f 1 2 3\nf 1 2 9\n", 6, 7); }

TEST_F(ObjLoader, NegativeIndexBeforeTheStart) {
  expect_error_at(std::string(kSquare) + "f -1 -2 -5\n", 5, 9);
  // Relative to the vertices so far: -4 is valid at the end of the file, not on line 4.
  expect_error_at("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\nv 1 1 1\n", 4, 9);
}

TEST_F(ObjLoader, ZeroIndex) { expect_error_at(std::string(kSquare) + "f 1 2 3\nf 3  0 1\n", 6, 6); }

TEST_F(ObjLoader, NormalIndexOutOfRange) {
  expect_error_at(std::string(kSquare) + "vn 0 0 1\nf 1//1 2//1 3//2\n", 6, 13);
}

TEST_F(ObjLoader, NonFiniteCoordinates) {
  expect_error_at("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 2, 3);
  expect_error_at("v 0 0 0\nv 1 0 0\n  v 0 1 inf\nf 1 2 3\n", 3, 9);
  expect_error_at("v 0 0 0\nv 1 1e999 0\nv 0 1 0\nf 1 2 3\n", 2, 5);  // overflows
  expect_error_at("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 -1e40 1\nf 1 2 3\n", 4, 6);
}

// The reader silently drops faces of one or two corners; later errors must still be placed right.
TEST_F(ObjLoader, ShortFacesDoNotShiftErrorPositions) {
  expect_error_at(std::string(kSquare) + "f 1 2\nf 1\nf 1 2 3\n f 1 2 7\n", 8, 8);
}

TEST_F(ObjLoader, MissingFileIsAnInputError) {
  const std::string missing = m_dir.file("nope.obj");
  try {
    load_obj(missing, m_scene, m_object);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing);
    EXPECT_EQ(e.line(), 0);
  }
}

}  // namespace
}  // namespace raylab
