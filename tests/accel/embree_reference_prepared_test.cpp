// EmbreeReference's prepared records (the bench's timing path for Embree): single records traced
// in any split into ranges, and packets of 16 in ranges starting on a packet, reset and traced
// again, answer exactly as the per-ray loop and the packet loop do.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <vector>

#include "raylab/accel/embree_reference.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

bool same_hit(const Hit& a, const Hit& b) {
  return a.prim_id == b.prim_id && std::bit_cast<std::uint32_t>(a.t) == std::bit_cast<std::uint32_t>(b.t) &&
         std::bit_cast<std::uint32_t>(a.u) == std::bit_cast<std::uint32_t>(b.u) &&
         std::bit_cast<std::uint32_t>(a.v) == std::bit_cast<std::uint32_t>(b.v);
}

TEST(EmbreeReferencePrepared, AnswersAsThePerRayLoopInAnySplitAndAfterAReset) {
  if (!embree_reference_available()) GTEST_SKIP() << "built without Embree";
  Sampler s(41);
  const Geometry g = every_shape_kind(s);  // triangles and user geometry
  std::vector<Ray> rays = random_rays(g, s, 500);
  for (std::size_t i = 0; i < rays.size(); i += 7) rays[i].tmax = 0.5f;  // some stop short
  EmbreeReference ref(g);

  std::vector<Hit> want(rays.size());
  std::vector<std::uint8_t> want_occluded(rays.size());
  ref.intersect1(rays, want);
  ref.occluded1(rays, want_occluded);
  int hits = 0;
  for (const Hit& h : want) hits += h.valid() ? 1 : 0;
  ASSERT_GT(hits, 100);  // a wrong answer must be able to show

  ref.prepare(rays);
  for (int pass = 0; pass < 2; ++pass) {
    // Ranges of uneven lengths, as the bench's threads take them.
    for (std::size_t b = 0, step = 1; b < rays.size(); b += step, step = step * 2 + 1) {
      ref.intersect1_prepared(b, std::min(rays.size(), b + step));
    }
    std::vector<Hit> got(rays.size());
    ref.prepared_hits(got);
    for (std::size_t i = 0; i < rays.size(); ++i)
      EXPECT_TRUE(same_hit(got[i], want[i])) << "pass " << pass << ", ray " << i;
    ref.reset_prepared(0, rays.size());

    ref.occluded1_prepared(0, rays.size());
    std::vector<std::uint8_t> occluded(rays.size(), 7);
    ref.prepared_occluded(occluded);
    EXPECT_EQ(occluded, want_occluded) << "pass " << pass;
    ref.reset_prepared(0, rays.size());
  }
}

TEST(EmbreeReferencePrepared, PacketsAnswerAsThePacketLoopInRangesAndAfterAReset) {
  if (!embree_reference_available()) GTEST_SKIP() << "built without Embree";
  Sampler s(42);
  const Geometry g = every_shape_kind(s);
  std::vector<Ray> rays = random_rays(g, s, 203);  // not a multiple of 16: the last packet masked
  EmbreeReference ref(g);
  std::vector<Hit> want(rays.size());
  std::vector<std::uint8_t> want_occluded(rays.size());
  ref.intersect16(rays, want);
  ref.occluded16(rays, want_occluded);
  int hits = 0;
  for (const Hit& h : want) hits += h.valid() ? 1 : 0;
  ASSERT_GT(hits, 40);

  ref.prepare(rays, true);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t b = 0; b < rays.size(); b += 48) ref.intersect16_prepared(b, std::min(rays.size(), b + 48));
    std::vector<Hit> got(rays.size());
    ref.prepared_hits(got);
    for (std::size_t i = 0; i < rays.size(); ++i)
      EXPECT_TRUE(same_hit(got[i], want[i])) << "pass " << pass << ", ray " << i;
    ref.reset_prepared(0, rays.size());

    ref.occluded16_prepared(0, rays.size());
    std::vector<std::uint8_t> occluded(rays.size(), 7);
    ref.prepared_occluded(occluded);
    EXPECT_EQ(occluded, want_occluded) << "pass " << pass;
    ref.reset_prepared(0, rays.size());
  }
}

}  // namespace
}  // namespace raylab
