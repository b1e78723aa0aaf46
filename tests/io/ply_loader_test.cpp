// parse_ply / load_ply: the same mesh written here in every encoding and property layout loads
// to exactly the same triangles; every scalar type; unknown elements and properties skipped;
// triangle strips with their winding; a real scanned mesh when present; bad input refused with
// the error at the exact line:col (text) or byte (binary), and random or mutated input never
// crashes.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "../test_paths.h"
#include "io_test_util.h"
#include "mesh_test_util.h"
#include "parse_error_util.h"
#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/io/ply_loader.h"

namespace raylab {
namespace {

using test::expect_triangle;
using test::expect_vec;

namespace fs = std::filesystem;

enum class Enc { kAscii, kLittle, kBig };
constexpr Enc kEncodings[] = {Enc::kAscii, Enc::kLittle, Enc::kBig};

const char* format_name(Enc e) {
  return e == Enc::kAscii ? "ascii" : (e == Enc::kLittle ? "binary_little_endian" : "binary_big_endian");
}

bool is_float_type(const std::string& type) {
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}

// Appends `v` as PLY type `type` in binary, in the byte order `big` asks for.
void append_binary(std::string& out, const std::string& type, double v, bool big) {
  auto put = [&](auto x) {
    auto raw = std::bit_cast<std::array<char, sizeof(x)>>(x);
    if (big != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
    out.append(raw.data(), raw.size());
  };
  if (type == "char" || type == "int8") return put(static_cast<std::int8_t>(v));
  if (type == "uchar" || type == "uint8") return put(static_cast<std::uint8_t>(v));
  if (type == "short" || type == "int16") return put(static_cast<std::int16_t>(v));
  if (type == "ushort" || type == "uint16") return put(static_cast<std::uint16_t>(v));
  if (type == "int" || type == "int32") return put(static_cast<std::int32_t>(v));
  if (type == "uint" || type == "uint32") return put(static_cast<std::uint32_t>(v));
  if (type == "float" || type == "float32") return put(static_cast<float>(v));
  if (type == "double" || type == "float64") return put(v);
  ADD_FAILURE() << "unknown type " << type;
}

// `v` as PLY type `type` in text: shortest round-trip form for floats, digits for integers.
std::string text_of(const std::string& type, double v) {
  char buf[64];
  std::to_chars_result r{};
  if (type == "float" || type == "float32") {
    r = std::to_chars(buf, buf + sizeof buf, static_cast<float>(v));
  } else if (is_float_type(type)) {
    r = std::to_chars(buf, buf + sizeof buf, v);
  } else {
    r = std::to_chars(buf, buf + sizeof buf, static_cast<std::int64_t>(v));
  }
  return std::string(buf, r.ptr);
}

// A PLY file written value by value, so that one description of a mesh gives the same file in
// each encoding.
class TestPly {
 public:
  explicit TestPly(Enc enc) : m_enc(enc) { m_header = std::string("ply\nformat ") + format_name(enc) + " 1.0\n"; }
  TestPly& header(const std::string& line) {
    m_header += line + "\n";
    return *this;
  }
  TestPly& value(const std::string& type, double v) {
    if (m_enc == Enc::kAscii) {
      m_body += text_of(type, v) + " ";
    } else {
      append_binary(m_body, type, v, m_enc == Enc::kBig);
    }
    return *this;
  }
  TestPly& values(const std::string& type, std::initializer_list<double> vs) {
    for (double v : vs) value(type, v);
    return *this;
  }
  TestPly& end_record() {
    if (m_enc == Enc::kAscii) m_body += "\n";
    return *this;
  }
  std::string str() const { return m_header + "end_header\n" + m_body; }
  // Offset of the first body byte in str().
  std::size_t body_offset() const { return m_header.size() + 11; }

 private:
  Enc m_enc;
  std::string m_header, m_body;
};

// The sample mesh: a square, its centre raised, and three faces (a triangle, the square as a quad,
// a triangle), which give four triangles.
const Vec3 kP[5] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 3}};
const Vec3 kN[5] = {{0, 0, 1}, {0.5f, -0.25f, 1}, {-0.75f, 0.5f, 0.125f}, {0, 1, 0}, {1, 0, 0}};
const Vec2 kUv[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.25f}};
const std::vector<std::vector<int>> kFaces = {{0, 1, 4}, {0, 1, 2, 3}, {2, 3, 4}};
const int kTriangles[4][3] = {{0, 1, 4}, {0, 1, 2}, {0, 2, 3}, {2, 3, 4}};

// Property layouts of the sample mesh, each reaching a different path of the reader.
enum class Layout {
  kPlain,  // float x y z [nx ny nz] [u v], list uchar int: the fast paths
  kMixed,  // mixed scalar types and skipped scalars: fixed-size records, general face path
  kListy,  // unknown lists in vertices and faces, unknown elements: variable-size records
};

std::string sample(Enc enc, Layout layout, bool normals = true, bool uvs = true) {
  TestPly f(enc);
  f.header("comment the sample mesh").header("obj_info layout " + std::to_string(static_cast<int>(layout)));
  if (layout == Layout::kListy) {
    f.header("element material 2").header("property uchar id").header("property list uchar float params");
  }
  f.header("element vertex 5");
  if (layout == Layout::kPlain) {
    f.header("property float x").header("property float y").header("property float z");
    if (normals) f.header("property float nx").header("property float ny").header("property float nz");
    if (uvs) f.header("property float u").header("property float v");
    f.header("element face 3").header("property list uchar int vertex_indices");
  } else if (layout == Layout::kMixed) {
    f.header("property double x").header("property float y").header("property short z").header("property uchar red");
    f.header("property float nx").header("property float32 ny").header("property float nz");
    f.header("property int quality").header("property double s").header("property float t");
    f.header("element face 3").header("property uchar flags").header("property list ushort uint vertex_index");
  } else {
    f.header("property float x").header("property list uchar int extra").header("property float y");
    f.header("property float z").header("property float nx").header("property float ny").header("property float nz");
    f.header("property float texture_u").header("property float texture_v");
    f.header("element face 3").header("property list int int8 neighbours");
    f.header("property list uint8 int32 vertex_indices").header("property float weight");
    f.header("element edge 2").header("property int vertex1").header("property int vertex2");
  }
  if (layout == Layout::kListy) {
    f.value("uchar", 7).value("uchar", 2).values("float", {0.5, 1.5}).end_record();
    f.value("uchar", 8).value("uchar", 0).end_record();
  }
  for (int i = 0; i < 5; ++i) {
    const Vec3 p = kP[i], n = kN[i];
    const Vec2 uv = kUv[i];
    if (layout == Layout::kPlain) {
      f.values("float", {p.x, p.y, p.z});
      if (normals) f.values("float", {n.x, n.y, n.z});
      if (uvs) f.values("float", {uv.x, uv.y});
    } else if (layout == Layout::kMixed) {
      f.value("double", p.x).value("float", p.y).value("short", p.z).value("uchar", 200);
      f.values("float", {n.x, n.y, n.z}).value("int", -5).value("double", uv.x).value("float", uv.y);
    } else {
      f.value("float", p.x).value("uchar", i % 3);
      for (int k = 0; k < i % 3; ++k) f.value("int", 100 + k);
      f.values("float", {p.y, p.z, n.x, n.y, n.z, uv.x, uv.y});
    }
    f.end_record();
  }
  for (const std::vector<int>& face : kFaces) {
    if (layout == Layout::kPlain) {
      f.value("uchar", face.size());
      for (int v : face) f.value("int", v);
    } else if (layout == Layout::kMixed) {
      f.value("uchar", 1).value("ushort", face.size());
      for (int v : face) f.value("uint", v);
    } else {
      f.value("int", 2).values("int8", {-1, 3}).value("uint8", face.size());
      for (int v : face) f.value("int32", v);
      f.value("float", 0.25);
    }
    f.end_record();
  }
  if (layout == Layout::kListy) {
    f.values("int", {0, 1}).end_record();
    f.values("int", {1, 2}).end_record();
  }
  return f.str();
}

// Checks that `g` holds exactly the sample mesh's four triangles.
void expect_sample(const Geometry& g, bool normals, bool uvs) {
  ASSERT_EQ(g.triangles.size(), 4u);
  ASSERT_EQ(g.triangle_normals.size(), normals ? 4u : 0u);
  ASSERT_EQ(g.triangle_uvs.size(), uvs ? 4u : 0u);
  for (int t = 0; t < 4; ++t) {
    SCOPED_TRACE("triangle " + std::to_string(t));
    const int* c = kTriangles[t];
    expect_triangle(g.triangles[t], kP[c[0]], kP[c[1]], kP[c[2]]);
    for (int k = 0; k < 3; ++k) {
      if (normals) expect_vec(g.triangle_normals[t][k], kN[c[k]]);
      if (uvs) {
        EXPECT_EQ(g.triangle_uvs[t][k].x, kUv[c[k]].x);
        EXPECT_EQ(g.triangle_uvs[t][k].y, kUv[c[k]].y);
      }
    }
  }
}

// The message of the InputError that parsing `bytes` must throw ("no error" if none).
std::string error_of(const std::string& bytes) { return test::parse_error(parse_ply, bytes, "mesh.ply"); }

// Expects parsing `bytes` to fail with a message that starts with `prefix` and contains `words`.
void expect_error(const std::string& bytes, const std::string& prefix, const std::string& words) {
  test::expect_message(error_of(bytes), prefix, words);
}

std::string byte_prefix(std::size_t offset) { return "mesh.ply: byte " + std::to_string(offset) + ": "; }

// The position just past the end of `text`: where a scanner reports "unexpected end of file".
std::string end_prefix(const std::string& text) { return test::end_position("mesh.ply", text); }

// A small ASCII file: the unit square as two triangles (lines 10-13 vertices, 14-15 faces).
std::string ascii_square(const std::string& vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n",
                         const std::string& faces = "3 0 1 2\n3 0 2 3\n", int vertex_count = 4, int face_count = 2) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertex_count) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(face_count) +
         "\nproperty list uchar int vertex_indices\nend_header\n" + vertices + faces;
}

// The same square in binary little-endian: 4 vertices of 12 bytes, 2 faces of 13 bytes.
TestPly binary_square(const std::vector<double>& coords = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0},
                      const std::vector<int>& faces = {0, 1, 2, 0, 2, 3}) {
  TestPly f(Enc::kLittle);
  f.header("element vertex 4").header("property float x").header("property float y").header("property float z");
  f.header("element face 2").header("property list uchar int vertex_indices");
  for (double c : coords) f.value("float", c);
  for (std::size_t i = 0; i < faces.size(); i += 3)
    f.value("uchar", 3).values("int", {double(faces[i]), double(faces[i + 1]), double(faces[i + 2])});
  return f;
}

TEST(PlyLoader, HandWrittenAsciiFile) {
  const std::string text =
      "ply\n"
      "format ascii 1.0\n"
      "comment made by hand\n"
      "obj_info nothing to see\n"
      "element vertex 4\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "element face 2\n"
      "property list uchar int vertex_indices\n"
      "end_header\n"
      "0 0 0\n"
      "1 0 0\n"
      "1 1 0.5\n"
      "0 1 0.5\n"
      "3 0 1 2\n"
      "4 0 1 2 3\n";
  Geometry g;
  test::expect_triangle_and_quad(parse_ply(text, "hand.ply", g, 7), g, 7);
}

TEST(PlyLoader, EveryEncodingAndLayoutGivesTheSameTriangles) {
  for (const Layout layout : {Layout::kPlain, Layout::kMixed, Layout::kListy}) {
    for (const Enc enc : kEncodings) {
      SCOPED_TRACE(std::string(format_name(enc)) + ", layout " + std::to_string(static_cast<int>(layout)));
      Geometry g;
      const MeshLoadReport r = parse_ply(sample(enc, layout), "sample.ply", g, 0);
      EXPECT_EQ(r.vertices, 5u);
      EXPECT_EQ(r.triangles, 4u);
      expect_sample(g, true, true);
    }
  }
}

TEST(PlyLoader, NormalsAndUvsAreOptional) {
  for (const Enc enc : kEncodings) {
    for (const bool normals : {false, true}) {
      for (const bool uvs : {false, true}) {
        SCOPED_TRACE(std::string(format_name(enc)) + (normals ? " normals" : "") + (uvs ? " uvs" : ""));
        Geometry g;
        parse_ply(sample(enc, Layout::kPlain, normals, uvs), "sample.ply", g, 0);
        expect_sample(g, normals, uvs);
      }
    }
  }
}

TEST(PlyLoader, PartialNormalsAreIgnored) {
  // nx and ny without nz are not a normal: skipped like unknown properties.
  TestPly f(Enc::kLittle);
  f.header("element vertex 3").header("property float x").header("property float y").header("property float z");
  f.header("property float nx").header("property float ny").header("property float u");
  f.header("element face 1").header("property list uchar int vertex_indices");
  for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}) f.values("float", {p.x, p.y, p.z, 9, 9, 9});
  f.value("uchar", 3).values("int", {0, 1, 2});
  Geometry g;
  EXPECT_EQ(parse_ply(f.str(), "partial.ply", g, 0).triangles, 1u);
  EXPECT_TRUE(g.triangle_normals.empty());
  EXPECT_TRUE(g.triangle_uvs.empty());
  expect_vec(g.triangles[0].p1, {1, 0, 0});
}

TEST(PlyLoader, EveryScalarTypeAndAlias) {
  const std::string types[] = {"char", "uchar", "short", "ushort", "int",   "uint",   "float",   "double",
                               "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  const Vec3 v[3] = {{0, 0, 0}, {5, 0, 0}, {0, 6, 7}};
  for (const Enc enc : kEncodings) {
    for (const std::string& type : types) {
      SCOPED_TRACE(std::string(format_name(enc)) + " " + type);
      const bool integer = !is_float_type(type);
      const std::string count_type = integer ? type : "uchar";
      const std::string index_type = integer ? type : "int";
      TestPly f(enc);
      // A skipped scalar and a skipped list of the same type check its size as well.
      f.header("element vertex 3").header("property " + type + " x").header("property " + type + " y");
      f.header("property " + type + " unused").header("property " + type + " z");
      f.header("element face 1").header("property list uchar " + type + " junk");
      f.header("property list " + count_type + " " + index_type + " vertex_indices");
      for (const Vec3 p : v) f.values(type, {p.x, p.y, 99, p.z}).end_record();
      f.value("uchar", 2).values(type, {7, 8});
      f.value(count_type, 3).values(index_type, {0, 1, 2}).end_record();
      Geometry g;
      parse_ply(f.str(), "types.ply", g, 0);
      ASSERT_EQ(g.triangles.size(), 1u);
      expect_triangle(g.triangles[0], v[0], v[1], v[2]);
    }
  }
}

TEST(PlyLoader, AlternativeNamesForIndicesAndTextureCoordinates) {
  for (const std::string& names : {std::string("s t"), std::string("texture_u texture_v"), std::string("u v")}) {
    const std::string u = names.substr(0, names.find(' ')), v = names.substr(names.find(' ') + 1);
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nproperty float " +
        u + "\nproperty float " + v +
        "\nelement face 1\nproperty list uchar int vertex_index\nend_header\n"
        "0 0 0 0.25 0.5\n1 0 0 0.75 0.5\n0 1 0 0.25 1\n3 2 1 0\n";
    SCOPED_TRACE(names);
    Geometry g;
    parse_ply(text, "names.ply", g, 0);
    ASSERT_EQ(g.triangle_uvs.size(), 1u);
    expect_vec(g.triangles[0].p0, {0, 1, 0});
    EXPECT_EQ(g.triangle_uvs[0][0].x, 0.25f);
    EXPECT_EQ(g.triangle_uvs[0][0].y, 1.f);
    EXPECT_EQ(g.triangle_uvs[0][1].x, 0.75f);
    EXPECT_EQ(g.triangle_uvs[0][2].y, 0.5f);
  }
}

TEST(PlyLoader, DegenerateFacesAreCountedAndDropped) {
  // A triangle with a repeated corner, one of collinear corners, a two-corner face, then a good one.
  Geometry g;
  const MeshLoadReport r = parse_ply(
      ascii_square("0 0 0\n1 0 0\n1 1 0\n2 0 0\n", "3 0 1 1\n3 0 1 3\n2 0 1\n3 0 1 2\n", 4, 4), "d.ply", g, 0);
  EXPECT_EQ(r.degenerate_dropped, 3u);
  EXPECT_EQ(r.triangles, 1u);
  ASSERT_EQ(g.triangles.size(), 1u);
  expect_vec(g.triangles[0].p2, {1, 1, 0});
}

TEST(PlyLoader, AppendsToExistingGeometry) {
  Geometry g;
  parse_ply(sample(Enc::kLittle, Layout::kPlain, false, false), "a.ply", g, 3);
  parse_ply(sample(Enc::kAscii, Layout::kPlain, false, false), "b.ply", g, 4);
  ASSERT_EQ(g.triangles.size(), 8u);
  EXPECT_EQ(g.triangle_objects[3], 3u);
  EXPECT_EQ(g.triangle_objects[4], 4u);
  expect_vec(g.triangles[4].p2, kP[4]);
}

// A strip element over a zig-zag of vertices in the plane z = 0: vertices 2k at (k, 0), 2k + 1 at
// (k, 1). Every triangle of a correctly wound strip then faces -z.
std::string strip_file(Enc enc, const std::vector<std::vector<int>>& records) {
  TestPly f(enc);
  f.header("element vertex 12").header("property float x").header("property float y").header("property float z");
  f.header("element tristrips " + std::to_string(records.size())).header("property list int int vertex_indices");
  for (int i = 0; i < 12; ++i) f.values("float", {double(i / 2), double(i % 2), 0}).end_record();
  for (const std::vector<int>& r : records) {
    f.value("int", r.size());
    for (int v : r) f.value("int", v);
    f.end_record();
  }
  return f.str();
}

Vec3 zigzag(int i) { return {float(i / 2), float(i % 2), 0}; }

TEST(PlyLoader, TriangleStripsRestartAndAlternateTheirWinding) {
  // One record with a restart, then a second record (a new strip) with a repeated vertex, whose two
  // zero-area triangles are dropped.
  const std::vector<std::vector<int>> records = {{0, 1, 2, 3, 4, 5, -1, 6, 7, 8}, {8, 9, 10, 10, 11}};
  const int want[][3] = {{0, 1, 2}, {2, 1, 3}, {2, 3, 4}, {4, 3, 5}, {6, 7, 8}, {8, 9, 10}};
  for (const Enc enc : kEncodings) {
    SCOPED_TRACE(format_name(enc));
    Geometry g;
    const MeshLoadReport r = parse_ply(strip_file(enc, records), "strips.ply", g, 0);
    EXPECT_EQ(r.triangles, 6u);
    EXPECT_EQ(r.degenerate_dropped, 2u);
    ASSERT_EQ(g.triangles.size(), 6u);
    for (int t = 0; t < 6; ++t) {
      SCOPED_TRACE("triangle " + std::to_string(t));
      expect_triangle(g.triangles[t], zigzag(want[t][0]), zigzag(want[t][1]), zigzag(want[t][2]));
      EXPECT_LT(triangle_normal(g.triangles[t]).z, 0.f);
    }
  }
}

TEST(PlyLoader, StripIndexBelowMinusOneIsAnError) {
  TestPly f(Enc::kLittle);
  f.header("element vertex 3").header("property float x").header("property float y").header("property float z");
  f.header("element tristrips 1").header("property list int int vertex_indices");
  f.values("float", {0, 0, 0, 1, 0, 0, 0, 1, 0}).value("int", 4).values("int", {0, 1, -2, 2});
  expect_error(f.str(), byte_prefix(f.body_offset() + 36 + 4 + 8), "vertex index -2 is out of range");
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n4 0 1 -2 2\n";
  expect_error(text, "mesh.ply:13:7: ", "vertex index -2 is out of range [-1, 2]");
}

TEST(PlyLoader, IgeaStripsExpandToTheTrianglesTheyImply) {
  const std::string path = raylab::test::source_dir() + "/../shared/scenes/igea.ply";
  if (!fs::exists(path)) GTEST_SKIP() << path << " is not present";
  if (std::endian::native != std::endian::little) GTEST_SKIP() << "the check below reads the file as little-endian";
  // Read the file independently: the header is known (float x y z, one int/int strip list).
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t body = bytes.find("end_header\n") + 11;
  ASSERT_NE(bytes.find("element tristrips 1\nproperty list int int vertex_indices\nend_header"), std::string::npos);
  const std::size_t vertex_count = std::stoul(bytes.substr(bytes.find("element vertex ") + 15));
  std::vector<Vec3> v(vertex_count);
  std::memcpy(v.data(), bytes.data() + body, 12 * vertex_count);
  std::int32_t n = 0;
  std::memcpy(&n, bytes.data() + body + 12 * vertex_count, 4);
  std::vector<std::int32_t> idx(static_cast<std::size_t>(n));
  std::memcpy(idx.data(), bytes.data() + body + 12 * vertex_count + 4, 4 * idx.size());

  // Each run between restarts of length m implies m - 2 triangles.
  std::size_t implied = 0, run = 0;
  for (const std::int32_t i : idx) {
    if (i == -1) {
      implied += run >= 2 ? run - 2 : 0;
      run = 0;
    } else {
      ++run;
    }
  }
  implied += run >= 2 ? run - 2 : 0;
  // The triangles themselves: the k-th of a run is (k, k+1, k+2) with its first two corners
  // swapped when k is odd; zero-area ones are dropped.
  std::vector<Triangle> want;
  std::vector<std::int32_t> strip;
  auto flush = [&] {
    for (std::size_t k = 0; k + 2 < strip.size(); ++k) {
      const Vec3 a = v[strip[k + (k % 2)]], b = v[strip[k + 1 - (k % 2)]], c = v[strip[k + 2]];
      const Vec3 normal = cross(b - a, c - a);
      if (dot(normal, normal) > 0.f) want.push_back({a, b, c});
    }
    strip.clear();
  };
  for (const std::int32_t i : idx) {
    if (i == -1) {
      flush();
    } else {
      strip.push_back(i);
    }
  }
  flush();

  Scene scene;
  const MeshLoadReport r = load_ply(path, scene, 0);
  EXPECT_EQ(r.vertices, vertex_count);
  EXPECT_EQ(r.triangles + r.degenerate_dropped, implied);
  EXPECT_GT(implied, 260000u);
  EXPECT_LT(implied, 280000u);
  ASSERT_EQ(scene.geometry.triangles.size(), want.size());
  EXPECT_EQ(r.triangles, want.size());
  for (std::size_t t = 0; t < want.size(); ++t) {
    const Triangle& got = scene.geometry.triangles[t];
    ASSERT_TRUE(got.p0 == want[t].p0 && got.p1 == want[t].p1 && got.p2 == want[t].p2) << "triangle " << t;
  }
}

TEST(PlyLoader, LoadsFromAFileAndNamesItInErrors) {
  const test::TempDir dir("ply");
  const std::string good = dir.file("good.ply"), bad = dir.file("bad.ply");
  std::ofstream(good, std::ios::binary) << sample(Enc::kBig, Layout::kMixed);
  std::ofstream(bad, std::ios::binary) << ascii_square("0 0 0\n1 0 0\n1 1 0\n0 1 0\n", "3 0 1 2\n3 0 2 4\n");
  Scene scene;
  EXPECT_EQ(load_ply(good, scene, 0).triangles, 4u);
  expect_sample(scene.geometry, true, true);
  const std::string message = test::thrown_message([&] { load_ply(bad, scene, 0); });
  EXPECT_EQ(message.rfind(bad + ":15:7: ", 0), 0u) << message;
  EXPECT_THROW(load_ply(dir.file("missing.ply"), scene, 0), InputError);
}

// ---------------------------------------------------------------------------- bad input

TEST(PlyLoader, IndexOutOfRangeInText) {
  expect_error(ascii_square("0 0 0\n1 0 0\n1 1 0\n0 1 0\n", "3 0 1 2\n3 0 2 4\n"),
               "mesh.ply:15:7: ", "vertex index 4 is out of range [0, 3]");
  expect_error(ascii_square("0 0 0\n1 0 0\n1 1 0\n0 1 0\n", "3 0 -1 2\n3 0 2 3\n"),
               "mesh.ply:14:5: ", "vertex index -1 is out of range");
}

TEST(PlyLoader, IndexOutOfRangeInBinary) {
  // Fast path (uchar/int list), second face, third index.
  TestPly past = binary_square({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {0, 1, 2, 0, 2, 4});
  expect_error(past.str(), byte_prefix(past.body_offset() + 48 + 13 + 1 + 8), "vertex index 4 is out of range");
  TestPly negative = binary_square({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {0, -7, 2, 0, 2, 3});
  expect_error(negative.str(), byte_prefix(negative.body_offset() + 48 + 1 + 4), "vertex index -7 is out of range");
  // General path (a scalar before the list), big-endian, short indices.
  TestPly f(Enc::kBig);
  f.header("element vertex 3").header("property float x").header("property float y").header("property float z");
  f.header("element face 1").header("property uchar flags").header("property list uchar short vertex_indices");
  f.values("float", {0, 0, 0, 1, 0, 0, 0, 1, 0}).value("uchar", 0).value("uchar", 3).values("short", {0, -3, 1});
  expect_error(f.str(), byte_prefix(f.body_offset() + 36 + 2 + 2), "vertex index -3 is out of range");
}

TEST(PlyLoader, NonFiniteNumbersInText) {
  expect_error(ascii_square("0 0 0\n1 nan 0\n1 1 0\n0 1 0\n"),
               "mesh.ply:11:3: ", "expected vertex y (a finite number)");
  expect_error(ascii_square("0 0 0\n1 0 0\n1 1 -inf\n0 1 0\n"),
               "mesh.ply:12:5: ", "expected vertex z (a finite number)");
  expect_error(ascii_square("0 0 0\n1 0 0\n1 1 0\n1e39 1 0\n"), "mesh.ply:13:1: ", "out of float range");
  expect_error(ascii_square("0 0 0\n1 0 0\n1 1 0\n0 1 zero\n"), "mesh.ply:13:5: ", "found 'zero'");
}

TEST(PlyLoader, NonFiniteNumbersInBinary) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  TestPly y = binary_square({0, 0, 0, 1, 0, 0, 1, nan, 0, 0, 1, 0});
  expect_error(y.str(), byte_prefix(y.body_offset() + 24 + 4), "vertex y is not a finite number");
  TestPly z = binary_square({0, 0, 0, 1, 0, -inf, 1, 1, 0, 0, 1, 0});
  expect_error(z.str(), byte_prefix(z.body_offset() + 12 + 8), "vertex z is not a finite number");
  // Non-finite normals (infinite once a float), on the general vertex path.
  for (const double bad : {1e300, nan}) {
    TestPly f(Enc::kBig);
    f.header("element vertex 2").header("property double x").header("property double y").header("property double z");
    f.header("property float nx").header("property float ny").header("property float nz");
    f.values("double", {0, 0, 0}).values("float", {0, 0, 1});
    f.values("double", {1, 2, 3}).values("float", {0, bad, 1});
    f.header("element face 0").header("property list uchar int vertex_indices");
    expect_error(f.str(), byte_prefix(f.body_offset() + 36 + 24 + 4), "vertex ny is not a finite number");
  }
  // A double too large for a float.
  TestPly f(Enc::kLittle);
  f.header("element vertex 1").header("property double x").header("property double y").header("property double z");
  f.values("double", {0, -1e300, 0});
  expect_error(f.str(), byte_prefix(f.body_offset() + 8), "vertex y is not a finite number");
}

TEST(PlyLoader, TruncatedBinaryFiles) {
  const TestPly f = binary_square();
  const std::string full = f.str();
  const std::size_t body = f.body_offset();
  ASSERT_EQ(full.size(), body + 48 + 26);
  // Fixed-size records missing are found from the header, before anything is read; a list cut
  // short, where it ends.
  struct Cut {
    std::size_t keep;  // bytes of body kept
    std::string prefix, words;
  };
  const std::string vertex_count = "mesh.ply:3:16: ", face_count = "mesh.ply:7:14: ";
  const Cut cuts[] = {
      {0, vertex_count, "unexpected end of file: element 'vertex' announces 4 records of at least 12 bytes"},
      {5, vertex_count, "room for at most 0"},
      {47, vertex_count, "room for at most 3"},
      {48, face_count, "unexpected end of file: element 'face' announces 2 records of at least 1 bytes"},
      {49, face_count, "room for at most 1"},
      {50, byte_prefix(body + 49), "unexpected end of file in element 'face' (record 1 of 2)"},
      {48 + 13 + 7, byte_prefix(body + 48 + 14), "unexpected end of file in element 'face' (record 2 of 2)"},
      {48 + 25, byte_prefix(body + 48 + 14), "unexpected end of file in element 'face' (record 2 of 2)"},
  };
  for (const Cut& c : cuts) {
    SCOPED_TRACE("keeping " + std::to_string(c.keep) + " body bytes");
    expect_error(full.substr(0, body + c.keep), c.prefix, c.words);
  }
  // Trailing data after the last element is fine.
  Geometry g;
  EXPECT_EQ(parse_ply(full + "trailing bytes", "mesh.ply", g, 0).triangles, 2u);
}

TEST(PlyLoader, TruncatedTextFiles) {
  // Values written long, so that the counts fit what is left when the file is cut in the body.
  const std::string full =
      ascii_square("0.0000 0.0000 0.0000\n1.0000 0.0000 0.0000\n1.0000 1.0000 0.0000\n0.0000 1.0000 0.0000\n");
  // Cut in the header, at its end, inside a vertex, between vertices, inside a face, before the
  // last index: found where the file ends.
  for (const std::size_t keep : {full.find("property float y"), full.find("end_header"), full.find("1.0000") + 11,
                                 full.find("1.0000 1.0000"), full.size() - 3, full.size() - 2}) {
    const std::string cut = full.substr(0, keep);
    SCOPED_TRACE(cut);
    expect_error(cut, end_prefix(cut), "unexpected end of file");
  }
  // Cut so short that the records cannot fit: refused at the count, before reading them.
  expect_error(full.substr(0, full.find("1.0000")), "mesh.ply:3:16: ",
               "unexpected end of file: element 'vertex' announces 4 records of at least 6 bytes (as text), but the "
               "rest of the file has room for at most 3");
}

TEST(PlyLoader, CountsThatDisagreeWithTheData) {
  // More faces announced than present: the end of the file comes first.
  const std::string more_faces = ascii_square("0 0 0\n1 0 0\n1 1 0\n0 1 0\n", "3 0 1 2\n3 0 2 3\n", 4, 3);
  expect_error(more_faces, "mesh.ply:16:1: ", "unexpected end of file");
  // More vertices announced than present, and no faces.
  const std::string more_vertices = ascii_square("0.5 0 0\n1.5 0 0\n1.5 1 0\n0.5 1 0\n", "", 5, 0);
  expect_error(more_vertices, "mesh.ply:14:1: ", "unexpected end of file, expected a vertex property value");
  // A binary list longer than the data left.
  TestPly f = binary_square();
  std::string bytes = f.str();
  bytes[f.body_offset() + 48 + 13] = 9;  // the second face now claims 9 indices
  expect_error(bytes, byte_prefix(f.body_offset() + 48 + 14), "unexpected end of file in element 'face'");
}

TEST(PlyLoader, HugeCountsAreRefusedBeforeAllocating) {
  const std::string counts[] = {"1000000000000", "18446744073709551615"};
  for (const std::string& count : counts) {
    SCOPED_TRACE(count);
    for (const Enc enc : kEncodings) {
      TestPly vertices(enc);
      vertices.header("element vertex " + count).header("property float x").header("property float y");
      vertices.header("property float z").values("float", {0, 0, 0});
      expect_error(vertices.str(), "mesh.ply:3:16: ", "announces " + count + " records");
      TestPly faces(enc);
      faces.header("element vertex 1").header("property float x").header("property float y").header("property float z");
      faces.header("element face " + count).header("property list uchar int vertex_indices").values("float", {0, 0, 0});
      expect_error(faces.str(), "mesh.ply:7:14: ", "announces " + count + " records");
    }
  }
  expect_error("ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\nend_header\n",
               "mesh.ply:3:16: ", "expected an element count");
}

TEST(PlyLoader, HeaderErrors) {
  const std::string fmt = "ply\nformat binary_little_endian 1.0\n";
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  struct Case {
    std::string text, prefix, words;
  };
  const Case cases[] = {
      {"", "mesh.ply:1:1: ", "not a PLY file"},
      {"solid cube\n", "mesh.ply:1:1: ", "not a PLY file"},
      {"ply\nelement vertex 1\nend_header\n", "mesh.ply:3:1: ", "no 'format' line"},
      {"ply\nformat binary_middle_endian 1.0\n", "mesh.ply:2:8: ", "unknown PLY format"},
      {"ply\nformat ascii 2.0\n", "mesh.ply:2:14: ", "unsupported PLY version"},
      {fmt + "property float x\n", "mesh.ply:3:1: ", "a property before any element"},
      {fmt + "element vertex 1\nproperty real x\n", "mesh.ply:4:10: ", "unknown PLY type 'real'"},
      {fmt + "element vertex 1\nproperty list float int x\n",
       "mesh.ply:4:15: ", "a list length must have an integer type"},
      {fmt + "element vertex 1\nproperty float\n", "mesh.ply:4:15: ", "expected a property name"},
      {fmt + "element vertex 1\nproperty float x y\n", "mesh.ply:4:18: ", "unexpected 'y'"},
      // A line that starts with no keyword is skipped; the missing end_header then names it.
      {fmt + "vertex 1\n", "mesh.ply:4:1: ",
       "unexpected end of file, expected 'end_header' (1 header line starting with no PLY keyword skipped, "
       "the first 'vertex 1' at line 3)"},
      {fmt + "element vertex -1\n", "mesh.ply:3:16: ", "expected an element count"},
      {fmt + "element vertex\n", "mesh.ply:3:15: ", "expected an element count"},
      {fmt + "element vertex 3 extra\n", "mesh.ply:3:18: ", "unexpected 'extra'"},
      {fmt + "element vertex 1\n" + xyz, "mesh.ply:7:1: ", "unexpected end of file, expected 'end_header'"},
      {fmt + "element vertex 0\nproperty float x\nproperty float y\nend_header\n",
       "mesh.ply:3:16: ", "needs properties x, y and z"},
      {fmt + "element vertex 0\nproperty list uchar float x\nproperty float y\nproperty float z\nend_header\n",
       "mesh.ply:4:10: ", "must be a scalar"},
      {fmt + "element face 1\nproperty list uchar int vertex_indices\nelement vertex 0\n" + xyz + "end_header\n\x03",
       "mesh.ply:3:14: ", "element 'face' comes before element 'vertex'"},
      {fmt + "element vertex 0\n" + xyz + "element face 0\nproperty list uchar float vertex_indices\nend_header\n",
       "mesh.ply:8:10: ", "must list integers"},
      {fmt + "element vertex 0\n" + xyz + "element face 0\nproperty int vertex_indices\nend_header\n",
       "mesh.ply:8:10: ", "must be a list"},
      {fmt + "element vertex 0\n" + xyz + "element face 0\nproperty int flags\nend_header\n",
       "mesh.ply:7:14: ", "has no 'vertex_indices' list"},
      {fmt + "element vertex 0\n" + xyz + "element vertex 0\n" + xyz + "end_header\n",
       "mesh.ply:7:16: ", "a second 'vertex' element"},
      {fmt + "element vertex 0\n" + xyz + "end_header junk\n", "mesh.ply:7:12: ", "unexpected 'junk'"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    expect_error(c.text, c.prefix, c.words);
  }
}

TEST(PlyLoader, HeaderLinesWithNoKeywordAreSkippedWithAWarning) {
  // Exporters write lines such as these; obj_info is a known convention, skipped silently.
  const std::string text =
      "ply\n"
      "format ascii 1.0\n"
      "Created by Blender 2.79 - www.blender.org\n"
      "obj_info scanned 2003\n"
      "element vertex 4\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "element face 2\n"
      "property list uchar int vertex_indices\n"
      "  exported\tby hand\n"
      "end_header\n"
      "0 0 0\n1 0 0\n1 1 0.5\n0 1 0.5\n"
      "3 0 1 2\n4 0 1 2 3\n";
  const test::TempDir dir("ply");
  const std::string path = test::write_text(dir.path() / "blender.ply", text);
  Scene scene;
  test::expect_triangle_and_quad(load_ply(path, scene, 2), scene.geometry, 2);
  ASSERT_EQ(scene.warnings.size(), 2u);
  EXPECT_EQ(
      scene.warnings[0],
      path + ":3:1: header line 'Created by Blender 2.79 - www.blender.or...' starts with no PLY keyword; skipped");
  EXPECT_EQ(scene.warnings[1], path + ":11:3: header line 'exported?by hand' starts with no PLY keyword; skipped")
      << "the line is shown from its first word to its last, control bytes as '?'";
  // parse_ply reads the same triangles; it has no scene to warn in.
  Geometry g;
  test::expect_triangle_and_quad(parse_ply(text, "blender.ply", g, 2), g, 2);
}

TEST(PlyLoader, ManySkippedHeaderLinesAreCountedNotListed) {
  std::string lines;
  for (int i = 0; i < 8; ++i) lines += "note " + std::to_string(i) + "\n";
  const std::string text = "ply\nformat ascii 1.0\n" + lines +
                           "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const test::TempDir dir("ply");
  const std::string path = test::write_text(dir.path() / "notes.ply", text);
  Scene scene;
  EXPECT_EQ(load_ply(path, scene, 0).triangles, 1u);
  ASSERT_EQ(scene.warnings.size(), 6u);
  EXPECT_EQ(scene.warnings[4], path + ":7:1: header line 'note 4' starts with no PLY keyword; skipped");
  EXPECT_EQ(scene.warnings[5], path + ": 3 more such header lines skipped");
}

TEST(PlyLoader, APropertyAfterASkippedLineIsRefused) {
  // "elemnt" is skipped; its property must not become a fourth property of the vertices.
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "elemnt face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_error(text, "mesh.ply:8:1: ",
               "a property after the skipped header line 'elemnt face 1' (line 7), which starts with no PLY "
               "keyword: is it a misspelt 'element'?");
  // Still refused from a file, with the file named.
  const test::TempDir dir("ply");
  const std::string path = test::write_text(dir.path() / "typo.ply", text);
  Scene scene;
  const std::string message = test::thrown_message([&] { load_ply(path, scene, 0); });
  EXPECT_EQ(message.rfind(path + ":8:1: ", 0), 0u) << message;
}

TEST(PlyLoader, CorruptElementLineInAFileIsStillRefused) {
  const test::TempDir dir("ply");
  const std::string path = test::write_text(
      dir.path() / "corrupt.ply",
      "ply\nformat ascii 1.0\ncomment fine\nelement vertex 4x\nproperty float x\nend_header\n0\n1\n2\n3\n");
  Scene scene;
  const std::string message = test::thrown_message([&] { load_ply(path, scene, 0); });
  test::expect_message(message, path + ":4:16: ", "expected an element count (a non-negative integer), found '4x'");
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(PlyLoader, NegativeListLengthInBinary) {
  TestPly f(Enc::kLittle);
  f.header("element vertex 3").header("property float x").header("property float y").header("property float z");
  f.header("element face 1").header("property list char int vertex_indices");
  f.values("float", {0, 0, 0, 1, 0, 0, 0, 1, 0}).value("char", -3).values("int", {0, 1, 2});
  expect_error(f.str(), byte_prefix(f.body_offset() + 36), "negative list length -3");
}

// Every error must carry a position: `fuzz.ply:line:col: ` or `fuzz.ply: byte N: `.
void expect_positioned(const InputError& e) {
  const std::string message = e.what();
  const bool at_line =
      e.line() > 0 && e.column() > 0 &&
      message.rfind("fuzz.ply:" + std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": ", 0) == 0;
  const bool at_byte = message.rfind("fuzz.ply: byte ", 0) == 0;
  EXPECT_TRUE(at_line || at_byte) << message;
}

// Parses `bytes`: success or a positioned InputError are the only acceptable outcomes (any other
// exception fails the test through gtest; a crash ends it).
void parse_anything(const std::string& bytes) {
  Geometry g;
  try {
    parse_ply(bytes, "fuzz.ply", g, 0);
  } catch (const InputError& e) {
    expect_positioned(e);
  }
}

TEST(PlyLoader, RandomBytesNeverCrash) {
  Pcg32 rng(20240611);
  const std::string headers[] = {"", "ply\nformat binary_little_endian 1.0\nelement vertex 3\n",
                                 sample(Enc::kBig, Layout::kListy).substr(0, 400)};
  for (int i = 0; i < 300; ++i) {
    std::string bytes = headers[i % 3];
    if (i % 3 == 2) bytes = bytes.substr(0, bytes.find("end_header") + 11);
    const std::uint32_t n = rng.next_u32() % 300;
    for (std::uint32_t k = 0; k < n; ++k) bytes += static_cast<char>(rng.next_u32() & 0xff);
    parse_anything(bytes);
  }
}

TEST(PlyLoader, MutatedFilesNeverCrash) {
  Pcg32 rng(77);
  std::vector<std::string> seeds;
  for (const Enc enc : kEncodings) {
    for (const Layout layout : {Layout::kPlain, Layout::kMixed, Layout::kListy}) seeds.push_back(sample(enc, layout));
    seeds.push_back(strip_file(enc, {{0, 1, 2, 3, -1, 4, 5, 6}, {7, 8, 9}}));
  }
  int failures = 0;
  for (int i = 0; i < 600; ++i) {
    std::string bytes = seeds[i % seeds.size()];
    const std::uint32_t flips = 1 + rng.next_u32() % 6;
    for (std::uint32_t k = 0; k < flips; ++k) {
      const std::size_t at = rng.next_u32() % bytes.size();
      // Half the mutations are small (off by one, as a count or index gone wrong), half random.
      bytes[at] = rng.next_u32() % 2 ? static_cast<char>(bytes[at] + 1) : static_cast<char>(rng.next_u32());
    }
    if (rng.next_u32() % 4 == 0) bytes.resize(rng.next_u32() % bytes.size());
    Geometry g;
    try {
      parse_ply(bytes, "fuzz.ply", g, 0);
    } catch (const InputError& e) {
      expect_positioned(e);
      ++failures;
    }
  }
  // Most mutations must be caught, but not all: some only change a coordinate.
  EXPECT_GT(failures, 100);
  EXPECT_LT(failures, 600);
}

}  // namespace
}  // namespace raylab
