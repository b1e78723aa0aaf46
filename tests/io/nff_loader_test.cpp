// parse_nff / load_nff: every entity on small texts, the seven SPD reference files against counts
// taken from their text independently of the parser, and malformed input located at the exact
// line and column.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <sstream>
#include <string>

#include "../test_paths.h"
#include "io_test_util.h"
#include "mesh_test_util.h"
#include "parse_error_util.h"
#include "raylab/core/error.h"
#include "raylab/io/nff_loader.h"
#include "raylab/io/read_file.h"

namespace raylab {
namespace {

using test::expect_vec;

namespace fs = std::filesystem;

const std::string kSpdDir = raylab::test::source_dir() + "/../shared/spd-reference/";

// A minimal valid view entity, for texts that need one.
constexpr const char* kView = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.5\nresolution 320 200\n";

// Parses `text` into `scene` as file "mem.nff" and finishes the builder.
MeshLoadReport parse(const std::string& text, Scene& scene) {
  NffSceneBuilder builder(scene);
  parse_nff(text, "mem.nff", builder);
  return builder.finish();
}

// Parses `text`, which must fail with an InputError at `line`:`col` whose message contains
// `needle`.
void expect_error(const std::string& text, int line, int col, const std::string& needle) {
  Scene scene;
  try {
    parse(text, scene);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    const std::string prefix = "mem.nff:" + std::to_string(line) + ":" + std::to_string(col) + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << "want " << prefix << "\ngot  " << e.what();
    EXPECT_EQ(e.line(), line);
    EXPECT_EQ(e.column(), col);
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

// Expects `m` to hold the values of the fill line "f red green blue Kd Ks Shine T index_of_refraction".
void expect_fill(const Material& m, Vec3 color, float kd, float ks, float shine, float t, float ior) {
  expect_vec(m.color, color);
  EXPECT_EQ(m.kd, kd);
  EXPECT_EQ(m.ks, ks);
  EXPECT_EQ(m.shininess, shine);
  EXPECT_EQ(m.transmittance, t);
  EXPECT_EQ(m.ior, ior);
}

float triangle_area(const Triangle& t) { return 0.5f * length(triangle_normal(t)); }

TEST(NffLoader, ReadsEveryEntity) {
  const std::string text = std::string("# a comment line\n") + kView +
                           "b 0.1 0.2 0.3\n"
                           "l 1 2 3\n"
                           "l 4 5 6 0.5 0.25 1   # coloured\n"
                           "s -1 -2 -3 0.5\n"  // before any fill: the white matte default
                           "f 0.9 0.8 0.7 0.6 0.5 30 0.4 1.5\n"
                           "s 1 2 3 4\n"
                           "c\n0 0 0 1\n0 2 0 0.25\n"
                           "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                           "pp 3\n0 0 1 0 0 1\n1 0 1 0 0 1\n0 1 1 0 0 1\n";
  Scene scene;
  const MeshLoadReport report = parse(text, scene);

  expect_vec(scene.camera.from, {0.f, 0.f, 5.f});
  expect_vec(scene.camera.at, {0.f, 0.f, 0.f});
  expect_vec(scene.camera.up, {0.f, 1.f, 0.f});
  EXPECT_EQ(scene.camera.vfov_degrees, 40.f);
  EXPECT_EQ(scene.camera.hither, 0.5f);
  EXPECT_EQ(scene.camera.fov_span, CameraSpec::FovSpan::kPixelCentres);
  EXPECT_EQ(scene.settings.width, 320);
  EXPECT_EQ(scene.settings.height, 200);
  expect_vec(scene.settings.background, {0.1f, 0.2f, 0.3f});

  ASSERT_EQ(scene.lights.size(), 2u);
  expect_vec(scene.lights[0].position, {1.f, 2.f, 3.f});
  const float share = 1.f / std::sqrt(2.f);  // the builder's share for a light without colour
  expect_vec(scene.lights[0].intensity, {share, share, share});
  expect_vec(scene.lights[1].position, {4.f, 5.f, 6.f});
  expect_vec(scene.lights[1].intensity, {0.5f, 0.25f, 1.f});

  const Geometry& g = scene.geometry;
  ASSERT_EQ(g.spheres.size(), 2u);
  expect_vec(g.spheres[0].center, {-1.f, -2.f, -3.f});
  EXPECT_EQ(g.spheres[0].radius, 0.5f);
  expect_vec(g.spheres[1].center, {1.f, 2.f, 3.f});
  EXPECT_EQ(g.spheres[1].radius, 4.f);
  ASSERT_EQ(g.cylinders.size(), 1u);
  expect_vec(g.cylinders[0].base, {0.f, 0.f, 0.f});
  EXPECT_EQ(g.cylinders[0].base_radius, 1.f);
  expect_vec(g.cylinders[0].apex, {0.f, 2.f, 0.f});
  EXPECT_EQ(g.cylinders[0].apex_radius, 0.25f);
  ASSERT_EQ(g.triangles.size(), 3u);  // the square gives 2, the patch 1
  EXPECT_EQ(report.triangles, 3u);
  EXPECT_EQ(report.degenerate_dropped, 0u);
  EXPECT_FLOAT_EQ(triangle_area(g.triangles[0]) + triangle_area(g.triangles[1]), 1.f);
  ASSERT_EQ(g.triangle_normals.size(), 3u);
  expect_vec(g.triangle_normals[2][1], {0.f, 0.f, 1.f});
  expect_vec(g.triangle_normals[0][0], {0.f, 0.f, 0.f});  // the `p` square has none

  // The first sphere has the default fill, everything after `f` the one given.
  ASSERT_EQ(scene.materials.size(), 2u);
  const Material& def = scene.material_of(g.triangles.size());  // global id of the first sphere
  expect_vec(def.color, {1.f, 1.f, 1.f});
  EXPECT_EQ(def.kd, 1.f);
  const Material& m = scene.materials[scene.objects[g.sphere_objects[1]].material];
  expect_fill(m, {0.9f, 0.8f, 0.7f}, 0.6f, 0.5f, 30.f, 0.4f, 1.5f);
  EXPECT_EQ(m.reflectivity, 0.5f);
  EXPECT_EQ(g.cylinder_objects[0], g.sphere_objects[1]);
  EXPECT_EQ(g.triangle_objects[2], g.sphere_objects[1]);
}

TEST(NffLoader, EntitiesAreTokensNotLines) {
  // Traditional layout puts a cone on three lines; any whitespace must do. CRLF too.
  Scene scene;
  parse("c 0 0 0 1 0 1 0 0.5 s\r\n1 1 1\r\n2\r\nl 1 2 3\r\nl 1 2 3 # no colour\r\n", scene);
  ASSERT_EQ(scene.geometry.cylinders.size(), 1u);
  EXPECT_EQ(scene.geometry.cylinders[0].apex_radius, 0.5f);
  ASSERT_EQ(scene.geometry.spheres.size(), 1u);
  EXPECT_EQ(scene.geometry.spheres[0].radius, 2.f);
  ASSERT_EQ(scene.lights.size(), 2u);
  const float share = 1.f / std::sqrt(2.f);
  expect_vec(scene.lights[0].intensity, {share, share, share});
  expect_vec(scene.lights[1].intensity, {share, share, share});
}

TEST(NffLoader, NonConvexPolygonIsEarClipped) {
  // An L of area 3: a fan from the first corner would cover the notch.
  Scene scene;
  const MeshLoadReport r = parse("p 6\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n", scene);
  EXPECT_EQ(r.triangles, 4u);
  EXPECT_EQ(r.degenerate_dropped, 0u);
  float area = 0.f;
  for (const Triangle& t : scene.geometry.triangles) area += triangle_area(t);
  EXPECT_FLOAT_EQ(area, 3.f);
}

TEST(NffLoader, ZeroAreaPolygonsAreDroppedAndCounted) {
  Scene scene;
  const MeshLoadReport r = parse("p 3\n0 0 0\n1 0 0\n2 0 0\np 3\n0 0 0\n1 0 0\n0 1 0\n", scene);
  EXPECT_EQ(r.triangles, 1u);
  EXPECT_EQ(r.degenerate_dropped, 1u);
  EXPECT_EQ(scene.geometry.triangles.size(), 1u);
}

TEST(NffLoader, PatchWithZeroNormalIsKept) {
  // A zero normal means "use the geometric normal" to the shading code; it is not an error.
  Scene scene;
  const MeshLoadReport r = parse("p 3\n0 0 1\n1 0 1\n0 1 1\npp 3\n0 0 0 0 0 0\n1 0 0 0 0 1\n0 1 0 0 0 0\n", scene);
  EXPECT_EQ(r.triangles, 2u);
  ASSERT_EQ(scene.geometry.triangle_normals.size(), 2u);
  expect_vec(scene.geometry.triangle_normals[1][0], {0.f, 0.f, 0.f});
  expect_vec(scene.geometry.triangle_normals[1][1], {0.f, 0.f, 1.f});
  expect_vec(scene.geometry.triangle_normals[1][2], {0.f, 0.f, 0.f});
}

TEST(NffLoader, FirstTriangleKeepsItsPatchNormals) {
  // A file whose very first polygon is a patch: its normals must not be lost.
  Scene scene;
  parse("pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\np 3\n0 0 1\n1 0 1\n0 1 1\n", scene);
  ASSERT_EQ(scene.geometry.triangle_normals.size(), 2u);
  expect_vec(scene.geometry.triangle_normals[0][0], {0.f, 0.f, 1.f});
  expect_vec(scene.geometry.triangle_normals[1][0], {0.f, 0.f, 0.f});
}

TEST(NffLoader, EmptyFileIsAnEmptyScene) {
  // Valid NFF; refusing a scene with nothing to render is the command line's business.
  for (const std::string text : {"", "\n\n  \t\n", "# nothing\n   # at all"}) {
    Scene scene;
    const MeshLoadReport r = parse(text, scene);
    EXPECT_EQ(scene.geometry.size(), 0u);
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_TRUE(scene.materials.empty());
    EXPECT_EQ(r.triangles, 0u);
  }
}

TEST(NffLoader, LoadNffReadsTheFileAndReportsPolygons) {
  const test::TempDir dir("nff");
  const std::string path = dir.file("scene.nff");
  std::ofstream(path, std::ios::binary) << "p 3\n0 0 0\n1 0 0\n1 0 0\np 3\n0 0 0\n1 0 0\n0 1 0\nl 0 0 9\nq\n";
  Scene scene;
  const std::string message = test::thrown_message([&] { load_nff(path, scene); });
  EXPECT_EQ(message.rfind(path + ":10:1: unknown entity 'q'", 0), 0u) << message;
  std::ofstream(path, std::ios::binary) << "p 3\n0 0 0\n1 0 0\n1 0 0\np 3\n0 0 0\n1 0 0\n0 1 0\nl 0 0 9\n";
  Scene good;
  const MeshLoadReport r = load_nff(path, good);
  EXPECT_EQ(r.triangles, 1u);
  EXPECT_EQ(r.degenerate_dropped, 1u);
  ASSERT_EQ(good.lights.size(), 1u);
  expect_vec(good.lights[0].intensity, {1.f, 1.f, 1.f});  // finish() ran: 1 / sqrt(1)
  EXPECT_THROW(load_nff(dir.file("missing.nff"), good), InputError);
}

// ---- malformed input, each located exactly ----

// A text that must fail with an InputError at `line`:`col` whose message contains `words`;
// `rule` names what the text breaks.
struct Malformed {
  const char* rule;
  std::string text;
  int line, col;
  const char* words;
};

// A view entity complete up to its resolution line (line 7).
const std::string kViewHead = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n";

const Malformed kMalformed[] = {
    // A text cut short is an unexpected end of file. Padding in a comment keeps the byte-count
    // check from refusing the polygon's count first.
    {"Truncated", "p 4\n0 0 0\n1 0 0\n1 1 0   # the fourth vertex is missing\n", 5, 1,
     "unexpected end of file, expected polygon vertex x"},
    {"Truncated", "p 3\n0 0 0  # padding padding\n1 0 0\n1 1", 4, 4,
     "unexpected end of file, expected polygon vertex z"},
    {"Truncated", "s 1 2 3", 1, 8, "unexpected end of file, expected sphere radius"},
    {"Truncated", std::string(kView).substr(0, 37), 5, 7, "unexpected end of file, expected view angle"},
    // A vertex count the rest of the file cannot hold is refused before reading, as are counts
    // below 3 and counts that are not integers.
    {"CountTooLarge", "p 1000000000000\n0 0 0\n1 0 0\n0 1 0\n", 1, 3, "1000000000000"},
    {"CountTooLarge", "p 1000000000000\n0 0 0\n1 0 0\n0 1 0\n", 1, 3, "more than the rest of the file can hold"},
    {"CountTooLarge", "s 0 0 0 1\n  pp 99999999999999999999999\n", 2, 6, "99999999999999999999999"},
    // Four patch vertices need at least 48 bytes; three are there, so the count is refused at
    // once rather than at the end of the file.
    {"CountTooLarge", "pp 4\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n", 1, 4, "patch vertex count '4'"},
    {"CountTooLarge", "p 2\n0 0 0\n1 0 0\n", 1, 3, "p needs at least 3 vertices, found '2'"},
    {"CountTooLarge", "pp -5\n", 1, 4, "pp needs at least 3 vertices"},
    {"CountTooLarge", "p three\n", 1, 3, "expected polygon vertex count (an integer), found 'three'"},
    // Numbers that are not finite in single precision.
    {"NonFinite", "s 0 nan 0 1\n", 1, 5, "expected sphere centre y (a finite number), found 'nan'"},
    {"NonFinite", "s 0 0 -inf 1\n", 1, 7, "found '-inf'"},
    {"NonFinite", "s 0 0 0 INF\n", 1, 9, "sphere radius"},
    {"NonFinite", "p 3\n0 0 0\n1 0 0\n0 1e39 0\n", 4, 3, "too large for single precision"},
    {"NonFinite", "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 NaN 1\n", 4, 9, "patch normal y"},
    {"NonFinite", "l 1 2 3 0.5 nan 1\n", 1, 13, "light green"},
    {"NonFinite", "f 1 1 1 1 0 0 0 1e400\n", 1, 17, "fill index of refraction"},
    {"NonFinite", "b 0.1 0x10 0.3\n", 1, 7, "background green"},
    // An unknown entity is named, with the valid ones listed.
    {"UnknownEntity", "s 0 0 0 1\n  q 1 2 3\n", 2, 3,
     "unknown entity 'q'; valid entities are v (view), b (background)"},
    {"UnknownEntity", "s 0 0 0 1\n  q 1 2 3\n", 2, 3, "pp (polygon patch)"},
    {"UnknownEntity", "P 3\n", 1, 1, "unknown entity 'P'"},
    // A polygon with more vertices than its count leaves numbers where an entity should be.
    {"UnknownEntity", "p 3\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", 5, 1, "more vertices than its count says"},
    // The view's lines, checked in their order.
    {"ViewOrder", "v\nfrom 0 0 5\nup 0 1 0\nat 0 0 0\n", 3, 1, "expected 'at'"},
    {"ViewOrder", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nresolution 10 10\n", 6, 1, "expected 'hither'"},
    {"ViewOrder", "v\nfrom 0 0 5\nat 0 0 5\nup 0 1 0\n", 3, 1, "'at' point is the same as the 'from' point"},
    {"ViewOrder", "v\nfrom 0 0 5\nat 0 0 0\nup 0 0 2\n", 4, 1, "parallel to the viewing direction"},
    {"ViewOrder", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 180\n", 5, 7, "between 0 and 180"},
    {"ViewOrder", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 0\n", 5, 7, "between 0 and 180"},
    {"ViewOrder", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither -1\n", 6, 8, "must not be negative"},
    {"ViewOrder", kViewHead + "resolution 0 512\n", 7, 12, "image width 0 is out of range [1, 65536]"},
    {"ViewOrder", kViewHead + "resolution 512 70000\n", 7, 16, "image height 70000 is out of range"},
    {"ViewOrder", kViewHead + "resolution 51.2 512\n", 7, 12, "expected image width (an integer)"},
    // Radii and colours out of range.
    {"BadValue", "s 0 0 0 -1\n", 1, 9, "sphere radius must be positive, found '-1'"},
    {"BadValue", "s 0 0 0 0\n", 1, 9, "sphere radius must be positive"},
    {"BadValue", "c\n0 0 0 -1\n0 1 0 1\n", 2, 7, "cone base radius must not be negative"},
    {"BadValue", "c\n0 0 0 1\n0 1 0 -0.5\n", 3, 7, "cone apex radius must not be negative"},
    {"BadValue", "c\n0 0 0 0\n0 1 0 0\n", 3, 7, "cone radii are both 0"},
    {"BadValue", "c\n0 0 0 1\n0 0 0 1\n", 3, 1, "cone apex is the same point as its base"},
    {"BadValue", "l 1 2 3 x\n", 1, 9, "expected light red (a finite number), found 'x'"},
    {"BadValue", "f 1 -1 1 1 0 0 0 1\n", 1, 5, "fill green must not be negative"},
    {"BadValue", "b 0 0 -0.5\n", 1, 7, "background blue must not be negative"},
};

// How gtest names a case in its listings: the text, as a C string literal would spell it.
void PrintTo(const Malformed& m, std::ostream* os) { *os << ::testing::PrintToString(m.text); }

class NffMalformed : public ::testing::TestWithParam<Malformed> {};

TEST_P(NffMalformed, IsRefusedAtItsLineAndColumn) {
  const Malformed& m = GetParam();
  expect_error(m.text, m.line, m.col, m.words);
}

INSTANTIATE_TEST_SUITE_P(NffLoader, NffMalformed, ::testing::ValuesIn(kMalformed),
                         [](const ::testing::TestParamInfo<Malformed>& info) {
                           return info.param.rule + ("_" + std::to_string(info.index));
                         });

TEST(NffLoader, GarbageBytesThrowInputErrorNeverCrash) {
  std::mt19937 rng(20240611u);
  for (int round = 0; round < 200; ++round) {
    std::string bytes(64 + rng() % 4096, '\0');
    for (char& c : bytes) c = static_cast<char>(rng() & 0xff);
    Scene scene;
    try {
      parse(bytes, scene);
      ADD_FAILURE() << "random bytes parsed, round " << round;
    } catch (const InputError& e) {
      EXPECT_GE(e.line(), 1);
      EXPECT_GE(e.column(), 1);
    }
  }
}

TEST(NffLoader, TokenSoupParsesOrThrowsInputError) {
  // Random sequences of entity names, numbers and bad words exercise every branch's error path;
  // anything but success or InputError (a crash, another exception) fails the test.
  const char* words[] = {"v",    "from", "at", "up", "angle", "hither", "resolution", "b",      "l",
                         "f",    "c",    "s",  "p",  "pp",    "0",      "1",          "-1",     "2.5",
                         "1e39", "nan",  "3",  "4",  "#",     "\n",     "x",          "1000000"};
  std::mt19937 rng(7u);
  int parsed = 0, refused = 0;
  for (int round = 0; round < 3000; ++round) {
    std::string text;
    const int n = 1 + static_cast<int>(rng() % 40);
    for (int i = 0; i < n; ++i) {
      text += words[rng() % std::size(words)];
      text += (rng() % 4 == 0) ? '\n' : ' ';
    }
    Scene scene;
    try {
      parse(text, scene);
      ++parsed;
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_EQ(parsed + refused, 3000);
}

TEST(NffLoader, EveryPrefixOfARealFileParsesOrThrowsInputError) {
  // Teapot's first 3000 bytes hold the view, lights, fills, polygons and its first patches;
  // rings' first 1000 its cones and spheres.
  for (const auto& [name, bytes] : {std::pair{"teapot.nff", 3000}, std::pair{"rings.nff", 1000}}) {
    const std::string path = kSpdDir + name;
    if (!fs::exists(path)) GTEST_SKIP() << path << " is not present";
    const std::string text = read_file(path).substr(0, bytes);
    int refused = 0;
    for (std::size_t n = 0; n <= text.size(); ++n) {
      Scene scene;
      try {
        parse(text.substr(0, n), scene);
      } catch (const InputError& e) {
        ++refused;
        ASSERT_GE(e.line(), 1) << e.what();
      }
    }
    EXPECT_GT(refused, 0) << name;
  }
}

// ---- the SPD reference files ----

// What a reference file holds, counted from its text without the parser: the first word of each
// line names the entity, and polygon lines say how many vertices follow.
struct TextCounts {
  std::size_t spheres = 0, cones = 0, polygons = 0, lights = 0, fan_triangles = 0;
};

TextCounts count_entities(const std::string& text) {
  TextCounts c;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == "s") ++c.spheres;
    if (first == "c") ++c.cones;
    if (first == "l") ++c.lights;
    if (first == "p" || first == "pp") {
      std::size_t n = 0;
      words >> n;
      ++c.polygons;
      c.fan_triangles += n - 2;  // what a polygon of n corners gives, before degenerate ones go
    }
  }
  return c;
}

struct SpdReference {
  const char* name;
  std::size_t spheres, polygons, cones;  // the table in spd-reference/README.md
};

constexpr SpdReference kSpdTable[] = {
    {"balls", 7381, 1, 0},  {"gears", 0, 9345, 0}, {"mount", 4, 8192, 0},   {"rings", 4200, 1, 4200},
    {"teapot", 0, 2292, 0}, {"tetra", 0, 4096, 0}, {"tree", 4095, 1, 4095},
};

TEST(NffLoader, SpdReferenceFilesHaveTheDocumentedPrimitives) {
  if (!fs::exists(kSpdDir)) GTEST_SKIP() << kSpdDir << " is not present";
  for (const SpdReference& ref : kSpdTable) {
    SCOPED_TRACE(ref.name);
    const std::string path = kSpdDir + ref.name + ".nff";
    const TextCounts want = count_entities(read_file(path));
    EXPECT_EQ(want.spheres, ref.spheres);
    EXPECT_EQ(want.polygons, ref.polygons);
    EXPECT_EQ(want.cones, ref.cones);

    Scene scene;
    const MeshLoadReport r = load_nff(path, scene);
    EXPECT_EQ(scene.geometry.spheres.size(), ref.spheres);
    EXPECT_EQ(scene.geometry.cylinders.size(), ref.cones);
    EXPECT_EQ(scene.geometry.triangles.size(), r.triangles);
    EXPECT_EQ(r.triangles + r.degenerate_dropped, want.fan_triangles);
    EXPECT_EQ(scene.lights.size(), want.lights);
    EXPECT_TRUE(scene.geometry.disks.empty());
    EXPECT_TRUE(scene.geometry.quads.empty());
    EXPECT_EQ(scene.camera.fov_span, CameraSpec::FovSpan::kPixelCentres);
    EXPECT_EQ(scene.settings.width, 512);
    EXPECT_EQ(scene.settings.height, 512);
  }
}

TEST(NffLoader, BallsViewLightsAndBackgroundMatchItsFirstLines) {
  const std::string path = kSpdDir + "balls.nff";
  if (!fs::exists(path)) GTEST_SKIP() << path << " is not present";
  Scene scene;
  load_nff(path, scene);
  // b 0.078 0.361 0.753 / v from 2.1 1.3 1.7 at 0 0 0 up 0 0 1 angle 45 hither 0.01
  // resolution 512 512 / l 4 3 2 / l 1 -4 4 / l -3 1 5 / f 1 0.75 0.33 0.8 0 100000 0 1
  expect_vec(scene.settings.background, {0.078f, 0.361f, 0.753f});
  expect_vec(scene.camera.from, {2.1f, 1.3f, 1.7f});
  expect_vec(scene.camera.at, {0.f, 0.f, 0.f});
  expect_vec(scene.camera.up, {0.f, 0.f, 1.f});
  EXPECT_EQ(scene.camera.vfov_degrees, 45.f);
  EXPECT_EQ(scene.camera.hither, 0.01f);
  EXPECT_EQ(scene.settings.max_depth, 5);
  ASSERT_EQ(scene.lights.size(), 3u);
  expect_vec(scene.lights[0].position, {4.f, 3.f, 2.f});
  expect_vec(scene.lights[1].position, {1.f, -4.f, 4.f});
  expect_vec(scene.lights[2].position, {-3.f, 1.f, 5.f});
  const float share = 1.f / std::sqrt(3.f);
  for (const Light& l : scene.lights) {
    EXPECT_EQ(l.kind, Light::Kind::kPoint);
    EXPECT_FALSE(l.falloff);
    expect_vec(l.intensity, {share, share, share});
  }
  ASSERT_FALSE(scene.materials.empty());
  expect_fill(scene.materials[0], {1.f, 0.75f, 0.33f}, 0.8f, 0.f, 100000.f, 0.f, 1.f);
}

}  // namespace
}  // namespace raylab
