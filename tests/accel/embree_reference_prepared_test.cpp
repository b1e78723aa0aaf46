// EmbreeReference's prepared records (the bench's timing path for Embree): single records traced
// in any split into ranges, and packets of 16 in ranges starting on a packet, reset and traced
// again, answer exactly as the per-ray loop and the packet loop do.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/embree_reference.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// Traces `rays` prepared as singles or packets twice (a reset between), closest hit in the
// ranges `next_end(begin)` cuts and any hit in one range, and holds every answer to those of
// the unprepared loop of the same kind.
template <class NextEnd>
void check_prepared(std::uint64_t seed, int count, bool packets, int min_hits, NextEnd next_end) {
  Sampler s(seed);
  const Geometry g = every_shape_kind(s);  // triangles and user geometry
  std::vector<Ray> rays = random_rays(g, s, count);
  for (std::size_t i = 0; i < rays.size(); i += 7) rays[i].tmax = 0.5f;  // some stop short
  EmbreeReference ref(g);
  std::vector<Hit> want(rays.size());
  std::vector<std::uint8_t> want_occluded(rays.size());
  packets ? ref.intersect16(rays, want) : ref.intersect1(rays, want);
  packets ? ref.occluded16(rays, want_occluded) : ref.occluded1(rays, want_occluded);
  int hits = 0;
  for (const Hit& h : want) hits += h.valid() ? 1 : 0;
  ASSERT_GT(hits, min_hits);  // a wrong answer must be able to show

  ref.prepare(rays, packets);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t b = 0; b < rays.size();) {
      const std::size_t e = std::min(rays.size(), next_end(b));
      packets ? ref.intersect16_prepared(b, e) : ref.intersect1_prepared(b, e);
      b = e;
    }
    std::vector<Hit> got(rays.size());
    ref.prepared_hits(got);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      EXPECT_TRUE(same_hit(got[i], want[i])) << "pass " << pass << ", ray " << i;
    }
    ref.reset_prepared(0, rays.size());

    packets ? ref.occluded16_prepared(0, rays.size()) : ref.occluded1_prepared(0, rays.size());
    std::vector<std::uint8_t> occluded(rays.size(), 7);
    ref.prepared_occluded(occluded);
    EXPECT_EQ(occluded, want_occluded) << "pass " << pass;
    ref.reset_prepared(0, rays.size());
  }
}

TEST(EmbreeReferencePrepared, SinglesAnswerAsThePerRayLoopInAnySplitAndAfterAReset) {
  if (!embree_reference_available()) GTEST_SKIP() << "built without Embree";
  // Ranges of uneven lengths (1, 3, 7, ...), as the bench's threads may take them.
  std::size_t step = 0;
  check_prepared(41, 500, false, 100, [&](std::size_t b) { return b + (step = step * 2 + 1); });
}

TEST(EmbreeReferencePrepared, PacketsAnswerAsThePacketLoopInRangesAndAfterAReset) {
  if (!embree_reference_available()) GTEST_SKIP() << "built without Embree";
  // 203 rays: not a multiple of 16, so the last packet is masked; ranges of three packets.
  check_prepared(42, 203, true, 40, [](std::size_t b) { return b + 48; });
}

}  // namespace
}  // namespace raylab
