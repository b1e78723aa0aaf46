// Every scene source raylab accepts, end to end through load_scene: the real scanned meshes in
// ../shared/scenes render at small size with their known triangle counts, and random bytes in a
// file of every supported extension give a clean InputError (or a valid scene), never a crash.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <typeinfo>

#include "../test_paths.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/renderer.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

const fs::path kShared = fs::path(raylab::test::source_dir()) / ".." / "shared" / "scenes";

// Renders `scene` at 40 x 30, 1 spp; returns the fraction of pixels that differ from the background.
double coverage(Scene& scene) {
  scene.settings.width = 40;
  scene.settings.height = 30;
  scene.settings.spp = 1;
  const auto accel = make_accelerator("bvh", scene.geometry);
  Film film(40, 30);
  render(scene, *accel, film);
  int differing = 0;
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) {
      const Color d = film.at(x, y) - scene.settings.background;
      EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z));
      differing += std::abs(d.x) + std::abs(d.y) + std::abs(d.z) > 0.02f;
    }
  }
  return differing / 1200.0;
}

TEST(SceneSources, SharedScannedMeshesLoadWithTheirTriangleCountsAndRender) {
  if (!fs::exists(kShared)) GTEST_SKIP() << "no " << kShared;
  struct Mesh {
    const char* file;
    std::size_t triangles;
  };
  // Counts from ../shared/scenes/README.md; igea's from its triangle strips.
  for (const Mesh m : {Mesh{"stanford-bunny.obj", 69451}, Mesh{"nefertiti.obj", 99938}, Mesh{"armadillo.off", 52000},
                       Mesh{"igea.ply", 268686}}) {
    SCOPED_TRACE(m.file);
    Scene scene = load_scene((kShared / m.file).string());
    EXPECT_EQ(scene.geometry.triangles.size(), m.triangles);
    // The fitted camera frames the mesh: a good part of the image shows it.
    EXPECT_GT(coverage(scene), 0.08);
  }
}

TEST(SceneSources, EveryBuiltInAndGeneratorRendersSomething) {
  for (const char* source : {"demo", "cornell", "spd:balls?size=2", "spd:gears?size=1", "spd:mount?size=3",
                             "spd:rings?size=1", "spd:teapot?size=2", "spd:tetra?size=3", "spd:tree?size=4"}) {
    SCOPED_TRACE(source);
    Scene scene = load_scene(source);
    EXPECT_GT(coverage(scene), 0.1);
  }
}

TEST(SceneSources, RandomBytesInEveryFormatAreRefusedCleanly) {
  const fs::path dir = fs::temp_directory_path() / ("raylab-garbage-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Pcg32 rng(2024);
  int refused = 0;
  for (const char* ext : {".json", ".nff", ".obj", ".ply", ".off", ".stl", ".gltf", ".glb"}) {
    for (int i = 0; i < 60; ++i) {
      // Half pure noise, half noise behind a plausible header, so parsers get past their first line.
      std::string bytes;
      if (i % 2 == 1) {
        const std::string e = ext;
        bytes = e == ".ply"    ? "ply\nformat binary_little_endian 1.0\n"
                : e == ".off"  ? "OFF\n"
                : e == ".stl"  ? "solid x\n"
                : e == ".json" ? "{\"version\": 1, "
                : e == ".obj"  ? "v 1 2 3\nf "
                : e == ".glb"  ? "glTF"
                               : "";
      }
      const std::uint32_t n = 1 + rng.next_u32() % 512;
      for (std::uint32_t k = 0; k < n; ++k) bytes += static_cast<char>(rng.next_u32() & 0xff);
      const fs::path file = dir / ("g" + std::to_string(i) + ext);
      std::ofstream(file, std::ios::binary) << bytes;
      SCOPED_TRACE(file.string());
      try {
        (void)load_scene(file.string());
      } catch (const InputError&) {
        ++refused;
      } catch (const std::exception& e) {
        ADD_FAILURE() << typeid(e).name() << ": " << e.what();
      }
    }
  }
  EXPECT_GT(refused, 400);  // nearly all of the 480 are refused; a rare one may parse
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raylab
