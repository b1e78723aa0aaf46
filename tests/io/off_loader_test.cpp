// parse_off / load_off: small files written here in each header variant give exactly the
// expected triangles, normals and uvs; the armadillo loads whole; bad input is refused with the
// error at the exact line:col, and random or mutated input never crashes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../test_paths.h"
#include "io_test_util.h"
#include "mesh_test_util.h"
#include "parse_error_util.h"
#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/io/off_loader.h"

namespace raylab {
namespace {

using test::expect_triangle;
using test::expect_vec;

namespace fs = std::filesystem;

std::string error_of(const std::string& text) { return test::parse_error(parse_off, text, "mesh.off"); }

void expect_error(const std::string& text, const std::string& prefix, const std::string& words) {
  test::expect_message(error_of(text), prefix, words);
}

// The position just past the end of `text`, where a truncated file's error is reported.
std::string end_prefix(const std::string& text) { return test::end_position("mesh.off", text); }

// A triangle of vertices (0 0 0) (1 0 0) (0 1 0) (lines 3-5) and face (line 6).
const std::string kTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

TEST(OffLoader, CommentsPolygonsAndFaceColours) {
  const std::string text =
      "OFF\n"
      "# a comment line\n"
      "\n"
      "4 2 0   # vertices faces edges\n"
      "0 0 0\n"
      "1 0 0\n"
      "1 1 0.5  # a comment after the values\n"
      "0 1 0.5\n"
      "3 0 1 2\n"
      "4 0 1 2 3 1 0 0\n";  // a quad with a colour
  Geometry g;
  test::expect_triangle_and_quad(parse_off(text, "c.off", g, 4), g, 4);
}

TEST(OffLoader, HeaderVariations) {
  const std::string variants[] = {
      kTriangle,
      "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",               // counts on the keyword's line
      "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",                   // no keyword
      "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2",                  // no edge count, no final newline
      "OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n",  // CRLF
      "\n\n# leading comment\nOFF\n3 1 0\n+0 0 0\n1.0 0 0\n0 1e0 0\n3 0 1 2\n",
      "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0\n0 1 0 0 0 255 255\n3 0 1 2 0.5 0.5 0.5 1\n",
  };
  for (const std::string& text : variants) {
    SCOPED_TRACE(text);
    Geometry g;
    EXPECT_EQ(parse_off(text, "v.off", g, 0).triangles, 1u);
    ASSERT_EQ(g.triangles.size(), 1u);
    expect_triangle(g.triangles[0], {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  }
}

TEST(OffLoader, VertexNormalsAndTextureCoordinates) {
  {
    Geometry g;
    parse_off("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 1 0\n0 1 0 1 0 0\n3 2 0 1\n", "n.off", g, 0);
    ASSERT_EQ(g.triangle_normals.size(), 1u);
    EXPECT_TRUE(g.triangle_uvs.empty());
    expect_triangle(g.triangles[0], {0, 1, 0}, {0, 0, 0}, {1, 0, 0});
    expect_vec(g.triangle_normals[0][0], {1, 0, 0});
    expect_vec(g.triangle_normals[0][1], {0, 0, 1});
    expect_vec(g.triangle_normals[0][2], {0, 1, 0});
  }
  {
    Geometry g;
    parse_off("STOFF\n3 1 0\n0 0 0 0.25 0.5\n1 0 0 1 0.5\n0 1 0 0.25 1\n3 0 1 2\n", "st.off", g, 0);
    ASSERT_EQ(g.triangle_uvs.size(), 1u);
    EXPECT_TRUE(g.triangle_normals.empty());
    EXPECT_EQ(g.triangle_uvs[0][0].x, 0.25f);
    EXPECT_EQ(g.triangle_uvs[0][1].x, 1.f);
    EXPECT_EQ(g.triangle_uvs[0][2].y, 1.f);
  }
  {
    // All three: position, normal, a colour of 4 or 3 values, then the texture coordinates last.
    Geometry g;
    parse_off(
        "STCNOFF\n3 1 0\n0 0 0 0 0 1 9 9 9 1 0.5 0.5\n1 0 0 0 0 1 9 9 9 0.75 0.5\n"
        "0 1 0 0 0 -1 9 9 9 1 0.5 0.75\n3 0 1 2\n",
        "all.off", g, 0);
    ASSERT_EQ(g.triangle_uvs.size(), 1u);
    ASSERT_EQ(g.triangle_normals.size(), 1u);
    expect_triangle(g.triangles[0], {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    expect_vec(g.triangle_normals[0][2], {0, 0, -1});
    EXPECT_EQ(g.triangle_uvs[0][1].x, 0.75f);
    EXPECT_EQ(g.triangle_uvs[0][1].y, 0.5f);
    EXPECT_EQ(g.triangle_uvs[0][2].y, 0.75f);
  }
}

TEST(OffLoader, DegenerateFacesAreCountedAndDropped) {
  Geometry g;
  const MeshLoadReport r =
      parse_off("OFF\n3 6 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n2 0 1\n1 0\n0\n3 0 0 0\n3 0 1 2\n", "d.off", g, 0);
  EXPECT_EQ(r.degenerate_dropped, 5u);
  EXPECT_EQ(r.triangles, 1u);
  ASSERT_EQ(g.triangles.size(), 1u);
  expect_triangle(g.triangles[0], {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
}

TEST(OffLoader, ArmadilloHasAllItsTriangles) {
  const std::string path = raylab::test::source_dir() + "/../shared/scenes/armadillo.off";
  if (!fs::exists(path)) GTEST_SKIP() << path << " is not present";
  Scene scene;
  const MeshLoadReport r = load_off(path, scene, 0);
  EXPECT_EQ(r.vertices, 26002u);
  EXPECT_EQ(r.triangles, 52000u);
  EXPECT_EQ(r.degenerate_dropped, 0u);
  ASSERT_EQ(scene.geometry.triangles.size(), 52000u);
  // The last face, read here line by line, must be the last triangle.
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  std::istringstream face(lines.back());
  int n = 0, a = 0, b = 0, c = 0;
  face >> n >> a >> b >> c;
  ASSERT_EQ(n, 3);
  auto vertex = [&](int i) {
    std::istringstream v(lines[2 + static_cast<std::size_t>(i)]);  // after "OFF" and the counts
    std::string x, y, z;
    v >> x >> y >> z;
    return Vec3{static_cast<float>(std::strtod(x.c_str(), nullptr)),
                static_cast<float>(std::strtod(y.c_str(), nullptr)),
                static_cast<float>(std::strtod(z.c_str(), nullptr))};
  };
  expect_triangle(scene.geometry.triangles.back(), vertex(a), vertex(b), vertex(c));
}

TEST(OffLoader, LoadsFromAFileAndNamesItInErrors) {
  const test::TempDir dir("off");
  const std::string good = dir.file("good.off"), bad = dir.file("bad.off");
  std::ofstream(good) << kTriangle;
  std::ofstream(bad) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n";
  Scene scene;
  EXPECT_EQ(load_off(good, scene, 0).triangles, 1u);
  const std::string message = test::thrown_message([&] { load_off(bad, scene, 0); });
  EXPECT_EQ(message.rfind(bad + ":6:7: vertex index 5 is out of range", 0), 0u) << message;
  EXPECT_THROW(load_off(dir.file("missing.off"), scene, 0), InputError);
}

// ---------------------------------------------------------------------------- bad input

TEST(OffLoader, IndexOutOfRange) {
  expect_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
               "mesh.off:6:7: ", "vertex index 3 is out of range (the file has 3 vertices)");
  expect_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3  0 -1 2\n", "mesh.off:6:6: ", "vertex index -1 is out of range");
  expect_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 x\n", "mesh.off:6:7: ", "expected vertex index (an integer)");
}

TEST(OffLoader, NonFiniteAndMissingNumbers) {
  expect_error("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n",
               "mesh.off:4:3: ", "expected vertex y (a finite number), found 'nan'");
  expect_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 inf\n3 0 1 2\n", "mesh.off:5:5: ", "expected vertex z (a finite number)");
  expect_error("OFF\n3 1 0\n-1e39 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "mesh.off:3:1: ", "out of float range");
  expect_error("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "mesh.off:4:4: ", "expected vertex z");
  expect_error("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 NaN 1\n0 1 0 0 0 1\n3 0 1 2\n",
               "mesh.off:4:9: ", "expected normal y (a finite number)");
  expect_error("STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1\n0 1 0 0 1\n3 0 1 2\n",
               "mesh.off:4:8: ", "expected texture coordinates");
}

TEST(OffLoader, TruncatedFiles) {
  // Cut short of what the counts need at the least: refused at the count.
  for (const std::size_t keep : {std::size_t{10}, std::size_t{13}, std::size_t{16}}) {
    SCOPED_TRACE(keep);
    expect_error(kTriangle.substr(0, keep), "mesh.off:2:1: ",
                 "unexpected end of file: the header announces 3 vertices, but the rest of the file has room for at "
                 "most");
  }
  // Cut later: found where the file ends. After the keyword, between vertices, inside a vertex,
  // inside the last face.
  const std::string padded = "OFF\n3 1 0\n0.0000 0.0000 0.0000\n1.0000 0.0000 0.0000\n0.0000 1.0000 0.0000\n3 0 1 2\n";
  const std::string cuts[] = {"OFF\n", padded.substr(0, padded.find("1.0000")),
                              padded.substr(0, padded.find("1.0000") + 11), kTriangle.substr(0, kTriangle.size() - 3),
                              kTriangle.substr(0, kTriangle.size() - 2)};
  for (const std::string& cut : cuts) {
    SCOPED_TRACE(cut);
    expect_error(cut, end_prefix(cut), "unexpected end of file");
  }
}

TEST(OffLoader, CountsThatDisagreeWithTheData) {
  // One face more than there are.
  expect_error("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
               "mesh.off:7:1: ", "unexpected end of file, expected a face");
  // One vertex more: the face line is read as a vertex, then there is no face.
  expect_error("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
               "mesh.off:7:1: ", "unexpected end of file, expected a face");
  // One vertex fewer cannot be told from trailing data: the third vertex line reads as an empty
  // face (dropped and counted), and the real face is ignored.
  Geometry g;
  const MeshLoadReport r = parse_off("OFF\n2 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "few.off", g, 0);
  EXPECT_EQ(r.triangles, 0u);
  EXPECT_EQ(r.degenerate_dropped, 1u);
}

TEST(OffLoader, HugeOrNegativeCountsAreRefusedBeforeAllocating) {
  expect_error("OFF\n1000000000000 1 0\n0 0 0\n", "mesh.off:2:1: ", "announces 1000000000000 vertices");
  expect_error(std::string("OFF\n3 1000000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
               "mesh.off:2:3: ", "announces 1000000000000 faces");
  expect_error("OFF\n99999999999999999999 1 0\n", "mesh.off:2:1: ", "expected vertex count (an integer)");
  expect_error("OFF\n-3 1 0\n", "mesh.off:2:1: ", "vertex count -3 is negative");
  expect_error("OFF\n3 -1 0\n", "mesh.off:2:3: ", "face count -1 is negative");
  expect_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n", "mesh.off:6:1: ", "face vertex count -3 is negative");
}

TEST(OffLoader, HeaderErrors) {
  expect_error("PLY\n", "mesh.off:1:1: ", "not an OFF file");
  expect_error("4OFF\n3 1 0\n", "mesh.off:1:1: ", "unsupported OFF variant '4OFF'");
  expect_error("OFF BINARY\n", "mesh.off:1:5: ", "binary OFF is not supported");
  expect_error("OFF\n3 1 0 7\n", "mesh.off:2:7: ", "unexpected '7' after the counts");
  expect_error("OFF\n3\n", "mesh.off:2:2: ", "expected the face count");
  expect_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3.5 0 1 2\n", "mesh.off:6:1: ", "expected face vertex count");
  expect_error("", "mesh.off:1:1: ", "unexpected end of file");
}

// Every error must carry a position `fuzz.off:line:col: `.
void parse_anything(const std::string& bytes) {
  Geometry g;
  try {
    parse_off(bytes, "fuzz.off", g, 0);
  } catch (const InputError& e) {
    const std::string prefix = "fuzz.off:" + std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": ";
    EXPECT_TRUE(e.line() > 0 && e.column() > 0 && std::string(e.what()).rfind(prefix, 0) == 0) << e.what();
  }
}

TEST(OffLoader, RandomBytesAndMutationsNeverCrash) {
  Pcg32 rng(4242);
  for (int i = 0; i < 300; ++i) {
    std::string bytes = i % 2 ? "OFF\n" : "";
    const std::uint32_t n = rng.next_u32() % 200;
    for (std::uint32_t k = 0; k < n; ++k) bytes += static_cast<char>(rng.next_u32() & 0xff);
    parse_anything(bytes);
  }
  const std::string seeds[] = {kTriangle,
                               "STCNOFF\n3 1 0\n0 0 0 0 0 1 9 9 9 1 0.5 0.5\n1 0 0 0 0 1 9 9 9 0.75 0.5\n"
                               "0 1 0 0 0 -1 9 9 9 1 0.5 0.75\n4 0 1 2 0\n"};
  // Digits and separators make mutations that still look like OFF: counts, indices and values off.
  const std::string alphabet = "0123456789 \n-.#eE+nN";
  for (int i = 0; i < 600; ++i) {
    std::string bytes = seeds[i % 2];
    const std::uint32_t flips = 1 + rng.next_u32() % 4;
    for (std::uint32_t k = 0; k < flips; ++k) {
      const std::size_t at = rng.next_u32() % bytes.size();
      bytes[at] = rng.next_u32() % 4 ? alphabet[rng.next_u32() % alphabet.size()] : static_cast<char>(rng.next_u32());
    }
    if (rng.next_u32() % 4 == 0) bytes.resize(rng.next_u32() % bytes.size());
    parse_anything(bytes);
  }
}

}  // namespace
}  // namespace raylab
