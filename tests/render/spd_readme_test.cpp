// raylab's SPD protocol against the statistics table of the SPD README (Readme.txt of SPD 3.14),
// which nobody here wrote: every scene at the size the table counted, every column within 1%.
// One cell is the exception, with its reason below.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "raylab/accel/factory.h"
#include "raylab/render/spd_statistics.h"
#include "raylab/scene/spd.h"

namespace raylab {
namespace {

SpdProtocolCounts counts_at(const SpdPublishedRow& row, ShadowFacing facing = ShadowFacing::kViewer) {
  Scene scene = make_spd_scene("spd:" + std::string(row.scene) + "?size=" + std::to_string(row.size));
  const auto accel = make_accelerator("bvh", scene.geometry);
  Film film(kSpdProtocolSize, kSpdProtocolSize);
  RenderOptions options;
  options.threads = 2;
  return render_spd_protocol(scene, *accel, film, options, facing).counts;
}

// The one figure raylab does not meet within 1%, and by how much it may differ: gears' refraction
// rays are 3.2% fewer than the README's. Rule 9 spawns no refraction ray on total internal
// reflection, which happens at 7,582 of gears' 208,597 transmitter hits (index 1.1: beyond 65.4
// degrees inside, as at the teeth's side faces). The README's 207,564 lies within 0.5% of the
// transmitter hits, refraction + total internal reflections, which the test below asserts: the
// README's tracer evidently counted a refraction ray (or none was lost to total internal
// reflection) at nearly every transmitter hit. See docs/spd.md.
constexpr double kGearsRefractionTolerance = 0.035;

class SpdReadme : public ::testing::TestWithParam<std::string> {};

TEST_P(SpdReadme, ProtocolCountsMatchTheReadmeTableWithinOnePercent) {
  const SpdPublishedTable& table = spd_readme_table();
  const SpdPublishedRow* row = nullptr;
  for (const SpdPublishedRow& r : table.rows) {
    if (r.scene == GetParam()) row = &r;
  }
  ASSERT_NE(row, nullptr);
  const SpdProtocolCounts counts = counts_at(*row);
  EXPECT_EQ(counts.primary, 513u * 513u);
  const auto comparisons = compare_with_published(counts, *row);
  ASSERT_EQ(comparisons.size(), 4u);  // eye hits, reflection, refraction, shadow
  for (const SpdCountComparison& c : comparisons) {
    SCOPED_TRACE(std::string(c.column));
    const bool gears_refraction = row->scene == "gears" && c.column == "refraction";
    const double tolerance = gears_refraction ? kGearsRefractionTolerance : 0.01;
    EXPECT_LE(std::abs(c.ratio() - 1.0), tolerance) << "raylab " << c.ours << ", README " << c.published;
    if (c.published == 0) {
      EXPECT_EQ(c.ours, 0u);
    }
  }
  if (row->scene == "gears") {
    const double transmitter_hits = static_cast<double>(counts.refraction + counts.total_internal_reflections);
    EXPECT_LE(std::abs(transmitter_hits / static_cast<double>(*row->refraction) - 1.0), 0.01);
    EXPECT_GT(counts.total_internal_reflections, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(AllSeven, SpdReadme,
                         ::testing::Values("balls", "gears", "mount", "rings", "teapot", "tetra", "tree"));

// The README's teapot is size 12: 32 x 2 x 12^2 - 8 x 12 = 9,120 patch triangles and 12^2 = 144
// checker squares, the 9,264 primitives its table lists.
TEST(SpdPublished, TeapotAtSizeTwelveHasTheTablesPrimitives) {
  const Scene scene = make_spd_scene("spd:teapot?size=12");
  EXPECT_EQ(scene.geometry.triangles.size(), 9120u + 2u * 144u);  // each square as two triangles
  EXPECT_NE(spd_readme_table().find("teapot", 12), nullptr);      // the table is keyed by that size
  EXPECT_EQ(spd_readme_table().find("teapot", 6), nullptr);
}

// Havran & Sixta's shadow counts follow the other reading of rule 10: on mount, whose glass
// spheres are hit from inside at 356,204 points, the outward normal gives their shadow rays within
// 1% and the viewer-facing one 15% too many.
TEST(SpdPublished, HavranAndSixtaCountShadowRaysByTheOutwardNormal) {
  const SpdPublishedRow& row = *havran_sixta_table().find("mount", 6);
  const double outward = static_cast<double>(counts_at(row, ShadowFacing::kOutward).shadow);
  const double viewer = static_cast<double>(counts_at(row, ShadowFacing::kViewer).shadow);
  EXPECT_LE(std::abs(outward / static_cast<double>(*row.shadow) - 1.0), 0.01);
  EXPECT_GT(viewer / static_cast<double>(*row.shadow) - 1.0, 0.1);
}

}  // namespace
}  // namespace raylab
