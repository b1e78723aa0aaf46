// Long renders in the library: a render taken in passes, stopped after any tile, or resumed from
// a saved state (or from any checkpoint taken on the way) ends with exactly the bits of a render
// done in one go; the state refuses another image; the adaptive samplers refuse what they cannot do.

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/render/render_progress.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

struct Setup {
  const char* filter;
  bool packets;
};

class RenderProgressTest : public ::testing::TestWithParam<Setup> {
 protected:
  RenderProgressTest() : m_scene(make_demo_scene()) {
    m_scene.settings.width = 61;  // tiles of 16: a ragged last column and row
    m_scene.settings.height = 37;
    m_scene.settings.spp = 9;  // jittered takes square counts
    m_scene.settings.sampler = "jittered";
    m_scene.settings.filter = GetParam().filter;
    m_accel = make_accelerator("bvh", m_scene.geometry);
  }

  RenderOptions options(int threads = 2) const {
    RenderOptions o;
    o.threads = threads;
    o.packets = GetParam().packets;
    return o;
  }

  // The render in one go, the reference.
  Film reference() const {
    Film film(m_scene.settings.width, m_scene.settings.height);
    render(m_scene, *m_accel, film, options());
    return film;
  }

  Film blank() const { return Film(m_scene.settings.width, m_scene.settings.height); }

  Scene m_scene;
  std::unique_ptr<Accelerator> m_accel;
};

bool same_bits(const Film& a, const Film& b) {
  return a.pixels().size() == b.pixels().size() &&
         std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Color)) == 0;
}

// A stop condition that lets `tiles` tiles start, then stops (thread-safe).
std::function<bool()> stop_after(int tiles) {
  auto started = std::make_shared<std::atomic<int>>(0);
  return [started, tiles] { return started->fetch_add(1) >= tiles; };
}

TEST_P(RenderProgressTest, PassesGiveTheImageOfOneGo) {
  const Film expected = reference();
  for (int passes : {2, 4, 9}) {
    Film film = blank();
    RenderOptions o = options();
    o.passes = passes;
    int previews = 0;
    o.on_pass = [&](int done, const Film& preview) {
      ++previews;
      EXPECT_EQ(done, previews);
      EXPECT_FALSE(same_bits(preview, blank())) << "a preview after a pass shows the samples so far";
    };
    const RenderResult result = render(m_scene, *m_accel, film, o);
    EXPECT_FALSE(result.interrupted);
    EXPECT_EQ(previews, passes - 1);
    if (std::string(GetParam().filter) == "box") {
      // Each pixel's own samples are summed in the same order whatever the passes.
      EXPECT_TRUE(same_bits(film, expected)) << passes << " passes";
    } else {
      // Wider filters add a neighbour's samples between a pixel's own ones in another order.
      for (std::size_t i = 0; i < film.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(film.pixels()[i][c], expected.pixels()[i][c], 1e-5f) << i;
      }
    }
    EXPECT_EQ(result.samples_per_pixel.front(), 9u);
  }
}

TEST_P(RenderProgressTest, StoppedAndResumedGivesTheSameBits) {
  const int tiles = 4 * 3;
  for (int passes : {1, 3}) {
    Film expected = blank();
    RenderOptions in_one_go = options();
    in_one_go.passes = passes;
    render(m_scene, *m_accel, expected, in_one_go);
    for (int stop_at : {0, 1, 7, tiles, tiles + 5, 2 * tiles + 11}) {
      RenderProgress progress;
      Film partial = blank();
      RenderOptions first = options();
      first.passes = passes;
      first.progress = &progress;
      first.should_stop = stop_after(stop_at);
      const RenderResult stopped = render(m_scene, *m_accel, partial, first);
      if (stop_at >= passes * tiles) {
        EXPECT_FALSE(stopped.interrupted);
        continue;
      }
      ASSERT_TRUE(stopped.interrupted) << passes << " passes, stop after " << stop_at;
      ASSERT_FALSE(progress.complete());
      if (progress.passes_done == 0) {
        // Tiles that never finished a pass are black in the partial image, and count no samples.
        for (int t : progress.unfinished_tiles()) {
          const TileSums& s = progress.tiles[static_cast<std::size_t>(t)];
          const int cx = std::min(s.x1 - 1, s.x0 + progress.margin), cy = std::min(s.y1 - 1, s.y0 + progress.margin);
          if (progress.margin == 0) {
            EXPECT_EQ(partial.at(cx, cy)[0], 0.f) << "tile " << t;
          }
          EXPECT_EQ(stopped.samples_per_pixel[std::size_t(cy) * partial.width() + cx], 0u);
        }
      }
      // Resume on one thread (the image must not depend on it) from a copy of the saved state.
      RenderProgress saved = progress;
      Film film = blank();
      RenderOptions second = options(1);
      second.passes = 99;  // ignored: the saved state says how many passes
      second.progress = &saved;
      const RenderResult resumed = render(m_scene, *m_accel, film, second);
      EXPECT_FALSE(resumed.interrupted);
      EXPECT_TRUE(saved.complete());
      EXPECT_TRUE(same_bits(film, expected)) << passes << " passes, stopped after " << stop_at << " tiles";
    }
  }
}

TEST_P(RenderProgressTest, EveryCheckpointResumesToTheSameBits) {
  RenderOptions o = options();
  o.passes = 2;
  std::mutex m;
  std::vector<RenderProgress> checkpoints;
  o.on_checkpoint = [&](const RenderProgress& p) {
    const std::lock_guard lock(m);
    checkpoints.push_back(p);
  };
  o.checkpoint_seconds = 1e-9;  // at every tile that finds no checkpoint under way
  Film expected = blank();
  render(m_scene, *m_accel, expected, o);
  ASSERT_GE(checkpoints.size(), 3u);
  for (std::size_t i = 0; i < checkpoints.size(); i += 3) {
    Film film = blank();
    RenderOptions resume = options();
    resume.progress = &checkpoints[i];
    render(m_scene, *m_accel, film, resume);
    EXPECT_TRUE(same_bits(film, expected)) << "checkpoint " << i;
  }
}

TEST_P(RenderProgressTest, AStateForAnotherImageIsRefused) {
  RenderProgress other = start_progress(60, 37, 16, 9, 1, 0);
  Film film = blank();
  RenderOptions o = options();
  o.progress = &other;
  EXPECT_THROW(render(m_scene, *m_accel, film, o), UsageError);
  RenderProgress more_samples = start_progress(61, 37, 16, 16, 1, 0);
  o.progress = &more_samples;
  EXPECT_THROW(render(m_scene, *m_accel, film, o), UsageError);
}

INSTANTIATE_TEST_SUITE_P(Filters, RenderProgressTest,
                         ::testing::Values(Setup{"box", true}, Setup{"box", false}, Setup{"gaussian", true},
                                           Setup{"mitchell", false}),
                         [](const auto& info) {
                           return std::string(info.param.filter) + (info.param.packets ? "Packets" : "Singles");
                         });

TEST(RenderProgress, PassesSplitTheSamplesEvenly) {
  const RenderProgress p = start_progress(10, 10, 4, 10, 3, 0);
  EXPECT_EQ(p.tile_count(), 9);
  EXPECT_EQ(p.samples_before(0), 0);
  EXPECT_EQ(p.samples_before(1), 3);
  EXPECT_EQ(p.samples_before(2), 6);
  EXPECT_EQ(p.samples_before(3), 10);
  EXPECT_EQ(p.tiles[8].x0, 8);
  EXPECT_EQ(p.tiles[8].x1, 10);
  EXPECT_EQ(p.tiles[8].sum.size(), 4u);
  EXPECT_TRUE(p.tiles[8].weight.empty());
  EXPECT_EQ(p.memory_bytes(), progress_memory_bytes(10, 10, 4, 0) - 9 * sizeof(TileSums));
  const RenderProgress wide = start_progress(10, 10, 4, 10, 3, 2);
  EXPECT_EQ(wide.tiles[4].x0, 2);  // the middle tile [4, 8) with its margin of 2
  EXPECT_EQ(wide.tiles[4].x1, 10);
  EXPECT_EQ(wide.tiles[4].weight.size(), 64u);
}

TEST(RenderProgress, PassesOutOfRangeAreRefused) {
  EXPECT_THROW(start_progress(10, 10, 4, 4, 5, 0), UsageError);
  EXPECT_THROW(start_progress(10, 10, 4, 4, 0, 0), UsageError);
  EXPECT_THROW(start_progress(0, 10, 4, 4, 1, 0), UsageError);
}

TEST(RenderProgress, AdaptiveSamplersRefusePassesAndStates) {
  Scene scene = make_demo_scene();
  scene.settings.width = 32;
  scene.settings.height = 16;
  scene.settings.spp = 16;
  scene.settings.sampler = "adaptive";
  const auto accel = make_accelerator("bvh", scene.geometry);
  Film film(32, 16);
  RenderOptions o;
  o.passes = 2;
  EXPECT_THROW(render(scene, *accel, film, o), UsageError);
  RenderProgress progress;
  RenderOptions with_state;
  with_state.progress = &progress;
  EXPECT_THROW(render(scene, *accel, film, with_state), UsageError);
}

}  // namespace
}  // namespace raylab
