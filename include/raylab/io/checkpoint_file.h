#pragma once
/// \file
/// Checkpoint files (`.ckpt`): where a render stands (RenderProgress) together with what it
/// renders (the scene's name and fingerprint, the settings that decide the image), so that
/// `raylab render --resume FILE` can go on and refuse a checkpoint of another scene or other
/// settings, saying what differs.
///
/// Layout, little-endian: "RAYLABCK", u32 version (1); the scene as text and its u64 fingerprint;
/// u32 number of settings, each a (name, value) pair of texts; the progress: i32 width, height,
/// tile size, spp, passes, margin, passes done; u32 tiles, a byte per tile (finished the pass
/// under way), then per tile its rectangle (4 x i32) and its sums (3 f32 per pixel), followed by
/// its weights (1 f32 per pixel) when the margin is positive; last, a u64 checksum (Hash64) of
/// every byte before it. A text is a u32 length and that many bytes.

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "raylab/render/render_progress.h"
#include "raylab/scene/render_settings.h"

namespace raylab {

/// What a checkpoint file holds.
struct RenderCheckpoint {
  std::string scene;                    ///< the scene as named to `raylab render` (file, built-in, spd:...)
  std::uint64_t scene_fingerprint = 0;  ///< scene_fingerprint() of the loaded scene
  /// The settings that decide the image, as (name, value) texts in a fixed order, compared one by
  /// one on resume (e.g. {"spp", "64"}).
  std::vector<std::pair<std::string, std::string>> settings;
  RenderProgress progress;  ///< where the render stands
};

/// The bytes of a checkpoint file.
std::vector<unsigned char> encode_checkpoint(const RenderCheckpoint& checkpoint);

/// Reads the bytes of checkpoint file `path`. Throws InputError "path: byte N: what is wrong" on
/// anything but a whole, undamaged checkpoint (bad magic or version, truncation, sizes that do not
/// fit together, a checksum mismatch).
RenderCheckpoint decode_checkpoint(std::span<const unsigned char> bytes, const std::string& path);

/// Writes `checkpoint` to `path` atomically (the previous file stays whole until the new one is).
void write_checkpoint(const std::string& path, const RenderCheckpoint& checkpoint);

/// Reads checkpoint file `path` (InputError when missing, unreadable or damaged).
RenderCheckpoint read_checkpoint(const std::string& path);

/// The settings of a render that decide its image, as a checkpoint records them (names and values
/// as text, in this order): width, height, spp, sampler (resolved), filter, filter radius, seed,
/// max depth, tile size, passes, accel (the names in io/setting_names.h).
std::vector<std::pair<std::string, std::string>> image_settings(const RenderSettings& settings,
                                                                const std::string& sampler, int tile_size, int passes,
                                                                const std::string& accel);

/// The value `saved` records for setting `name`, or null.
const std::string* saved_setting(const RenderCheckpoint& saved, const std::string& name);

/// How `saved` differs from `now` in scene and settings, one line per difference (e.g. "spp: 16
/// in the checkpoint, 64 now"); empty when the checkpoint can be resumed.
std::vector<std::string> checkpoint_differences(const RenderCheckpoint& saved, const RenderCheckpoint& now);

}  // namespace raylab
