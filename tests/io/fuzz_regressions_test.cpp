// Replays inputs that once broke (or were built to probe) the project's own parsers: each must
// load or be refused with an InputError, never crash or throw anything else. New crash inputs
// from `make fuzz` go into tests/data/fuzz-regressions/FORMAT/.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "../test_paths.h"
#include "raylab/core/error.h"
#include "raylab/io/nff_loader.h"
#include "raylab/io/off_loader.h"
#include "raylab/io/ply_loader.h"
#include "raylab/io/scene_json.h"
#include "raylab/io/stl_loader.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

void parse_as(const std::string& format, const std::string& bytes, const std::string& name) {
  Geometry geometry;
  Scene scene;
  if (format == "nff") {
    NffSceneBuilder builder(scene);
    parse_nff(bytes, name, builder);
  } else if (format == "ply") {
    parse_ply(bytes, name, geometry, 0);
  } else if (format == "off") {
    parse_off(bytes, name, geometry, 0);
  } else if (format == "stl") {
    parse_stl(bytes, name, geometry, 0);
  } else {
    parse_scene_json(bytes, name, "/nonexistent-raylab-folder");
  }
}

TEST(FuzzRegressions, EveryStoredInputLoadsOrIsRefusedCleanly) {
  const fs::path root = fs::path(raylab::test::source_dir()) / "tests" / "data" / "fuzz-regressions";
  int replayed = 0;
  for (const auto& dir : fs::directory_iterator(root)) {
    for (const auto& file : fs::directory_iterator(dir.path())) {
      SCOPED_TRACE(file.path().string());
      std::ifstream in(file.path(), std::ios::binary);
      const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      try {
        parse_as(dir.path().filename().string(), bytes, file.path().filename().string());
      } catch (const InputError&) {
        // A located refusal is the right outcome for bad input.
      }
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0);
}

}  // namespace
}  // namespace raylab
