// Checkpoint files: what is written is read back bit for bit; a damaged, cut or foreign file is
// refused with the byte where it goes wrong, never half-read; the differences a resume would
// refuse are named. And the scene fingerprint that a checkpoint records: equal for equal scenes,
// different after any change that could change the image.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/core/hash64.h"
#include "raylab/io/checkpoint_file.h"
#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/scene_fingerprint.h"

namespace raylab {
namespace {

// A checkpoint with every field set to something recognisable: tiles half done, sums that are
// each their own value.
RenderCheckpoint sample_checkpoint(int margin) {
  RenderCheckpoint c;
  c.scene = "scenes/cornell.json";
  c.scene_fingerprint = 0x0123456789ABCDEFull;
  c.settings = {{"width", "37"}, {"height", "21"}, {"spp", "8"}, {"sampler", "jittered"}};
  c.progress = start_progress(37, 21, 8, 8, 2, margin);
  c.progress.passes_done = 1;
  float value = 0.25f;
  for (int t = 0; t < c.progress.tile_count(); ++t) {
    c.progress.tile_done[static_cast<std::size_t>(t)] = t % 2;
    for (Color& s : c.progress.tiles[static_cast<std::size_t>(t)].sum) {
      s = Color{value, -value, value * 0.5f};
      value += 1.f;
    }
    for (float& w : c.progress.tiles[static_cast<std::size_t>(t)].weight) w = value++;
  }
  return c;
}

// A checkpoint's header and its progress but for the tiles' sums, as one value to compare.
auto header_and_counters(const RenderCheckpoint& c) {
  const RenderProgress& p = c.progress;
  return std::tie(c.scene, c.scene_fingerprint, c.settings, p.width, p.height, p.tile_size, p.spp, p.passes, p.margin,
                  p.passes_done, p.tile_done);
}

void expect_same(const RenderCheckpoint& a, const RenderCheckpoint& b) {
  EXPECT_EQ(header_and_counters(a), header_and_counters(b));
  const RenderProgress &p = a.progress, &q = b.progress;
  ASSERT_EQ(p.tiles.size(), q.tiles.size());
  for (std::size_t t = 0; t < p.tiles.size(); ++t) {
    ASSERT_EQ(p.tiles[t].sum.size(), q.tiles[t].sum.size());
    EXPECT_EQ(std::memcmp(p.tiles[t].sum.data(), q.tiles[t].sum.data(), p.tiles[t].sum.size() * sizeof(Color)), 0);
    EXPECT_EQ(p.tiles[t].weight, q.tiles[t].weight);
  }
}

// The message of the InputError that decoding `bytes` throws ("" when it throws none).
std::string decode_error(const std::vector<unsigned char>& bytes) {
  try {
    decode_checkpoint(bytes, "x.ckpt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointFile, RoundTripsBitForBit) {
  for (int margin : {0, 2}) {
    const RenderCheckpoint c = sample_checkpoint(margin);
    const std::vector<unsigned char> bytes = encode_checkpoint(c);
    const RenderCheckpoint back = decode_checkpoint(bytes, "x.ckpt");
    expect_same(c, back);
    EXPECT_EQ(encode_checkpoint(back), bytes);
  }
}

TEST(CheckpointFile, CutFilesAreRefused) {
  const std::vector<unsigned char> bytes = encode_checkpoint(sample_checkpoint(1));
  for (std::size_t keep : {std::size_t{0}, std::size_t{5}, std::size_t{12}, std::size_t{40}, bytes.size() / 2,
                           bytes.size() - 9, bytes.size() - 1}) {
    const std::vector<unsigned char> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(keep));
    const std::string error = decode_error(cut);
    EXPECT_NE(error.find("x.ckpt"), std::string::npos) << keep << " bytes: '" << error << "'";
    EXPECT_NE(error.find("byte"), std::string::npos) << keep << " bytes: '" << error << "'";
  }
}

TEST(CheckpointFile, AnyChangedByteIsCaught) {
  const std::vector<unsigned char> bytes = encode_checkpoint(sample_checkpoint(0));
  for (std::size_t at = 12; at < bytes.size(); at += 97) {
    std::vector<unsigned char> damaged = bytes;
    damaged[at] ^= 0x10;
    EXPECT_NE(decode_error(damaged).find("checksum mismatch"), std::string::npos) << "byte " << at;
  }
}

TEST(CheckpointFile, ForeignFilesAndVersionsAreNamed) {
  std::vector<unsigned char> bytes = encode_checkpoint(sample_checkpoint(0));
  std::vector<unsigned char> png = bytes;
  std::memcpy(png.data(), "\x89PNG\r\n\x1a\n", 8);
  EXPECT_NE(decode_error(png).find("not a raylab checkpoint"), std::string::npos);
  bytes[8] = 7;  // version 7
  EXPECT_NE(decode_error(bytes).find("checkpoint version 7"), std::string::npos);
}

TEST(CheckpointFile, SizesThatDoNotFitTheFileAllocateNothing) {
  // A well-formed, correctly checksummed file whose header claims a 32768 x 32768 image in tiles
  // of 1 pixel: refused from its length, before anything that size is allocated.
  RenderCheckpoint c = sample_checkpoint(0);
  std::vector<unsigned char> bytes = encode_checkpoint(c);
  const std::string needle = "\x25\x00\x00\x00\x15\x00\x00\x00\x08\x00\x00\x00";  // 37, 21, 8
  auto it = std::search(bytes.begin(), bytes.end(), needle.begin(), needle.end());
  ASSERT_NE(it, bytes.end());
  const std::int32_t huge[3] = {32768, 32768, 1};
  std::memcpy(&*it, huge, sizeof huge);
  bytes.erase(bytes.end() - 8, bytes.end());  // the old checksum (resize tripped GCC's bounds warning at -O1)
  Hash64 checksum;
  checksum.bytes(bytes.data(), bytes.size());
  const std::uint64_t sum = checksum.value();
  bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&sum),
               reinterpret_cast<const unsigned char*>(&sum) + sizeof sum);
  EXPECT_NE(decode_error(bytes).find("do not match the length of the file"), std::string::npos) << decode_error(bytes);
}

TEST(CheckpointFile, DifferencesAreNamed) {
  const RenderCheckpoint saved = sample_checkpoint(0);
  RenderCheckpoint now = saved;
  EXPECT_TRUE(checkpoint_differences(saved, now).empty());
  now.settings[2].second = "64";
  now.scene_fingerprint ^= 1;
  const std::vector<std::string> diff = checkpoint_differences(saved, now);
  ASSERT_EQ(diff.size(), 2u);
  EXPECT_NE(diff[0].find("has changed since the checkpoint"), std::string::npos) << diff[0];
  EXPECT_EQ(diff[1], "spp: 8 in the checkpoint, 64 now");
  now.scene = "demo";
  EXPECT_NE(checkpoint_differences(saved, now)[0].find("'scenes/cornell.json' in the checkpoint, 'demo' now"),
            std::string::npos);
}

TEST(SceneFingerprint, EqualScenesAgreeAndEveryChangeShows) {
  const Scene base = make_demo_scene();
  const std::uint64_t f = scene_fingerprint(base);
  EXPECT_EQ(scene_fingerprint(make_demo_scene()), f);
  Scene copy = base;
  copy.warnings.push_back("warnings do not change the image");
  EXPECT_EQ(scene_fingerprint(copy), f);

  std::vector<Scene> changed(7, base);
  ASSERT_FALSE(changed[0].geometry.spheres.empty());
  changed[0].geometry.spheres[0].radius = std::nextafter(changed[0].geometry.spheres[0].radius, 10.f);
  changed[1].materials[0].color.x += 0.01f;
  ASSERT_FALSE(changed[2].lights.empty());
  changed[2].lights[0].intensity.y *= 2.f;
  changed[3].camera.vfov_degrees += 1.f;
  changed[4].settings.background.z = 0.5f;
  changed[5].settings.seed = 7;
  changed[6].objects.push_back({"extra", 0});
  for (std::size_t i = 0; i < changed.size(); ++i) EXPECT_NE(scene_fingerprint(changed[i]), f) << "change " << i;
}

TEST(SceneFingerprint, EveryChangeOfTheCameraPathShows) {
  Scene base = make_demo_scene();
  const std::uint64_t still = scene_fingerprint(base);
  base.camera_path.keys = {{0, base.camera}, {24, base.camera}};
  base.camera_path.keys[1].camera.from.x += 1.f;
  const std::uint64_t f = scene_fingerprint(base);
  EXPECT_NE(f, still);

  std::vector<Scene> changed(9, base);
  changed[0].camera_path.interpolation = CameraPath::Interpolation::kSmooth;
  changed[1].camera_path.keys[1].frame = 25;
  changed[2].camera_path.keys[1].camera.from.x += 0.5f;
  changed[3].camera_path.keys[1].camera.at.y = 0.25f;
  changed[4].camera_path.keys[1].camera.up.z = 0.5f;
  changed[5].camera_path.keys[1].camera.vfov_degrees += 1.f;
  changed[6].camera_path.keys[1].camera.hither = 0.125f;
  changed[7].camera_path.keys[1].camera.fov_span = CameraSpec::FovSpan::kPixelCentres;
  changed[8].camera_path.keys.pop_back();
  std::set<std::uint64_t> seen{f, still};
  for (std::size_t i = 0; i < changed.size(); ++i) {
    EXPECT_TRUE(seen.insert(scene_fingerprint(changed[i])).second) << "change " << i;
  }
}

}  // namespace
}  // namespace raylab
