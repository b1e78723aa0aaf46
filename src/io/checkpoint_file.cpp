#include "raylab/io/checkpoint_file.h"

#include <bit>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string_view>

#include "raylab/core/error.h"
#include "raylab/core/hash64.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/binary_reader.h"
#include "raylab/io/read_file.h"
#include "raylab/io/setting_names.h"

namespace raylab {
namespace {

constexpr char kMagic[8] = {'R', 'A', 'Y', 'L', 'A', 'B', 'C', 'K'};
constexpr std::uint32_t kVersion = 1;
// The largest image side the command line accepts, and so the largest a checkpoint may claim.
constexpr int kMaxSide = 32768;

static_assert(std::endian::native == std::endian::little, "checkpoints are written little-endian as in memory");

// Appends values in the file's byte order.
class Writer {
 public:
  template <class T>
  void put(T value) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes.insert(bytes.end(), raw, raw + sizeof(T));
  }
  void text(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size()));
    bytes.insert(bytes.end(), s.begin(), s.end());
  }
  void floats(const float* data, std::size_t n) {
    const auto* raw = reinterpret_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), raw, raw + n * sizeof(float));
  }
  std::vector<unsigned char> bytes;
};

std::string read_text(BinaryReader& in, std::string_view bytes, std::string_view what) {
  const auto n = in.read<std::uint32_t>(false, what);
  const std::size_t at = in.offset();
  in.skip(n, what);
  return std::string(bytes.substr(at, n));
}

int read_int(BinaryReader& in, std::string_view what, int lo, int hi) {
  const std::size_t at = in.offset();
  const auto v = in.read<std::int32_t>(false, what);
  if (v < lo || v > hi) {
    in.fail(at, std::string(what) + " " + std::to_string(v) + " is out of range [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "]");
  }
  return v;
}

void read_floats(BinaryReader& in, std::string_view bytes, float* out, std::size_t n, std::string_view what) {
  const std::size_t at = in.offset();
  in.skip(n * sizeof(float), what);
  if (n > 0) std::memcpy(out, bytes.data() + at, n * sizeof(float));  // `out` is null for no weights
}

}  // namespace

std::vector<unsigned char> encode_checkpoint(const RenderCheckpoint& c) {
  Writer w;
  w.bytes.insert(w.bytes.end(), kMagic, kMagic + sizeof kMagic);
  w.put(kVersion);
  w.text(c.scene);
  w.put(c.scene_fingerprint);
  w.put(static_cast<std::uint32_t>(c.settings.size()));
  for (const auto& [name, value] : c.settings) {
    w.text(name);
    w.text(value);
  }
  const RenderProgress& p = c.progress;
  for (int v : {p.width, p.height, p.tile_size, p.spp, p.passes, p.margin, p.passes_done}) w.put<std::int32_t>(v);
  w.put(static_cast<std::uint32_t>(p.tiles.size()));
  w.bytes.insert(w.bytes.end(), p.tile_done.begin(), p.tile_done.end());
  for (const TileSums& s : p.tiles) {
    for (int v : {s.x0, s.y0, s.x1, s.y1}) w.put<std::int32_t>(v);
    w.floats(reinterpret_cast<const float*>(s.sum.data()), s.sum.size() * 3);
    w.floats(s.weight.data(), s.weight.size());
  }
  Hash64 checksum;
  checksum.bytes(w.bytes.data(), w.bytes.size());
  w.put(checksum.value());
  return std::move(w.bytes);
}

RenderCheckpoint decode_checkpoint(std::span<const unsigned char> raw, const std::string& path) {
  const std::string_view bytes(reinterpret_cast<const char*>(raw.data()), raw.size());
  BinaryReader in(path, bytes);
  in.require(sizeof kMagic, "the file's signature");
  if (bytes.substr(0, sizeof kMagic) != std::string_view(kMagic, sizeof kMagic)) {
    in.fail(0, "not a raylab checkpoint (it does not start with RAYLABCK)");
  }
  in.skip(sizeof kMagic, "the file's signature");
  const auto version = in.read<std::uint32_t>(false, "the version");
  if (version != kVersion) {
    in.fail(sizeof kMagic, "checkpoint version " + std::to_string(version) + " (this raylab reads version " +
                               std::to_string(kVersion) + ")");
  }
  // The checksum first: a damaged file is reported as such, not as whatever its damage looks like.
  if (raw.size() < sizeof(std::uint64_t) + sizeof kMagic + sizeof version) {
    in.fail(raw.size(), "unexpected end of file (no checksum)");
  }
  const std::size_t body = raw.size() - sizeof(std::uint64_t);
  Hash64 checksum;
  checksum.bytes(raw.data(), body);
  std::uint64_t stored;
  std::memcpy(&stored, raw.data() + body, sizeof stored);
  if (stored != checksum.value()) {
    in.fail(body, "checksum mismatch: the checkpoint is damaged or was cut short");
  }
  BinaryReader content(path, bytes.substr(0, body), in.offset());

  RenderCheckpoint c;
  c.scene = read_text(content, bytes, "the scene name");
  c.scene_fingerprint = content.read<std::uint64_t>(false, "the scene fingerprint");
  const auto settings = content.read<std::uint32_t>(false, "the number of settings");
  for (std::uint32_t i = 0; i < settings; ++i) {
    std::string name = read_text(content, bytes, "a setting's name");
    std::string value = read_text(content, bytes, "a setting's value");
    c.settings.emplace_back(std::move(name), std::move(value));
  }
  const int width = read_int(content, "the image width", 1, kMaxSide);
  const int height = read_int(content, "the image height", 1, kMaxSide);
  const int tile_size = read_int(content, "the tile size", 1, kMaxSide);
  const int spp = read_int(content, "the samples per pixel", 1, std::numeric_limits<int>::max());
  const int passes = read_int(content, "the number of passes", 1, spp);
  const int margin = read_int(content, "the filter margin", 0, kMaxSide);
  const int passes_done = read_int(content, "the passes done", 0, passes);
  // The layout follows from the sizes, and so does the length of the rest of the file: checked
  // before anything is allocated, so that a damaged size cannot ask for gigabytes.
  const std::size_t at_layout = content.offset();
  const std::int64_t tile_count = progress_tile_count(width, height, tile_size);
  const std::size_t per_tile = sizeof(std::uint8_t) + 4 * sizeof(std::int32_t);
  const std::size_t left = content.remaining();
  if (tile_count < 0 || static_cast<std::size_t>(tile_count) > left / per_tile ||
      sizeof(std::uint32_t) + static_cast<std::size_t>(tile_count) * per_tile +
              progress_pixels(width, height, tile_size, margin) * (3 + (margin > 0 ? 1 : 0)) * sizeof(float) !=
          left) {
    content.fail(at_layout, "the sizes (" + std::to_string(width) + "x" + std::to_string(height) + " in tiles of " +
                                std::to_string(tile_size) + ", margin " + std::to_string(margin) +
                                ") do not match the length of the file");
  }
  // The file must agree with the layout tile by tile.
  RenderProgress& p = c.progress;
  p = start_progress(width, height, tile_size, spp, passes, margin);
  p.passes_done = passes_done;
  const std::size_t at_tiles = content.offset();
  const auto tiles = content.read<std::uint32_t>(false, "the number of tiles");
  if (tiles != p.tiles.size()) {
    content.fail(at_tiles, std::to_string(tiles) + " tiles, where a " + std::to_string(width) + "x" +
                               std::to_string(height) + " image in tiles of " + std::to_string(tile_size) + " has " +
                               std::to_string(p.tiles.size()));
  }
  for (std::uint8_t& done : p.tile_done) {
    const std::size_t at = content.offset();
    done = content.read<std::uint8_t>(false, "a tile's state");
    if (done > 1) content.fail(at, "a tile's state must be 0 or 1, not " + std::to_string(done));
  }
  for (TileSums& s : p.tiles) {
    const std::size_t at = content.offset();
    int rect[4];
    for (int& v : rect) v = read_int(content, "a tile's rectangle", 0, kMaxSide);
    if (rect[0] != s.x0 || rect[1] != s.y0 || rect[2] != s.x1 || rect[3] != s.y1) {
      content.fail(at, "a tile's rectangle does not match the image's tiling");
    }
    read_floats(content, bytes, reinterpret_cast<float*>(s.sum.data()), s.sum.size() * 3, "a tile's sums");
    read_floats(content, bytes, s.weight.data(), s.weight.size(), "a tile's weights");
  }
  if (content.remaining() != 0) {
    content.fail(content.offset(), std::to_string(content.remaining()) + " bytes left over after the last tile");
  }
  return c;
}

void write_checkpoint(const std::string& path, const RenderCheckpoint& checkpoint) {
  write_file_atomically(path, encode_checkpoint(checkpoint));
}

RenderCheckpoint read_checkpoint(const std::string& path) {
  const std::string bytes = read_file(path);
  return decode_checkpoint(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()), path);
}

std::vector<std::pair<std::string, std::string>> image_settings(const RenderSettings& s, const std::string& sampler,
                                                                int tile_size, int passes, const std::string& accel) {
  char radius[32];
  std::snprintf(radius, sizeof radius, "%.9g", static_cast<double>(s.filter_radius));
  namespace name = setting_name;
  std::vector<std::pair<std::string, std::string>> settings = {{name::kWidth, std::to_string(s.width)},
                                                               {name::kHeight, std::to_string(s.height)},
                                                               {name::kSpp, std::to_string(s.spp)},
                                                               {name::kSampler, sampler},
                                                               {name::kFilter, s.filter},
                                                               {name::kFilterRadius, radius},
                                                               {name::kSeed, std::to_string(s.seed)},
                                                               {name::kMaxDepth, std::to_string(s.max_depth)},
                                                               {name::kTileSize, std::to_string(tile_size)},
                                                               {name::kPasses, std::to_string(passes)},
                                                               {name::kAccel, accel}};
  if (s.integrator != "whitted") settings.emplace_back(name::kIntegrator, s.integrator);
  return settings;
}

const std::string* saved_setting(const RenderCheckpoint& saved, const std::string& name) {
  for (const auto& [saved_name, value] : saved.settings) {
    if (saved_name == name) return &value;
  }
  return nullptr;
}

std::vector<std::string> checkpoint_differences(const RenderCheckpoint& saved, const RenderCheckpoint& now) {
  std::vector<std::string> out;
  if (saved.scene != now.scene) {
    out.push_back("scene: '" + saved.scene + "' in the checkpoint, '" + now.scene + "' now");
  } else if (saved.scene_fingerprint != now.scene_fingerprint) {
    out.push_back("scene: '" + now.scene + "' has changed since the checkpoint was written (its content differs)");
  }
  for (const auto& [name, value] : now.settings) {
    std::string before = "(not recorded)";
    for (const auto& [saved_name, saved_value] : saved.settings) {
      if (saved_name == name) before = saved_value;
    }
    if (before != value) out.push_back(name + ": " + before + " in the checkpoint, " + value + " now");
  }
  return out;
}

}  // namespace raylab
