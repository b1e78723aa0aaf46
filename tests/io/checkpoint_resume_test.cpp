// Resuming a checkpoint: what a render leaves unsaid comes from the checkpoint, what it says wins,
// a damaged value is an input error naming the setting, and a render that differs is refused.
// The names the resume reads are the ones image_settings writes.

#include <gtest/gtest.h>

#include <string>

#include "raylab/core/error.h"
#include "raylab/io/checkpoint_resume.h"
#include "raylab/io/setting_names.h"

namespace raylab {
namespace {

RenderCheckpoint saved_render() {
  const RenderSettings s{.width = 37,
                         .height = 21,
                         .spp = 8,
                         .filter = "tent",
                         .filter_radius = 1.25f,
                         .max_depth = 3,
                         .seed = 12345678901234ull};
  return RenderCheckpoint{"scenes/cornell.json", 7, image_settings(s, "jittered", 16, 2, "grid"), {}};
}

TEST(CheckpointResume, FillsWhatIsNotGiven) {
  ResumableRequest r;
  fill_from_checkpoint(r, saved_render(), "x.ckpt");
  EXPECT_EQ(r.scene, "scenes/cornell.json");
  EXPECT_EQ(r.accel, "grid");
  EXPECT_EQ(r.passes, 2);
  EXPECT_EQ(r.settings.width, 37);
  EXPECT_EQ(r.settings.height, 21);
  EXPECT_EQ(r.settings.spp, 8);
  EXPECT_EQ(r.settings.max_depth, 3);
  EXPECT_EQ(r.settings.seed, 12345678901234ull);
  EXPECT_EQ(r.settings.sampler, "jittered");
  EXPECT_EQ(r.settings.filter, "tent");
  EXPECT_EQ(r.settings.filter_radius, 1.25f);
  EXPECT_FALSE(r.settings.aa_threshold);
  EXPECT_FALSE(r.settings.aa_depth);
}

TEST(CheckpointResume, WhatIsGivenWins) {
  ResumableRequest r;
  r.scene = "demo";
  r.accel = "bvh";
  r.settings.spp = 64;
  fill_from_checkpoint(r, saved_render(), "x.ckpt");
  EXPECT_EQ(r.scene, "demo");
  EXPECT_EQ(r.accel, "bvh");
  EXPECT_EQ(r.settings.spp, 64);
  EXPECT_EQ(r.settings.width, 37);
}

TEST(CheckpointResume, SettingsNotRecordedStayEmpty) {
  RenderCheckpoint saved;
  saved.scene = "demo";
  saved.settings = {{setting_name::kSpp, "4"}};
  ResumableRequest r;
  fill_from_checkpoint(r, saved, "x.ckpt");
  EXPECT_EQ(r.settings.spp, 4);
  EXPECT_FALSE(r.settings.width);
  EXPECT_FALSE(r.accel);
  EXPECT_FALSE(r.passes);
}

TEST(CheckpointResume, ABadValueNamesTheSetting) {
  RenderCheckpoint saved = saved_render();
  for (auto& [name, value] : saved.settings) {
    if (name == setting_name::kMaxDepth) value = "deep";
  }
  ResumableRequest r;
  try {
    fill_from_checkpoint(r, saved, "x.ckpt");
    FAIL() << "a bad value was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.ckpt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the checkpoint's setting 'max depth' is not a valid value"),
              std::string::npos)
        << e.what();
  }
}

TEST(CheckpointResume, ADifferentRenderIsRefusedWithEveryDifference) {
  const RenderCheckpoint saved = saved_render();
  EXPECT_NO_THROW(check_resumable(saved, saved, "x.ckpt"));
  RenderCheckpoint now = saved;
  now.settings[2].second = "64";
  try {
    check_resumable(saved, now, "x.ckpt");
    FAIL() << "a different render was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("cannot resume: this render differs from the checkpoint's\n  spp: 8 in the checkpoint, 64 now"),
              std::string::npos)
        << m;
  }
}

}  // namespace
}  // namespace raylab
