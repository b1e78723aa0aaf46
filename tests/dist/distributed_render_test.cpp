// Distributed rendering over in-process channels (one thread per rank, each with its own scene
// and accelerator, as separate processes would have): the image has the bits of a local render
// for any number of ranks, filter, packets and passes; an interrupted run resumes to the same
// bits; a rank that fails, disagrees, or falls silent ends the run with a message naming it and
// the tiles it held.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include "raylab/accel/factory.h"
#include "raylab/dist/distributed_frames.h"
#include "raylab/dist/distributed_render.h"
#include "raylab/dist/local_channel.h"
#include "raylab/render/renderer.h"
#include "raylab/render/tile_renderer.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab::dist {
namespace {

// What one rank holds: its own copy of the scene and its own accelerator.
struct Rank {
  Scene scene;
  std::unique_ptr<Accelerator> accel;
  std::unique_ptr<TileRenderer> renderer;
};

Scene test_scene(const char* filter) {
  Scene s = make_demo_scene();
  s.settings.width = 61;  // tiles of 16: a ragged last column and row
  s.settings.height = 37;
  s.settings.spp = 4;
  s.settings.sampler = "jittered";
  s.settings.filter = filter;
  return s;
}

RenderOptions options_for(bool packets, int passes = 1) {
  RenderOptions o;
  o.threads = 2;
  o.packets = packets;
  o.passes = passes;
  return o;
}

std::unique_ptr<Rank> make_rank(const Scene& scene, const RenderOptions& options) {
  auto r = std::make_unique<Rank>();
  r->scene = scene;
  r->accel = make_accelerator("bvh", r->scene.geometry);
  r->renderer = std::make_unique<TileRenderer>(r->scene, *r->accel, options);
  return r;
}

Film local_render(const Scene& scene, const RenderOptions& options) {
  Film film(scene.settings.width, scene.settings.height);
  const auto accel = make_accelerator("bvh", scene.geometry);
  render(scene, *accel, film, options);
  return film;
}

bool same_bits(const Film& a, const Film& b) {
  return a.pixels().size() == b.pixels().size() &&
         std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Color)) == 0;
}

// Runs render_distributed on `size` ranks, rank r with options `per_rank(r)` and channel
// `wrap(r, channel)`; returns every rank's result, rank 0's image into `film`.
std::vector<DistributedResult> run_ranks(int size, const Scene& scene, Film& film,
                                         const std::function<DistributedOptions(int)>& per_rank,
                                         std::vector<std::unique_ptr<Channel>> channels = {}) {
  if (channels.empty()) channels = make_local_channels(size);
  std::vector<std::unique_ptr<Rank>> ranks;
  std::vector<DistributedOptions> options;
  for (int r = 0; r < size; ++r) {
    options.push_back(per_rank(r));
    ranks.push_back(make_rank(scene, options.back().render));
  }
  std::vector<DistributedResult> results(static_cast<std::size_t>(size));
  std::vector<std::thread> threads;
  for (int r = 1; r < size; ++r) {
    threads.emplace_back([&, r] {
      Film none(0, 0);
      const auto i = static_cast<std::size_t>(r);
      results[i] = render_distributed(*channels[i], *ranks[i]->renderer, none, options[i]);
    });
  }
  results[0] = render_distributed(*channels[0], *ranks[0]->renderer, film, options[0]);
  for (std::thread& t : threads) t.join();
  return results;
}

struct Case {
  const char* filter;
  bool packets;
  int passes;
};

class DistributedRender : public ::testing::TestWithParam<Case> {};

TEST_P(DistributedRender, ImageHasTheBitsOfALocalRenderForAnyNumberOfRanks) {
  const Case c = GetParam();
  const Scene scene = test_scene(c.filter);
  const Film reference = local_render(scene, options_for(c.packets, c.passes));
  for (int size : {1, 2, 3, 4}) {
    SCOPED_TRACE(size);
    Film film(scene.settings.width, scene.settings.height);
    int passes_seen = 0;
    const std::vector<DistributedResult> results = run_ranks(size, scene, film, [&](int) {
      DistributedOptions o;
      o.render = options_for(c.packets, c.passes);
      o.render.on_pass = [&](int, const Film&) { ++passes_seen; };
      o.agreement = 42;
      return o;
    });
    ASSERT_EQ(results[0].outcome, DistributedOutcome::kComplete) << results[0].message;
    EXPECT_TRUE(same_bits(film, reference));
    EXPECT_EQ(passes_seen, c.passes - 1);  // after every pass but the last
    // Every rank reported, and the tiles add up to every pass of every tile.
    ASSERT_EQ(results[0].ranks.size(), static_cast<std::size_t>(size));
    int jobs = 0;
    for (const RankReport& r : results[0].ranks) jobs += r.jobs;
    EXPECT_EQ(jobs, 4 * 3 * c.passes);  // 61x37 in tiles of 16: 4 x 3 tiles
    // The rays of all ranks together are those of the local render.
    RenderStats local;
    {
      Film again(scene.settings.width, scene.settings.height);
      const auto accel = make_accelerator("bvh", scene.geometry);
      local = render(scene, *accel, again, options_for(c.packets, c.passes)).stats;
    }
    EXPECT_EQ(results[0].render.stats.total_rays(), local.total_rays());
    EXPECT_EQ(results[0].render.samples_per_pixel.size(), std::size_t(61 * 37));
    EXPECT_EQ(results[0].render.samples_per_pixel[0], 4u);
  }
}

INSTANTIATE_TEST_SUITE_P(FiltersPacketsPasses, DistributedRender,
                         ::testing::Values(Case{"box", true, 1}, Case{"box", false, 1}, Case{"gaussian", true, 1},
                                           Case{"mitchell", false, 2}, Case{"box", true, 4}));

TEST(DistributedRenderFaults, InterruptedRunResumesToTheSameBits) {
  const Scene scene = test_scene("gaussian");
  const Film reference = local_render(scene, options_for(true, 2));
  RenderProgress progress;
  std::atomic<int> done{0};
  Film film(scene.settings.width, scene.settings.height);
  RenderProgress saved;
  bool checkpointed = false;
  std::vector<DistributedResult> results = run_ranks(3, scene, film, [&](int r) {
    DistributedOptions o;
    o.render = options_for(true, 2);
    o.agreement = 7;
    o.interrupt_grace_seconds = 1.0;  // generous: a loaded machine may be slow to answer
    if (r == 0) {
      o.render.progress = &progress;
      o.render.on_progress = [&](int, int) { ++done; };
      o.render.on_checkpoint = [&](const RenderProgress& p) {
        saved = p;
        checkpointed = true;
      };
    }
    // Every rank is told to stop once 5 tiles are in, as a launcher signals every process.
    o.render.should_stop = [&] { return done.load() >= 5; };
    return o;
  });
  ASSERT_EQ(results[0].outcome, DistributedOutcome::kInterrupted) << results[0].message;
  ASSERT_TRUE(checkpointed);  // the state is saved when a run ends early
  EXPECT_FALSE(saved.complete());
  // Go on from the saved state with another number of ranks: the same bits.
  Film resumed(scene.settings.width, scene.settings.height);
  results = run_ranks(2, scene, resumed, [&](int r) {
    DistributedOptions o;
    o.render = options_for(true, 2);
    o.agreement = 7;
    if (r == 0) o.render.progress = &saved;
    return o;
  });
  ASSERT_EQ(results[0].outcome, DistributedOutcome::kComplete) << results[0].message;
  EXPECT_TRUE(same_bits(resumed, reference));
}

// A channel that notes when its rank has sent its first message.
class NotingChannel final : public Channel {
 public:
  NotingChannel(std::unique_ptr<Channel> inner, std::atomic<bool>& sent) : m_inner(std::move(inner)), m_sent(sent) {}
  int rank() const override { return m_inner->rank(); }
  int size() const override { return m_inner->size(); }
  void send(int to, int tag, std::vector<std::uint8_t> bytes) override {
    m_inner->send(to, tag, std::move(bytes));
    m_sent = true;
  }
  std::optional<Message> receive(double seconds) override { return m_inner->receive(seconds); }
  void flush(double seconds) override { m_inner->flush(seconds); }

 private:
  std::unique_ptr<Channel> m_inner;
  std::atomic<bool>& m_sent;
};

// An on_progress for rank 0 that holds its render threads after each tile until `flag` is set (10 s
// at most), so that rank 0 cannot finish the image before the other rank has spoken, however late
// that rank starts. Only for runs whose other ranks send no results: those would call it from
// rank 0's message loop.
std::function<void(int, int)> wait_for(const std::atomic<bool>& flag) {
  return [&flag](int, int) {
    for (int i = 0; i < 1000 && !flag.load(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  };
}

TEST(DistributedRenderFaults, RankWithAnotherSceneIsRefusedByName) {
  const Scene scene = test_scene("box");
  auto channels = make_local_channels(2);
  std::atomic<bool> greeted{false};
  channels[1] = std::make_unique<NotingChannel>(std::move(channels[1]), greeted);
  Film film(scene.settings.width, scene.settings.height);
  const std::vector<DistributedResult> results = run_ranks(
      2, scene, film,
      [&](int r) {
        DistributedOptions o;
        o.render = options_for(true);
        o.agreement = r == 1 ? 99 : 1;
        if (r == 0) o.render.on_progress = wait_for(greeted);
        return o;
      },
      std::move(channels));
  EXPECT_EQ(results[0].outcome, DistributedOutcome::kFailed);
  EXPECT_NE(results[0].message.find("rank 1"), std::string::npos) << results[0].message;
  EXPECT_NE(results[0].message.find("another scene"), std::string::npos) << results[0].message;
  EXPECT_EQ(results[1].outcome, DistributedOutcome::kFailed);  // told to stop
}

TEST(DistributedRenderFaults, RankThatFailsBeforeRenderingIsNamedWithItsReason) {
  const Scene scene = test_scene("box");
  auto channels = make_local_channels(2);
  std::atomic<bool> reported{false};
  channels[1] = std::make_unique<NotingChannel>(std::move(channels[1]), reported);
  std::thread worker([&] { report_failure(*channels[1], "cannot read 'bunny.obj'", 10.0); });
  auto rank0 = make_rank(scene, options_for(true));
  Film film(scene.settings.width, scene.settings.height);
  DistributedOptions o;
  o.render = options_for(true);
  o.render.on_progress = wait_for(reported);
  const DistributedResult result = render_distributed(*channels[0], *rank0->renderer, film, o);
  worker.join();
  EXPECT_EQ(result.outcome, DistributedOutcome::kFailed);
  EXPECT_NE(result.message.find("rank 1 failed: cannot read 'bunny.obj'"), std::string::npos) << result.message;
}

// A channel that falls silent, as a killed process does, once it has received its first job
// (the first message with contents: heartbeats and the stop are empty).
class DyingChannel final : public Channel {
 public:
  DyingChannel(std::unique_ptr<Channel> inner, std::atomic<bool>& died) : m_inner(std::move(inner)), m_died(died) {}
  int rank() const override { return m_inner->rank(); }
  int size() const override { return m_inner->size(); }
  void send(int to, int tag, std::vector<std::uint8_t> bytes) override { m_inner->send(to, tag, std::move(bytes)); }
  std::optional<Message> receive(double seconds) override {
    std::optional<Message> m = m_inner->receive(seconds);
    if (m && !m->bytes.empty()) {
      silence(*m_inner);
      m_died = true;
    }
    return m;
  }
  void flush(double) override {}

 private:
  std::unique_ptr<Channel> m_inner;
  std::atomic<bool>& m_died;
};

TEST(DistributedRenderFaults, SilentRankHoldingTilesFailsTheRunNamingItsTiles) {
  const Scene scene = test_scene("box");
  auto channels = make_local_channels(2);
  std::atomic<bool> died{false};
  channels[1] = std::make_unique<DyingChannel>(std::move(channels[1]), died);
  std::atomic<bool> over{false};
  Film film(scene.settings.width, scene.settings.height);
  RenderProgress saved;
  const std::vector<DistributedResult> results = run_ranks(
      2, scene, film,
      [&](int r) {
        DistributedOptions o;
        o.render = options_for(true);
        o.rank_timeout_seconds = 2.0;  // well above a live rank's 1 s heartbeat
        if (r == 0) {
          o.render.on_checkpoint = [&](const RenderProgress& p) { saved = p; };
          o.on_stopping = [&](const std::string&) { over = true; };
          o.render.on_progress = wait_for(died);  // until rank 1 holds jobs (it never sends a result)
        }
        if (r == 1) o.render.should_stop = [&] { return over.load(); };  // ends the dead rank's thread
        return o;
      },
      std::move(channels));
  ASSERT_TRUE(died.load());
  ASSERT_EQ(results[0].outcome, DistributedOutcome::kFailed) << results[0].message;
  const std::string& m = results[0].message;
  EXPECT_NE(m.find("rank 1 has not answered"), std::string::npos) << m;
  EXPECT_NE(m.find("it held tile"), std::string::npos) << m;
  // The tiles it held are unfinished in the checkpoint; the finished ones are kept.
  ASSERT_EQ(saved.tile_count(), 12);
  EXPECT_FALSE(saved.complete());
  EXPECT_FALSE(saved.unfinished_tiles().empty());
}

TEST(DistributedFrames, EveryFrameArrivesOnceWithTheBitsOfALocalRender) {
  const Scene scene = test_scene("box");
  const int size = 3;
  auto channels = make_local_channels(size);
  std::vector<std::unique_ptr<Rank>> ranks;
  for (int r = 0; r < size; ++r) ranks.push_back(make_rank(scene, options_for(true)));
  // Frame f moves the camera sideways by f / 10.
  auto frame_scene = [](Scene s, int f) {
    s.camera.from.x += 0.1f * static_cast<float>(f);
    return s;
  };
  std::vector<int> delivered;
  std::vector<Film> films(8, Film(0, 0));
  std::vector<FramesResult> results(static_cast<std::size_t>(size));
  auto options_of = [&](int r) {
    FramesOptions o;
    o.frames = {0, 1, 2, 3, 4, 5, 6, 7};
    o.render_frame = [&, r](int f) {
      Rank& rank = *ranks[static_cast<std::size_t>(r)];
      rank.scene = frame_scene(scene, f);
      RenderedFrame out;
      out.frame = f;
      out.film = Film(scene.settings.width, scene.settings.height);
      out.result = render(rank.scene, *rank.accel, out.film, options_for(true));
      return out;
    };
    if (r == 0) {
      o.on_frame = [&](const RenderedFrame& f) {
        delivered.push_back(f.frame);
        films[static_cast<std::size_t>(f.frame)] = f.film;
      };
    }
    return o;
  };
  std::vector<std::thread> threads;
  for (int r = 1; r < size; ++r) {
    threads.emplace_back([&, r] {
      results[static_cast<std::size_t>(r)] =
          render_frames_distributed(*channels[static_cast<std::size_t>(r)], options_of(r));
    });
  }
  results[0] = render_frames_distributed(*channels[0], options_of(0));
  for (std::thread& t : threads) t.join();
  ASSERT_EQ(results[0].outcome, DistributedOutcome::kComplete) << results[0].message;
  std::sort(delivered.begin(), delivered.end());
  EXPECT_EQ(delivered, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  for (int f = 0; f < 8; ++f) {
    SCOPED_TRACE(f);
    EXPECT_TRUE(same_bits(films[static_cast<std::size_t>(f)], local_render(frame_scene(scene, f), options_for(true))));
  }
  int frames = 0;
  for (const RankReport& r : results[0].ranks) frames += r.jobs;
  EXPECT_EQ(frames, 8);
}

TEST(DistributedRender, LoadImbalanceIsBusiestOverMean) {
  std::vector<RankReport> ranks(2);
  ranks[0].busy_seconds = 3;
  ranks[1].busy_seconds = 1;
  EXPECT_DOUBLE_EQ(load_imbalance(ranks), 1.5);
  ranks[1].busy_seconds = 3;
  EXPECT_DOUBLE_EQ(load_imbalance(ranks), 1.0);
}

}  // namespace
}  // namespace raylab::dist
