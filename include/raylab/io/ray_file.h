#pragma once
/// \file
/// `.rays` and `.hits` files: the same rays and answers for any tracer, ours or another.
///
/// Both are headerless arrays of little-endian records, so that any language can read them with
/// one call:
///   `.rays`  32 bytes per ray: float32 origin x, y, z, tmin, direction x, y, z, tmax.
///   `.hits`   8 bytes per ray: float32 t (+inf for a miss), uint32 primitive id
///             (0xFFFFFFFF, kMissPrimitive, for a miss; else the global primitive id, which for a
///             scene of one mesh is the triangle's index in file order).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "raylab/core/ray.h"

namespace raylab {

/// Bytes of one `.rays` record.
inline constexpr std::size_t kRayRecordBytes = 32;
/// Bytes of one `.hits` record.
inline constexpr std::size_t kHitRecordBytes = 8;
/// Primitive id a `.hits` file stores for a miss (the same value as kInvalidId).
inline constexpr std::uint32_t kMissPrimitive = 0xFFFFFFFFu;

/// One `.hits` record: the closest hit's distance and primitive.
struct HitRecord {
  float t = 0.f;                           ///< +inf for a miss
  std::uint32_t prim_id = kMissPrimitive;  ///< kMissPrimitive for a miss
  /// True for a miss.
  bool miss() const { return prim_id == kMissPrimitive; }
};

/// The record of `hit` (a miss when `hit` is not valid, whatever its t).
HitRecord hit_record(const Hit& hit);

/// `rays` as `.rays` bytes.
std::vector<unsigned char> encode_rays(std::span<const Ray> rays);
/// The rays of `.rays` bytes; InputError naming `file` when the size is not a multiple of 32.
std::vector<Ray> decode_rays(std::span<const unsigned char> bytes, const std::string& file);
/// `hits` as `.hits` bytes.
std::vector<unsigned char> encode_hits(std::span<const HitRecord> hits);
/// The records of `.hits` bytes; InputError naming `file` when the size is not a multiple of 8.
std::vector<HitRecord> decode_hits(std::span<const unsigned char> bytes, const std::string& file);

/// Reads a `.rays` file. InputError naming the file when it cannot be read or its size is not a
/// multiple of the record size (the message gives both sizes).
std::vector<Ray> read_rays(const std::string& path);
/// Writes a `.rays` file atomically (never half a file; InputError when it cannot be written).
void write_rays(const std::string& path, std::span<const Ray> rays);
/// Reads a `.hits` file, with the same errors as read_rays.
std::vector<HitRecord> read_hits(const std::string& path);
/// Writes a `.hits` file atomically.
void write_hits(const std::string& path, std::span<const HitRecord> hits);

}  // namespace raylab
