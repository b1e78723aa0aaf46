// A render is a pure function of the scene and settings: thread count, tile size and scheduling
// must not change a single bit, in the library or through the command line.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "../test_paths.h"
#include "raylab/accel/factory.h"
#include "raylab/io/image_io.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

// A fresh, empty folder under the system temp folder, removed with everything in it at the end.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    static std::atomic<int> counter{0};
    m_path = fs::temp_directory_path() /
             ("raylab-determinism-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(m_path);
    fs::create_directories(m_path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(m_path, ec);
  }
  const fs::path& path() const { return m_path; }

 private:
  fs::path m_path;
};

struct Rendered {
  Film film;
  RenderStats stats;
};

Rendered render_demo(int width, int height, int spp, int threads, int tile) {
  Scene scene = make_demo_scene();
  scene.settings.width = width;
  scene.settings.height = height;
  scene.settings.spp = spp;
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  Film film(width, height);
  RenderOptions options;
  options.threads = threads;
  options.tile_size = tile;
  const RenderResult r = render(scene, *accel, film, options);
  return {std::move(film), r.stats};
}

bool same_bits(const Film& a, const Film& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Color)) == 0;
}

std::vector<char> read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs the raylab binary with `args`; returns its exit code (-1 if it did not exit normally).
int run_raylab(const std::string& args, const fs::path& log) {
  const std::string cmd = "'" + raylab::test::raylab_binary() + "' " + args + " >'" + log.string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The demo exercises every path that could race: area-light sampling (random numbers), mirror
// and glass recursion, a triangle mesh, and per-thread statistics.
TEST(Determinism, DemoIsBitIdenticalForAnyThreadCountAndTileSize) {
  const Rendered reference = render_demo(96, 54, 4, 1, 16);
  // Not a trivially uniform image: the comparison below would prove little otherwise.
  bool varied = false;
  for (const Color& c : reference.film.pixels()) varied = varied || !(c == reference.film.pixels()[0]);
  ASSERT_TRUE(varied);

  struct Config {
    int threads, tile;
  };
  for (const Config cfg : {Config{2, 16}, Config{1, 7}, Config{2, 7}, Config{2, 1}}) {
    SCOPED_TRACE(::testing::Message() << "threads " << cfg.threads << " tile " << cfg.tile);
    const Rendered other = render_demo(96, 54, 4, cfg.threads, cfg.tile);
    EXPECT_TRUE(same_bits(reference.film, other.film));
    // Ray counts are sums of per-thread counters: the total must not depend on the split either.
    for (int k = 0; k < static_cast<int>(RayKind::kCount); ++k) {
      EXPECT_EQ(reference.stats.rays[k], other.stats.rays[k]) << ray_kind_name(static_cast<RayKind>(k));
      EXPECT_EQ(reference.stats.ray_hits[k], other.stats.ray_hits[k]) << ray_kind_name(static_cast<RayKind>(k));
    }
  }
}

TEST(Determinism, SameSettingsTwiceGiveTheSameImage) {
  EXPECT_TRUE(same_bits(render_demo(40, 24, 2, 2, 5).film, render_demo(40, 24, 2, 2, 5).film));
}

// The seed is the only source of variation: another seed moves the jittered samples.
TEST(Determinism, AnotherSeedGivesAnotherImage) {
  Scene scene = make_demo_scene();
  scene.settings.width = 40;
  scene.settings.height = 24;
  scene.settings.spp = 2;
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  Film a(40, 24), b(40, 24);
  render(scene, *accel, a, {});
  scene.settings.seed = 12345;
  render(scene, *accel, b, {});
  EXPECT_FALSE(same_bits(a, b));
}

// Through the real binary: files written with 1 and 2 threads are byte-for-byte equal, and equal
// to what the library renders in-process with the same settings (PFM keeps the floats exactly).
TEST(Determinism, CommandLineOutputDoesNotDependOnThreads) {
  const TempDir dir("cli");
  const fs::path a = dir.path() / "A.pfm", b = dir.path() / "B.pfm";
  const std::string common = "render demo --width 64 --height 36 --spp 2 -q";
  ASSERT_EQ(run_raylab(common + " --threads 1 -o '" + a.string() + "'", dir.path() / "a.log"), 0);
  ASSERT_EQ(run_raylab(common + " --threads 2 -o '" + b.string() + "'", dir.path() / "b.log"), 0);
  const std::vector<char> bytes_a = read_bytes(a), bytes_b = read_bytes(b);
  ASSERT_FALSE(bytes_a.empty());
  EXPECT_EQ(bytes_a, bytes_b);

  const Film from_file = read_image(a.string());
  EXPECT_TRUE(same_bits(from_file, render_demo(64, 36, 2, 2, 16).film));
}

}  // namespace
}  // namespace raylab
