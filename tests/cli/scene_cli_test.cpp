// The scene-facing commands through the real binary: flags override scene files, --list-scenes,
// --spd-protocol, info, convert, and the exit codes of bad scenes.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "../test_paths.h"
#include "cli_fixture.h"
#include "raylab/io/image_io.h"
#include "raylab/io/nff_loader.h"

namespace raylab {
namespace {

using namespace cli_test;

const std::string kScenes = raylab::test::source_dir() + "/scenes/";

TEST_F(Cli, FlagsOverrideTheSceneFilesRenderSettings) {
  const CliResult r =
      run("render '" + kScenes + "whitted.json' --width 32 --height 20 --spp 1 -q -o '" + out_file("w.pfm") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const Film film = read_image(out_file("w.pfm"));
  EXPECT_EQ(film.width(), 32);  // the file says 640 x 400
  EXPECT_EQ(film.height(), 20);
}

TEST_F(Cli, ListScenesNamesBuiltInsAndGenerators) {
  const CliResult r = run("render --list-scenes");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"demo", "cornell", "spd:balls", "spd:gears", "spd:mount", "spd:rings", "spd:teapot",
                           "spd:tetra", "spd:tree", ".json", ".nff", ".ply"}) {
    EXPECT_NE(r.out.find(name), std::string::npos) << name << "\n" << r.out;
  }
}

// The row of `kind` in the protocol's table, as its numbers.
std::vector<std::uint64_t> protocol_row(const std::string& out, const std::string& kind) {
  const auto at = out.find("\n" + kind + " ");
  if (at == std::string::npos) return {};
  std::istringstream row(out.substr(at + 1 + kind.size(), out.find('\n', at + 1) - at - 1 - kind.size()));
  std::vector<std::uint64_t> numbers;
  for (std::string word; row >> word;) {
    if (word.find('.') == std::string::npos) numbers.push_back(std::stoull(word));
  }
  return numbers;
}

TEST_F(Cli, SpdProtocolPrintsTheRayCountInvariants) {
  const CliResult r = run("render 'spd:balls?size=1' --spd-protocol -q -o '" + out_file("p.png") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(protocol_row(r.out, "eye").size(), 2u) << r.out;
  EXPECT_EQ(protocol_row(r.out, "eye")[0], 513u * 513u) << r.out;
  for (const char* kind : {"reflection", "refraction", "shadow"}) {
    EXPECT_EQ(protocol_row(r.out, kind).size(), 2u) << kind << "\n" << r.out;  // cast, hit
  }
  // Size 1 is not a size the SPD README counted: no column of its figures.
  EXPECT_EQ(r.out.find("SPD README"), std::string::npos) << r.out;
  const Film film = read_image(out_file("p.png"));
  EXPECT_EQ(film.width(), 512);
  // The procedure fixes size and depth; asking for others is a usage error.
  const CliResult bad = run("render spd:balls --spd-protocol --width 100 -q -o '" + out_file("q.png") + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--spd-protocol"), std::string::npos) << bad.err;
}

// At the README's size the table gains the README's figure and the ratio; --json - puts the
// same counts on stdout as one JSON document (the table then goes to stderr).
TEST_F(Cli, SpdProtocolComparesWithTheReadmeAndWritesJson) {
  const CliResult r = run("render spd:tetra --spd-protocol -q -o '" + out_file("t.png") + "' --json -");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("SPD README"), std::string::npos) << r.err;
  const std::vector<std::uint64_t> eye = protocol_row(r.err, "eye");  // cast, hit, README's eye hits
  ASSERT_EQ(eye.size(), 3u) << r.err;
  EXPECT_EQ(eye[2], 49788u);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scene"], "spd:tetra");
  EXPECT_EQ(j["facing"], "viewer");
  EXPECT_EQ(j["rays"]["eye"]["cast"], 513u * 513u);
  EXPECT_EQ(j["rays"]["eye"]["hit"], eye[1]);
  EXPECT_EQ(j["rays"]["shadow"]["cast"], protocol_row(r.err, "shadow")[0]);
  ASSERT_EQ(j["published"].size(), 2u);  // the README and Havran & Sixta
  EXPECT_EQ(j["published"][0]["table"], "SPD README");
  EXPECT_EQ(j["published"][0]["figures"][0]["published"], 49788u);

  // To a file, with the other reading of rule 10.
  const CliResult f = run("render spd:tetra --spd-protocol --spd-facing outward -q -o '" + out_file("u.png") +
                          "' --json '" + out_file("t.json") + "'");
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_NE(f.out.find("by the outward normal"), std::string::npos) << f.out;
  EXPECT_EQ(nlohmann::json::parse(read_text(out_file("t.json")))["facing"], "outward");
}

TEST_F(Cli, SpdProtocolOptionsAreCheckedBeforeTheRender) {
  // Protocol options without the protocol, and an unknown reading, are usage errors.
  for (const char* extra : {"--spd-facing outward", "--json -", "--spd-protocol --spd-facing inward"}) {
    SCOPED_TRACE(extra);
    const CliResult r = run(std::string("render 'spd:balls?size=1' ") + extra + " -q -o '" + out_file("x.png") + "'");
    EXPECT_EQ(r.code, 2) << r.err;
  }
  // A JSON file that cannot be written is refused before anything is rendered or written.
  const CliResult r = run("render 'spd:balls?size=1' --spd-protocol -q -o '" + out_file("x.png") + "' --json '" +
                          out_file("missing/x.json") + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(entries(out()).empty());
}

TEST_F(Cli, BadSpdNamesAndSizesAreUsageErrors) {
  struct Case {
    const char* source;
    const char* words;
  };
  for (const Case& c : {Case{"spd:nope", "valid: balls, gears, mount, rings, teapot, tetra, tree"},
                        Case{"'spd:balls?size=99'", "from 1 to"}, Case{"'spd:balls?size=x'", "from 1 to"},
                        Case{"'spd:balls?depth=2'", "unknown SPD parameter 'depth'"}}) {
    SCOPED_TRACE(c.source);
    const CliResult r = run(std::string("render ") + c.source + " -q -o '" + out_file("x.png") + "'");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(c.words), std::string::npos) << r.err;
    expect_out_empty();
  }
}

TEST_F(Cli, InfoDescribesTheCornellBox) {
  const CliResult r = run("info cornell");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* words : {"triangles 30", "quads     1", "materials   4", "lights      1", "load time", "memory",
                            "from (278, 273, -800)"}) {
    EXPECT_NE(r.out.find(words), std::string::npos) << words << "\n" << r.out;
  }
}

TEST_F(Cli, ConvertWritesNffThatReadsBackToTheSameScene) {
  const CliResult r = run("convert 'spd:balls?size=2' '" + out_file("b.nff") + "' -q");
  ASSERT_EQ(r.code, 0) << r.err;
  Scene back;
  load_nff(out_file("b.nff"), back);
  EXPECT_EQ(back.geometry.spheres.size(), 91u);  // 1 + 9 + 81
  const CliResult obj = run("convert 'spd:balls?size=1' '" + out_file("b.obj") + "' --segments 8 -q");
  ASSERT_EQ(obj.code, 0) << obj.err;
  const CliResult again = run("info '" + out_file("b.obj") + "'");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("spheres   0"), std::string::npos) << again.out;  // tessellated
}

TEST_F(Cli, ConvertRefusesUnknownFormatsAndLeavesNothingOnBadInput) {
  const CliResult fmt = run("convert demo '" + out_file("x.xyz") + "'");
  EXPECT_EQ(fmt.code, 2);
  EXPECT_NE(fmt.err.find(".nff .obj .ply"), std::string::npos) << fmt.err;
  write_text(work() / "bad.json", "{\"version\": 1,\n  \"objects\": [}\n");
  const CliResult bad = run("convert '" + (work() / "bad.json").string() + "' '" + out_file("x.ply") + "'");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("bad.json:2:"), std::string::npos) << bad.err;
  expect_out_empty();
}

TEST_F(Cli, SceneFileReferencesOutsideItsFolderNeedTheFlag) {
  fs::create_directories(work() / "scene");
  write_text(work() / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_text(work() / "scene" / "s.json",
             "{\"version\": 1, \"materials\": {\"m\": {}},\n \"objects\": [{\"type\": \"mesh\", \"material\": \"m\", "
             "\"file\": \"../tri.obj\"}]}");
  const std::string scene = (work() / "scene" / "s.json").string();
  const CliResult refused = run("render '" + scene + "' --width 8 --height 8 -q -o '" + out_file("s.png") + "'");
  EXPECT_EQ(refused.code, 1);
  EXPECT_NE(refused.err.find("s.json:2:48:"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--allow-outside-paths"), std::string::npos) << refused.err;
  expect_out_empty();
  const CliResult allowed =
      run("render '" + scene + "' --allow-outside-paths --width 8 --height 8 -q -o '" + out_file("s.png") + "'");
  EXPECT_EQ(allowed.code, 0) << allowed.err;
}

TEST_F(Cli, ZeroAreaFacesAreDroppedWithACountedWarning) {
  // Two good triangles and two degenerate ones (a repeated corner, three collinear corners).
  write_text(work() / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 2\nf 1 2 4\nf 3 2 1\n");
  const CliResult r = run("info '" + (work() / "m.obj").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("m.obj: 2 zero-area triangles dropped"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("triangles 2"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace raylab
