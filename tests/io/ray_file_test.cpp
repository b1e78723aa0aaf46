// .rays and .hits files: bit-exact round trips, the documented byte layout, and clear errors.

#include "raylab/io/ray_file.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "raylab/core/error.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

fs::path temp_path(const std::string& name) {
  return fs::temp_directory_path() /
         ("raylab-rayfile-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" + name);
}

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

// Rays with awkward values: negative zero, a denormal, infinities, the largest float.
std::vector<Ray> awkward_rays() {
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<Ray> rays(4);
  rays[0] = Ray{{1.f, -2.5f, 3.25f}, 0.f, {0.f, 0.f, -1.f}, inf};
  rays[1] = Ray{{-0.f, std::numeric_limits<float>::denorm_min(), 1e30f}, 1e-3f, {0.5f, -0.25f, 0.125f}, 7.f};
  rays[2] = Ray{{std::numeric_limits<float>::max(), 0.1f, -0.1f}, 2.f, {-inf, 1.f, 0.f}, 3.f};
  rays[3] = Ray{{0.3f, 0.7f, 0.9f}, 0.f, {1e-20f, 1e20f, -3.f}, 0.f};
  return rays;
}

TEST(RayFile, RaysRoundTripBitExactThroughAFile) {
  const std::vector<Ray> rays = awkward_rays();
  const fs::path p = temp_path("a.rays");
  write_rays(p.string(), rays);
  EXPECT_EQ(fs::file_size(p), rays.size() * kRayRecordBytes);
  const std::vector<Ray> back = read_rays(p.string());
  fs::remove(p);
  ASSERT_EQ(back.size(), rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(std::memcmp(&back[i], &rays[i], sizeof(Ray)), 0) << "ray " << i;
  }
}

TEST(RayFile, RaysAreLittleEndianFloatsInTheDocumentedOrder) {
  const Ray r{{1.f, 2.f, 3.f}, 4.f, {5.f, 6.f, 7.f}, 8.f};
  const std::vector<unsigned char> bytes = encode_rays(std::span(&r, 1));
  ASSERT_EQ(bytes.size(), 32u);
  for (int k = 0; k < 8; ++k) {
    const std::uint32_t expected = bits(static_cast<float>(k + 1));
    const std::uint32_t got = bytes[4 * k] | bytes[4 * k + 1] << 8 | bytes[4 * k + 2] << 16 |
                              static_cast<std::uint32_t>(bytes[4 * k + 3]) << 24;
    EXPECT_EQ(got, expected) << "float " << k;
  }
}

TEST(RayFile, HitsRoundTripWithMissesAsInfinityAndAllOnes) {
  Hit hit;
  hit.t = 2.5f;
  hit.prim_id = 17;
  Hit miss;
  miss.t = 3.f;  // a stale t on a miss is not written
  const std::vector<HitRecord> hits = {hit_record(hit), hit_record(miss), {0.f, 0}};
  EXPECT_TRUE(std::isinf(hits[1].t));
  EXPECT_EQ(hits[1].prim_id, 0xFFFFFFFFu);
  EXPECT_TRUE(hits[1].miss());
  const fs::path p = temp_path("a.hits");
  write_hits(p.string(), hits);
  EXPECT_EQ(fs::file_size(p), 24u);
  const std::vector<HitRecord> back = read_hits(p.string());
  fs::remove(p);
  ASSERT_EQ(back.size(), hits.size());
  for (std::size_t i = 0; i < hits.size(); ++i) {
    EXPECT_EQ(bits(back[i].t), bits(hits[i].t)) << i;
    EXPECT_EQ(back[i].prim_id, hits[i].prim_id) << i;
  }
  const std::vector<unsigned char> bytes = encode_hits(hits);
  EXPECT_EQ(bytes[12], 0xFF);  // the miss id, byte by byte
  EXPECT_EQ(bytes[15], 0xFF);
  EXPECT_EQ(bytes[4], 17);  // little-endian id
}

TEST(RayFile, SizeThatIsNotAWholeNumberOfRecordsIsAnInputErrorNamingTheFile) {
  const fs::path p = temp_path("cut.rays");
  std::vector<unsigned char> bytes = encode_rays(awkward_rays());
  bytes.resize(bytes.size() - 5);  // 123 bytes
  std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  try {
    read_rays(p.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), p.string());
    EXPECT_NE(what.find(p.string()), std::string::npos) << what;
    EXPECT_NE(what.find("123"), std::string::npos) << what;
    EXPECT_NE(what.find("32"), std::string::npos) << what;
  }
  EXPECT_THROW(read_hits(p.string()), InputError);  // 123 is no multiple of 8 either
  fs::remove(p);
  EXPECT_THROW(read_rays(p.string()), InputError);  // missing
  EXPECT_THROW(decode_hits(std::span(bytes.data(), 12), "x.hits"), InputError);
  EXPECT_TRUE(decode_rays(std::span(bytes.data(), 0), "empty.rays").empty());  // empty is fine
}

TEST(RayFile, AFailedWriteLeavesNothingBehind) {
  const fs::path dir = temp_path("missing-dir");
  EXPECT_THROW(write_rays((dir / "x.rays").string(), awkward_rays()), InputError);
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace raylab
