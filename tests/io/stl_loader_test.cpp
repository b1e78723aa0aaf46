// parse_stl / load_stl: ASCII and binary files written here give exactly the expected triangles
// (facet normals ignored), binary files whose header starts with "solid" are told apart by their
// size, and bad input is refused with the error at the exact line:col or byte; random or
// mutated input never crashes.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "io_test_util.h"
#include "mesh_test_util.h"
#include "parse_error_util.h"
#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/io/stl_loader.h"

namespace raylab {
namespace {

using test::expect_triangle;
using test::expect_vec;

namespace fs = std::filesystem;

// Two facets of the unit square, the second with a wrong facet normal (which must not matter).
const std::array<Triangle, 2> kSquare = {Triangle{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5f}},
                                         Triangle{{0, 0, 0}, {1, 1, 0.5f}, {0, 1, -0.25f}}};

const std::string kAscii =
    "solid square part\n"       // 1
    "  facet normal 0 0 1\n"    // 2
    "    outer loop\n"          // 3
    "      vertex 0 0 0\n"      // 4
    "      vertex 1 0 0\n"      // 5
    "      vertex 1 1 0.5\n"    // 6
    "    endloop\n"             // 7
    "  endfacet\n"              // 8
    "  facet normal 9 9 9\n"    // 9
    "    outer loop\n"          // 10
    "      vertex 0 0 0\n"      // 11
    "      vertex 1 1 0.5\n"    // 12
    "      vertex 0 1 -0.25\n"  // 13
    "    endloop\n"             // 14
    "  endfacet\n"              // 15
    "endsolid square part\n";   // 16

void put_float(std::string& out, float f) {
  auto raw = std::bit_cast<std::array<char, 4>>(f);
  if (std::endian::native == std::endian::big) std::reverse(raw.begin(), raw.end());
  out.append(raw.data(), 4);
}

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xff);
}

// A binary STL of `triangles`, with header text `header` (padded to 80 bytes) and `count` as the
// triangle count (the true count unless given).
std::string binary(const std::vector<Triangle>& triangles, const std::string& header = "binary",
                   std::int64_t count = -1) {
  std::string out = header;
  out.resize(80, '\0');
  put_u32(out, static_cast<std::uint32_t>(count < 0 ? static_cast<std::int64_t>(triangles.size()) : count));
  for (const Triangle& t : triangles) {
    for (float f : {9.f, 9.f, 9.f}) put_float(out, f);  // a wrong normal, ignored
    for (const Vec3& p : {t.p0, t.p1, t.p2}) {
      put_float(out, p.x);
      put_float(out, p.y);
      put_float(out, p.z);
    }
    out += "\x01\x02";  // attribute word, ignored
  }
  return out;
}

void expect_square(const Geometry& g) {
  ASSERT_EQ(g.triangles.size(), 2u);
  for (int t = 0; t < 2; ++t) {
    expect_triangle(g.triangles[t], kSquare[t].p0, kSquare[t].p1, kSquare[t].p2);
  }
  EXPECT_TRUE(g.triangle_normals.empty());
  EXPECT_TRUE(g.triangle_uvs.empty());
}

std::string error_of(const std::string& bytes) { return test::parse_error(parse_stl, bytes, "mesh.stl"); }

void expect_error(const std::string& bytes, const std::string& prefix, const std::string& words) {
  test::expect_message(error_of(bytes), prefix, words);
}

std::string end_prefix(const std::string& text) { return test::end_position("mesh.stl", text); }

TEST(StlLoader, AsciiFacets) {
  Geometry g;
  const MeshLoadReport r = parse_stl(kAscii, "a.stl", g, 3);
  EXPECT_EQ(r.triangles, 2u);
  EXPECT_EQ(r.vertices, 6u);
  EXPECT_EQ(r.degenerate_dropped, 0u);
  expect_square(g);
  EXPECT_EQ(g.triangle_objects[1], 3u);
}

TEST(StlLoader, BinaryFacetsEqualTheAsciiOnes) {
  for (const std::string header : {"binary", "solid but binary: the size decides"}) {
    SCOPED_TRACE(header);
    Geometry g;
    const MeshLoadReport r = parse_stl(binary({kSquare[0], kSquare[1]}, header), "b.stl", g, 0);
    EXPECT_EQ(r.triangles, 2u);
    EXPECT_EQ(r.vertices, 6u);
    expect_square(g);
  }
  // Bytes after the records are ignored when the header does not say "solid".
  Geometry g;
  parse_stl(binary({kSquare[0], kSquare[1]}) + "padding", "b.stl", g, 0);
  expect_square(g);
}

TEST(StlLoader, SeveralSolidsAndUppercaseKeywords) {
  const std::string text =
      "SOLID first\nFACET NORMAL 0 0 0\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 1 1 0.5\nENDLOOP\nENDFACET\n"
      "ENDSOLID first\n\nsolid\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 1 0.5\nvertex 0 1 -0.25\n"
      "endloop\nendfacet\nendsolid";
  Geometry g;
  parse_stl(text, "s.stl", g, 0);
  expect_square(g);
}

TEST(StlLoader, ZeroAreaFacetsAreCountedAndDropped) {
  const Triangle flat{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  Geometry g;
  MeshLoadReport r = parse_stl(binary({flat, kSquare[0], flat, kSquare[1]}), "z.stl", g, 0);
  EXPECT_EQ(r.degenerate_dropped, 2u);
  EXPECT_EQ(r.triangles, 2u);
  expect_square(g);
  // ASCII, with the "nan" normal some exporters write for such facets.
  const std::string text =
      "solid z\nfacet normal nan nan nan\nouter loop\nvertex 0 0 0\nvertex 1 1 1\nvertex 2 2 2\n"
      "endloop\nendfacet\nendsolid z\n";
  Geometry h;
  r = parse_stl(text, "z.stl", h, 0);
  EXPECT_EQ(r.degenerate_dropped, 1u);
  EXPECT_EQ(r.triangles, 0u);
  EXPECT_TRUE(h.triangles.empty());
}

TEST(StlLoader, LoadsFromAFileAndNamesItInErrors) {
  const test::TempDir dir("stl");
  const std::string good = dir.file("good.stl"), bad = dir.file("bad.stl");
  std::ofstream(good, std::ios::binary) << binary({kSquare[0], kSquare[1]});
  std::ofstream(bad, std::ios::binary) << binary({kSquare[0], kSquare[1]}, "x", 3);
  Scene scene;
  EXPECT_EQ(load_stl(good, scene, 0).triangles, 2u);
  expect_square(scene.geometry);
  const std::string message = test::thrown_message([&] { load_stl(bad, scene, 0); });
  EXPECT_EQ(message.rfind(bad + ": byte 80: unexpected end of file", 0), 0u) << message;
  EXPECT_THROW(load_stl(dir.file("missing.stl"), scene, 0), InputError);
}

// ---------------------------------------------------------------------------- bad input

TEST(StlLoader, BinaryCountIsCheckedAgainstTheFileSize) {
  const std::vector<Triangle> two = {kSquare[0], kSquare[1]};
  expect_error(binary(two, "x", 3),
               "mesh.stl: byte 80: ", "announces 3 triangles, which need 234 bytes, but the file has 184");
  expect_error(binary(two, "x", 0xffffffff), "mesh.stl: byte 80: ", "announces 4294967295 triangles");
  // Truncated inside the records.
  for (const std::size_t keep : {std::size_t{84}, std::size_t{100}, std::size_t{134}, std::size_t{183}}) {
    SCOPED_TRACE(keep);
    expect_error(binary(two).substr(0, keep), "mesh.stl: byte 80: ", "announces 2 triangles");
  }
  expect_error(std::string(10, 'x'), "mesh.stl: byte 10: ", "unexpected end of file: too short for binary STL");
  expect_error("", "mesh.stl: byte 0: ", "unexpected end of file");
}

TEST(StlLoader, NonFiniteBinaryCoordinates) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  // Second record (from byte 134), normal (12 bytes), first vertex y at +4.
  expect_error(binary({kSquare[0], Triangle{{0, nan, 0}, {1, 0, 0}, {0, 1, 0}}}),
               "mesh.stl: byte 150: ", "vertex coordinate is not a finite number");
  expect_error(binary({Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, -inf}}}), "mesh.stl: byte 128: ", "not a finite number");
}

TEST(StlLoader, TruncatedAsciiFiles) {
  for (const char* at : {"square part\n  ", "facet normal 9", "outer loop\n      vertex 0 0 0\n      vertex 1 1",
                         "endloop\n  endfacet\n"}) {
    const std::size_t pos = kAscii.rfind(at);
    ASSERT_NE(pos, std::string::npos) << at;
    const std::string cut = kAscii.substr(0, pos + std::strlen(at));
    SCOPED_TRACE(cut);
    expect_error(cut, end_prefix(cut), "unexpected end of file");
  }
}

TEST(StlLoader, AsciiErrorsAtTheirLineAndColumn) {
  auto with = [](const std::string& from, const std::string& to) {
    std::string text = kAscii;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  expect_error(with("vertex 1 0 0", "vertex 1 nan 0"), "mesh.stl:5:16: ", "found 'nan'");
  expect_error(with("vertex 1 0 0", "vertex 1 0 inf"), "mesh.stl:5:18: ", "found 'inf'");
  expect_error(with("vertex 1 0 0", "vertex 1e39 0 0"), "mesh.stl:5:14: ", "out of float range");
  expect_error(with("vertex 1 0 0", "vertex 1 0"), "mesh.stl:6:7: ", "found 'vertex'");
  expect_error(with("    endloop\n  endfacet\nendsolid", "    vertex 0 0 0\n    endloop\n  endfacet\nendsolid"),
               "mesh.stl:14:5: ", "expected 'endloop', found 'vertex'");
  expect_error(with("outer loop", "outer ring"), "mesh.stl:3:11: ", "expected 'loop', found 'ring'");
  expect_error(with("  facet normal 9 9 9", "  facet"), "mesh.stl:10:5: ", "expected 'normal', found 'outer'");
  expect_error(with("  facet normal 9", "  face normal 9"), "mesh.stl:9:3: ", "expected 'facet' or 'endsolid'");
  expect_error(kAscii + "junk\n", "mesh.stl:17:1: ", "expected 'solid', found 'junk'");
}

// Every error must carry a position: `fuzz.stl:line:col: ` or `fuzz.stl: byte N: `.
void parse_anything(const std::string& bytes) {
  Geometry g;
  try {
    parse_stl(bytes, "fuzz.stl", g, 0);
  } catch (const InputError& e) {
    const std::string message = e.what();
    const std::string at_line = "fuzz.stl:" + std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": ";
    EXPECT_TRUE((e.line() > 0 && message.rfind(at_line, 0) == 0) || message.rfind("fuzz.stl: byte ", 0) == 0)
        << message;
  }
}

TEST(StlLoader, RandomBytesAndMutationsNeverCrash) {
  Pcg32 rng(99);
  for (int i = 0; i < 300; ++i) {
    std::string bytes = i % 3 == 0 ? "solid x\n" : "";
    // A third of the buffers are binary-sized for the count they carry.
    const std::uint32_t n = i % 3 == 1 ? 84 + 50 * (rng.next_u32() % 4) : rng.next_u32() % 300;
    for (std::uint32_t k = 0; k < n; ++k) bytes += static_cast<char>(rng.next_u32() & 0xff);
    if (i % 3 == 1) {
      const std::uint32_t count = (n - 84) / 50;
      std::memcpy(bytes.data() + 80, &count, 4);
    }
    parse_anything(bytes);
  }
  const std::string seeds[] = {kAscii, binary({kSquare[0], kSquare[1]}),
                               binary({kSquare[0], kSquare[1]}, "solid but binary")};
  for (int i = 0; i < 600; ++i) {
    std::string bytes = seeds[i % 3];
    const std::uint32_t flips = 1 + rng.next_u32() % 4;
    for (std::uint32_t k = 0; k < flips; ++k) bytes[rng.next_u32() % bytes.size()] = static_cast<char>(rng.next_u32());
    if (rng.next_u32() % 4 == 0) bytes.resize(rng.next_u32() % bytes.size());
    parse_anything(bytes);
  }
}

}  // namespace
}  // namespace raylab
