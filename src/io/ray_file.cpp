#include "raylab/io/ray_file.h"

#include <bit>
#include <cstring>
#include <limits>

#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/read_file.h"

namespace raylab {
namespace {

// Little-endian 32-bit words, whatever the host's byte order, so the files travel between machines.
void put_word(unsigned char* out, std::uint32_t w) {
  for (int k = 0; k < 4; ++k) out[k] = static_cast<unsigned char>(w >> (8 * k));
}
std::uint32_t get_word(const unsigned char* in) {
  std::uint32_t w = 0;
  for (int k = 0; k < 4; ++k) w |= static_cast<std::uint32_t>(in[k]) << (8 * k);
  return w;
}
void put_float(unsigned char* out, float f) { put_word(out, std::bit_cast<std::uint32_t>(f)); }
float get_float(const unsigned char* in) { return std::bit_cast<float>(get_word(in)); }

// Throws unless `size` is a whole number of records; names both sizes, so a truncated or foreign
// file is recognised at once.
void check_size(std::size_t size, std::size_t record, const char* kind, const std::string& file) {
  if (size % record == 0) return;
  throw InputError(file, "size " + std::to_string(size) + " bytes is not a multiple of the " + kind + " record size (" +
                             std::to_string(record) + " bytes): truncated or not a " + kind + " file");
}

// The bytes of `records`, each written by `put(record, out)` into its `record_bytes` at `out`.
template <class Record, class Put>
std::vector<unsigned char> encode_records(std::span<const Record> records, std::size_t record_bytes, Put put) {
  std::vector<unsigned char> bytes(records.size() * record_bytes);
  for (std::size_t i = 0; i < records.size(); ++i) put(records[i], bytes.data() + i * record_bytes);
  return bytes;
}

// The records of a `kind` file, each read by `get(in)` from its `record_bytes` at `in`; throws
// unless the size is a whole number of records.
template <class Record, class Get>
std::vector<Record> decode_records(std::span<const unsigned char> bytes, std::size_t record_bytes, const char* kind,
                                   const std::string& file, Get get) {
  check_size(bytes.size(), record_bytes, kind, file);
  std::vector<Record> records(bytes.size() / record_bytes);
  for (std::size_t i = 0; i < records.size(); ++i) records[i] = get(bytes.data() + i * record_bytes);
  return records;
}

std::span<const unsigned char> as_bytes(const std::string& s) {
  return {reinterpret_cast<const unsigned char*>(s.data()), s.size()};
}

}  // namespace

HitRecord hit_record(const Hit& hit) {
  if (!hit.valid()) return {std::numeric_limits<float>::infinity(), kMissPrimitive};
  return {hit.t, hit.prim_id};
}

std::vector<unsigned char> encode_rays(std::span<const Ray> rays) {
  return encode_records(rays, kRayRecordBytes, [](const Ray& r, unsigned char* out) {
    const float f[8] = {r.origin.x,    r.origin.y,    r.origin.z,    r.tmin,
                        r.direction.x, r.direction.y, r.direction.z, r.tmax};
    for (int k = 0; k < 8; ++k) put_float(out + 4 * k, f[k]);
  });
}

std::vector<Ray> decode_rays(std::span<const unsigned char> bytes, const std::string& file) {
  return decode_records<Ray>(bytes, kRayRecordBytes, ".rays", file, [](const unsigned char* in) {
    float f[8];
    for (int k = 0; k < 8; ++k) f[k] = get_float(in + 4 * k);
    return Ray{{f[0], f[1], f[2]}, f[3], {f[4], f[5], f[6]}, f[7]};
  });
}

std::vector<unsigned char> encode_hits(std::span<const HitRecord> hits) {
  return encode_records(hits, kHitRecordBytes, [](const HitRecord& h, unsigned char* out) {
    put_float(out, h.t);
    put_word(out + 4, h.prim_id);
  });
}

std::vector<HitRecord> decode_hits(std::span<const unsigned char> bytes, const std::string& file) {
  return decode_records<HitRecord>(bytes, kHitRecordBytes, ".hits", file, [](const unsigned char* in) {
    return HitRecord{get_float(in), get_word(in + 4)};
  });
}

std::vector<Ray> read_rays(const std::string& path) { return decode_rays(as_bytes(read_file(path)), path); }

void write_rays(const std::string& path, std::span<const Ray> rays) { write_file_atomically(path, encode_rays(rays)); }

std::vector<HitRecord> read_hits(const std::string& path) { return decode_hits(as_bytes(read_file(path)), path); }

void write_hits(const std::string& path, std::span<const HitRecord> hits) {
  write_file_atomically(path, encode_hits(hits));
}

}  // namespace raylab
