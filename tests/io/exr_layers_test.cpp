// EXR extra layers: written next to R, G, B as float channels and read back through OpenEXR's
// reader, value for value (values that half floats cannot hold prove the FLOAT type); PNG and
// PFM ignore the layers.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

// Every channel of an EXR file by name, read back through OpenEXR (read_exr_channels).
struct ExrChannels {
  std::map<std::string, std::vector<float>> channels;
};

ExrChannels read_exr(const std::string& path) {
  ExrChannels out;
  for (ImageLayer& l : read_exr_channels(path)) out.channels[l.name] = std::move(l.values);
  return out;
}

class ExrLayers : public ::testing::Test {
 protected:
  std::string file(const std::string& name) const { return m_dir.file(name); }
  test::TempDir m_dir{"exr-layers"};
};

// A 7x5 film and two layers with a distinct value per pixel (odd size: no row padding hides).
Film sample_film() {
  Film f(7, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) f.at(x, y) = {0.1f * x, 0.01f * y, 1.5f + x * y};
  }
  return f;
}

std::vector<ImageLayer> sample_layers() {
  ImageLayer samples{"samples.Y", {}}, cost{"cost", {}};
  for (int i = 0; i < 35; ++i) {
    samples.values.push_back(static_cast<float>(4 + (i * 7) % 61) + 1.0f / 4096.f);
    cost.values.push_back(0.1f * static_cast<float>(i) - 3.0001f);  // not representable as half
  }
  return {samples, cost};
}

TEST_F(ExrLayers, LayersAreExtraFloatChannelsWithTheirValues) {
  const Film film = sample_film();
  const std::vector<ImageLayer> layers = sample_layers();
  write_image(film, file("a.exr"), layers);
  const ExrChannels read = read_exr(file("a.exr"));
  ASSERT_EQ(read.channels.size(), 5u);  // R, G, B, samples.Y, cost
  for (const ImageLayer& l : layers) {
    ASSERT_TRUE(read.channels.count(l.name)) << l.name;
    EXPECT_EQ(read.channels.at(l.name), l.values) << l.name;  // float all the way: bit-exact
  }
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      const std::size_t i = std::size_t(y) * 7 + x;
      EXPECT_EQ(read.channels.at("R")[i], film.at(x, y).x);
      EXPECT_EQ(read.channels.at("G")[i], film.at(x, y).y);
      EXPECT_EQ(read.channels.at("B")[i], film.at(x, y).z);
    }
  }
  // Our own reader still sees the colour.
  EXPECT_EQ(read_image(file("a.exr")).pixels(), film.pixels());
}

TEST_F(ExrLayers, WithoutLayersTheFileHasOnlyRgb) {
  write_image(sample_film(), file("plain.exr"), {});
  const ExrChannels read = read_exr(file("plain.exr"));
  EXPECT_EQ(read.channels.size(), 3u);
  EXPECT_EQ(read.channels.at("G").size(), 35u);
  EXPECT_THROW(read_exr_channels(file("missing.exr")), InputError);
  EXPECT_EQ(encode_image(sample_film(), ".exr"), encode_image(sample_film(), ".exr", {}));
}

TEST_F(ExrLayers, PngAndPfmIgnoreTheLayers) {
  const Film film = sample_film();
  const std::vector<ImageLayer> layers = sample_layers();
  EXPECT_EQ(encode_image(film, ".png", layers), encode_image(film, ".png"));
  EXPECT_EQ(encode_image(film, ".pfm", layers), encode_image(film, ".pfm"));
  write_image(film, file("a.pfm"), layers);
  EXPECT_EQ(read_image(file("a.pfm")).pixels(), film.pixels());
}

TEST_F(ExrLayers, BadLayersAreRejectedBeforeAnythingIsWritten) {
  const Film film = sample_film();
  std::vector<ImageLayer> short_layer = {{"samples.Y", std::vector<float>(34, 1.f)}};
  EXPECT_THROW(write_image(film, file("short.exr"), short_layer), std::invalid_argument);
  std::vector<ImageLayer> clash = {{"G", std::vector<float>(35, 1.f)}};
  EXPECT_THROW(write_image(film, file("clash.exr"), clash), std::invalid_argument);
  std::vector<ImageLayer> twice = sample_layers();
  twice[1].name = twice[0].name;
  EXPECT_THROW(write_image(film, file("twice.exr"), twice), std::invalid_argument);
  EXPECT_TRUE(fs::is_empty(m_dir.path()));
}

}  // namespace
}  // namespace raylab
