// The quality study on a tiny scene: error falls with samples, a reference made like a row
// measures zero for it, the plan (seeds, budgets) follows the samplers' nature, and auto
// references are cached under a key that changes with what changes the image.

#include "raylab/lab/quality_study.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "../test_util.h"
#include "raylab/accel/two_level.h"
#include "raylab/core/error.h"
#include "raylab/io/image_io.h"
#include "raylab/io/scene_loader.h"
#include "raylab/lab/quality_reference.h"
#include "raylab/render/renderer.h"
#include "raylab/sampling/pixel_sampler.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

// The demo scene at 32 x 24 with its structure.
struct TinyScene {
  Scene scene;
  std::unique_ptr<Accelerator> accel;

  TinyScene() : scene(load_scene("demo")) {
    scene.settings.width = 32;
    scene.settings.height = 24;
    accel = make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, SceneAccelOptions{});
  }
};

QualityOptions small_options() {
  QualityOptions o;
  o.reference_spp = 64;
  o.threads = 2;
  return o;
}

class QualityCache : public ::testing::Test {
 protected:
  void SetUp() override {
    m_dir = fs::temp_directory_path() / ("raylab-quality-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(m_dir);
  }
  void TearDown() override { fs::remove_all(m_dir); }
  fs::path m_dir;
};

TEST(QualityStudy, JitteredErrorFallsWithTheSampleCount) {
  const TinyScene t;
  QualityOptions o = small_options();
  const Film reference = render_reference(t.scene, *t.accel, o);
  o.samplers = {"jittered"};
  o.budgets = {16, 1, 4};  // reported ascending
  o.seeds = 2;
  const QualityResult r = run_quality_study(t.scene, *t.accel, reference, o);
  ASSERT_EQ(r.rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const QualityRow& row = r.rows[i];
    EXPECT_EQ(row.budget, (std::array{1, 4, 16})[i]);
    EXPECT_EQ(row.spp, row.budget);
    EXPECT_EQ(row.seeds, 2);
    EXPECT_DOUBLE_EQ(row.rays_per_pixel, row.budget);  // one primary ray per sample
    EXPECT_GT(row.rmse, 0.0);
    EXPECT_LE(row.rmse_min, row.rmse);
    EXPECT_GE(row.rmse_max, row.rmse);
    EXPECT_LT(row.ssim, 1.0);
    EXPECT_GE(row.p999, row.rmse);  // below 1000 pixels the percentile is the largest error
  }
  EXPECT_GT(r.rows[0].rmse, r.rows[1].rmse);
  EXPECT_GT(r.rows[1].rmse, r.rows[2].rmse);
  EXPECT_LT(r.rows[0].psnr, r.rows[2].psnr);
  EXPECT_LT(r.rows[0].ssim, r.rows[2].ssim);
  EXPECT_EQ(r.width, 32);
  EXPECT_EQ(r.height, 24);
}

TEST(QualityStudy, AReferenceRenderedLikeARowMeasuresZeroForIt) {
  const TinyScene t;
  Scene same = t.scene;
  same.settings.sampler = "jittered";
  same.settings.spp = 4;
  same.settings.seed = 0;
  Film reference(32, 24);
  render(same, *t.accel, reference);
  QualityOptions o = small_options();
  o.samplers = {"jittered"};
  o.budgets = {4, 16};
  o.seeds = 1;
  const QualityResult r = run_quality_study(t.scene, *t.accel, reference, o);
  ASSERT_EQ(r.rows.size(), 2u);
  EXPECT_EQ(r.rows[0].rmse, 0.0);
  EXPECT_EQ(r.rows[0].rmse_max, 0.0);
  EXPECT_EQ(r.rows[0].p999, 0.0);
  EXPECT_EQ(r.rows[0].ssim, 1.0);
  EXPECT_TRUE(std::isinf(r.rows[0].psnr));
  EXPECT_GT(r.rows[1].rmse, 0.0);  // another sample set is not the same image
}

TEST(QualityStudy, DeterministicSamplersRunOneSeedAndCenterOneBudget) {
  const TinyScene t;
  QualityOptions o = small_options();
  o.samplers = {"center", "regular", "jittered"};
  o.budgets = {4, 1};
  o.seeds = 3;
  const QualityResult r = run_quality_study(t.scene, *t.accel, render_reference(t.scene, *t.accel, o), o);
  ASSERT_EQ(r.rows.size(), 5u);  // center 1; regular 1, 4; jittered 1, 4
  EXPECT_EQ(r.rows[0].sampler, "center");
  EXPECT_EQ(r.rows[0].budget, 1);
  EXPECT_EQ(r.rows[0].seeds, 1);
  for (std::size_t i = 1; i < 5; ++i) {
    EXPECT_EQ(r.rows[i].seeds, r.rows[i].sampler == "regular" ? 1 : 3) << r.rows[i].sampler;
    EXPECT_DOUBLE_EQ(r.rows[i].rays_per_pixel, r.rows[i].spp) << r.rows[i].sampler;
  }
  EXPECT_EQ(r.rows[0].rmse_min, r.rows[0].rmse_max);  // one seed: no spread
  EXPECT_EQ(r.rows[0].rmse_stddev, 0.0);
  EXPECT_NE(r.find("jittered", 4), nullptr);
  EXPECT_EQ(r.find("center", 4), nullptr);
}

TEST(QualityStudy, AdaptiveRowsCountTheRaysTheyTraced) {
  const TinyScene t;
  QualityOptions o = small_options();
  o.reference_spp = 16;
  o.samplers = {"adaptive-corners", "adaptive"};
  o.budgets = {4};
  o.seeds = 2;
  const QualityResult r = run_quality_study(t.scene, *t.accel, render_reference(t.scene, *t.accel, o), o);
  ASSERT_EQ(r.rows.size(), 2u);
  EXPECT_EQ(r.rows[0].seeds, 1);  // corner rays do not depend on the seed
  EXPECT_EQ(r.rows[1].seeds, 2);
  for (const QualityRow& row : r.rows) {
    EXPECT_EQ(row.spp, 4) << row.sampler;
    EXPECT_GT(row.rays_per_pixel, 0.0) << row.sampler;
    EXPECT_GT(row.rmse, 0.0) << row.sampler;
  }
  // The filter rule is checked before any work: adaptive samplers weight samples in the pixel.
  TinyScene tent;
  tent.scene.settings.filter = "tent";
  EXPECT_THROW(run_quality_study(tent.scene, *tent.accel, Film(32, 24), o), UsageError);
}

TEST(QualityStudy, UsedSppFollowsTheSamplers) {
  EXPECT_EQ(used_spp("center", 64), 1);
  EXPECT_EQ(used_spp("jittered", 10), valid_spp("jittered", 10));
  EXPECT_EQ(used_spp("sobol", 16), 16);
  EXPECT_EQ(used_spp("adaptive", 10), 10);  // the most per pixel, as asked
  EXPECT_TRUE(sampler_is_deterministic("adaptive-corners"));
  EXPECT_FALSE(sampler_is_deterministic("adaptive"));
  EXPECT_EQ(quality_sampler_names().size(), 8u);
}

TEST(QualityStudy, BadOptionsAreUsageErrors) {
  const TinyScene t;
  const Film reference(32, 24);
  QualityOptions o = small_options();
  o.samplers = {"jittered", "stratified"};
  test::expect_contains_all(
      test::thrown_message<UsageError>([&] { run_quality_study(t.scene, *t.accel, reference, o); }),
      {"'stratified'", "adaptive-corners"});
  o = small_options();
  o.budgets = {4, 4};
  EXPECT_THROW(validate_quality_options(o), UsageError);
  o.budgets = {0};
  EXPECT_THROW(validate_quality_options(o), UsageError);
  o = small_options();
  o.seeds = 0;
  EXPECT_THROW(validate_quality_options(o), UsageError);
  EXPECT_EQ(parse_budget_list("1, 4,16"), (std::vector<int>{1, 4, 16}));
  for (const char* bad : {"1,x", "1,,4", "", "2.5", "-1", "99999999999"}) {
    EXPECT_THROW(parse_budget_list(bad), UsageError) << bad;
  }
  EXPECT_EQ(parse_sampler_list("cmj,adaptive"), (std::vector<std::string>{"cmj", "adaptive"}));
  EXPECT_THROW(parse_sampler_list("cmj,foo"), UsageError);
  // A reference of another size: InputError naming both sizes.
  try {
    run_quality_study(t.scene, *t.accel, Film(16, 12), small_options());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("16x12"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("32x24"), std::string::npos) << e.what();
  }
}

TEST(QualityStudy, BarRatiosAndReports) {
  QualityResult r;
  r.width = 8;
  r.height = 4;
  r.filter = "box";
  r.seeds = 2;
  QualityRow j{"jittered", 16, 16, 2, 16.0, 2.0, 0.04, 0.03, 0.05, 0.01, 30.0, 0.9, 0.4};
  QualityRow a{"adaptive", 16, 16, 2, 4.0, 0.5, 0.03, 0.02, 0.04, 0.01, 31.0, 0.92, 0.2};
  QualityRow c{"center", 1, 1, 1, 1.0, 0.1, 0.2, 0.2, 0.2, 0.0, INFINITY, 0.5, 1.0};
  r.rows = {c, j, a};
  const std::optional<BarRatios> b = bar_ratios(r);
  ASSERT_TRUE(b);
  EXPECT_DOUBLE_EQ(b->rays, 0.25);
  EXPECT_DOUBLE_EQ(b->rmse, 0.75);
  EXPECT_DOUBLE_EQ(b->p999, 0.5);
  EXPECT_DOUBLE_EQ(b->time, 0.25);
  EXPECT_DOUBLE_EQ(b->time_at_equal_rmse, 0.25);  // one row, below the target: its time bounds it
  EXPECT_EQ(format_bar_ratios(*b),
            "adaptive (budget 16) vs jittered at 16 spp: primary rays x0.250, RMSE x0.750, p99.9 x0.500, "
            "time x0.250, time at equal RMSE x0.250");
  EXPECT_FALSE(bar_ratios(r, "adaptive", "jittered", 4));
  EXPECT_FALSE(bar_ratios(r, "sobol"));

  // A cheaper adaptive row that errs more: the time at equal RMSE lies between the two rows,
  // log-log; the row compared stays the cheapest one that errs no more than the baseline.
  QualityResult r2 = r;
  r2.rows.push_back(QualityRow{"adaptive", 4, 4, 2, 2.0, 0.2, 0.08, 0.07, 0.09, 0.01, 25.0, 0.8, 0.6});
  const std::optional<BarRatios> b2 = bar_ratios(r2);
  ASSERT_TRUE(b2);
  EXPECT_EQ(b2->budget, 16);
  const double f = (std::log(0.04) - std::log(0.08)) / (std::log(0.03) - std::log(0.08));
  EXPECT_NEAR(b2->time_at_equal_rmse, std::exp(std::log(0.2) + f * (std::log(0.5) - std::log(0.2))) / 2.0, 1e-12);
  // No row reaches the baseline: the lowest-RMSE row is compared and the time is NaN.
  r2.rows[2].rmse = 0.05;
  const std::optional<BarRatios> b3 = bar_ratios(r2);
  ASSERT_TRUE(b3);
  EXPECT_EQ(b3->budget, 16);
  EXPECT_TRUE(std::isnan(b3->time_at_equal_rmse));

  const std::string table = format_quality_table(r, "demo");
  for (const char* s : {"center", "jittered", "adaptive", "inf"}) EXPECT_NE(table.find(s), std::string::npos) << s;
  const std::string csv = format_quality_csv(r);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
  EXPECT_NE(csv.find("\ncenter,1,1,1,1,0.1,0.2,0.2,0.2,0,inf,0.5,1\n"), std::string::npos) << csv;
  const std::string json = format_quality_json(r, "demo \"x\"");
  EXPECT_NE(json.find("\"scene\": \"demo \\\"x\\\"\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"psnr_db\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"rays_ratio\": 0.25"), std::string::npos) << json;
}

TEST_F(QualityCache, AutoReferenceIsRenderedOnceThenReused) {
  const TinyScene t;
  QualityOptions o = small_options();
  o.reference_spp = 16;
  o.cache_dir = (m_dir / "cache" / "refs").string();  // created, parents included
  o.reference_key = "demo";
  const ReferenceImage first = obtain_reference(t.scene, *t.accel, o);
  EXPECT_TRUE(first.rendered);
  EXPECT_FALSE(first.from_cache);
  ASSERT_TRUE(fs::is_regular_file(first.path)) << first.path;
  EXPECT_EQ(fs::path(first.path).filename().string(), reference_file_name(t.scene.settings, o));
  EXPECT_EQ(first.film.pixels(), render_reference(t.scene, *t.accel, o).pixels());  // deterministic
  const auto stamp = fs::last_write_time(first.path);

  const ReferenceImage second = obtain_reference(t.scene, *t.accel, o);
  EXPECT_TRUE(second.from_cache);
  EXPECT_FALSE(second.rendered);
  EXPECT_EQ(second.path, first.path);
  EXPECT_EQ(fs::last_write_time(second.path), stamp);
  EXPECT_EQ(second.film.pixels(), first.film.pixels());  // EXR floats: bit-exact
  EXPECT_NE(second.description.find("cached"), std::string::npos);

  // What changes the image changes the file; the file name is all the key there is.
  QualityOptions other_key = o;
  other_key.reference_key = "demo hash64:0123456789abcdef";
  EXPECT_NE(reference_file_name(t.scene.settings, other_key), reference_file_name(t.scene.settings, o));
  RenderSettings wider = t.scene.settings;
  wider.width = 33;
  EXPECT_NE(reference_file_name(wider, o), reference_file_name(t.scene.settings, o));
  RenderSettings tent = t.scene.settings;
  tent.filter = "tent";
  EXPECT_NE(reference_file_name(tent, o), reference_file_name(t.scene.settings, o));
  QualityOptions more = o;
  more.reference_spp = 64;
  EXPECT_NE(reference_file_name(t.scene.settings, more), reference_file_name(t.scene.settings, o));
  // Not the study's own settings: those are replaced for the reference.
  RenderSettings other_sampler = t.scene.settings;
  other_sampler.sampler = "sobol";
  other_sampler.spp = 7;
  EXPECT_EQ(reference_file_name(other_sampler, o), reference_file_name(t.scene.settings, o));

  const ReferenceImage third = obtain_reference(t.scene, *t.accel, other_key);
  EXPECT_TRUE(third.rendered);
  EXPECT_NE(third.path, first.path);
  EXPECT_EQ(std::distance(fs::directory_iterator(o.cache_dir), fs::directory_iterator()), 2);
}

TEST_F(QualityCache, ABrokenCachedFileIsRenderedAgain) {
  const TinyScene t;
  QualityOptions o = small_options();
  o.reference_spp = 16;
  o.cache_dir = m_dir.string();
  fs::create_directories(m_dir);
  const fs::path file = m_dir / reference_file_name(t.scene.settings, o);
  std::ofstream(file) << "not an EXR";
  const ReferenceImage r = obtain_reference(t.scene, *t.accel, o);
  EXPECT_TRUE(r.rendered);
  EXPECT_EQ(read_image(file.string()).pixels(), r.film.pixels());
}

TEST_F(QualityCache, GivenReferencesAreCheckedForSizeAndFormat) {
  const TinyScene t;
  fs::create_directories(m_dir);
  QualityOptions o = small_options();
  o.reference = (m_dir / "small.exr").string();
  write_image(Film(16, 12), o.reference);
  try {
    obtain_reference(t.scene, *t.accel, o);
    FAIL();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("16x12"), std::string::npos) << msg;
    EXPECT_NE(msg.find("32x24"), std::string::npos) << msg;
    EXPECT_NE(msg.find("small.exr"), std::string::npos) << msg;
  }
  o.reference = (m_dir / "right.pfm").string();
  write_image(Film(32, 24), o.reference);
  const ReferenceImage r = obtain_reference(t.scene, *t.accel, o);
  EXPECT_FALSE(r.rendered);
  EXPECT_EQ(r.path, o.reference);
  o.reference = (m_dir / "missing.exr").string();
  EXPECT_THROW(obtain_reference(t.scene, *t.accel, o), InputError);
  EXPECT_THROW(load_reference_file((m_dir / "ref.png").string()), UsageError);
}

TEST(QualityReference, SourceKeysHashFileContents) {
  EXPECT_EQ(scene_source_key("spd:balls?size=2"), "spd:balls?size=2");
  const fs::path p = fs::temp_directory_path() / ("raylab-key-" + std::to_string(::getpid()) + ".nff");
  std::ofstream(p) << "v\n";
  const std::string a = scene_source_key(p.string());
  std::ofstream(p) << "v\nb 0 0 0\n";
  const std::string b = scene_source_key(p.string());
  fs::remove(p);
  EXPECT_TRUE(a.starts_with(p.string() + " hash64:")) << a;
  EXPECT_NE(a, b);
}

TEST(QualityReference, DefaultCacheFolderFollowsXdgThenHome) {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  const std::string saved_xdg = xdg ? xdg : "", saved_home = home ? home : "";
  ::setenv("XDG_CACHE_HOME", "/x/cache", 1);
  EXPECT_EQ(default_reference_cache_dir(), "/x/cache/raylab/references");
  ::setenv("XDG_CACHE_HOME", "", 1);
  ::setenv("HOME", "/home/u", 1);
  EXPECT_EQ(default_reference_cache_dir(), "/home/u/.cache/raylab/references");
  ::unsetenv("HOME");
  ::unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(default_reference_cache_dir(), ".raylab-cache");
  if (xdg) ::setenv("XDG_CACHE_HOME", saved_xdg.c_str(), 1);
  if (home) ::setenv("HOME", saved_home.c_str(), 1);
}

}  // namespace
}  // namespace raylab
