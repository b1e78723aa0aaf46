// The EXR module (libraylab_exr): OpenEXR behind the codec of exr_codec.h, loaded by the library
// on the first EXR file it reads or writes.

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "exr_codec.h"

namespace raylab {
namespace {

// OpenEXR writes through a stream; this one collects the bytes so the file can be written atomically.
class MemoryOStream final : public Imf::OStream {
 public:
  MemoryOStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (m_pos + n > m_data.size()) m_data.resize(m_pos + n);
    std::memcpy(m_data.data() + m_pos, c, static_cast<std::size_t>(n));
    m_pos += static_cast<std::size_t>(n);
  }
  uint64_t tellp() override { return m_pos; }
  void seekp(uint64_t pos) override { m_pos = pos; }
  std::vector<unsigned char>& data() { return m_data; }

 private:
  std::vector<unsigned char> m_data;
  std::size_t m_pos = 0;
};

std::vector<unsigned char> encode(const Film& film, std::span<const ImageLayer> layers) {
  Imf::Header header(film.width(), film.height());
  header.channels().insert("R", Imf::Channel(Imf::FLOAT));
  header.channels().insert("G", Imf::Channel(Imf::FLOAT));
  header.channels().insert("B", Imf::Channel(Imf::FLOAT));
  for (const ImageLayer& l : layers) header.channels().insert(l.name, Imf::Channel(Imf::FLOAT));
  MemoryOStream stream;
  Imf::OutputFile file(stream, header);
  Imf::FrameBuffer fb;
  auto* base = reinterpret_cast<char*>(const_cast<Color*>(film.pixels().data()));
  const std::size_t xs = sizeof(Color), ys = sizeof(Color) * film.width();
  fb.insert("R", Imf::Slice(Imf::FLOAT, base + 0, xs, ys));
  fb.insert("G", Imf::Slice(Imf::FLOAT, base + 4, xs, ys));
  fb.insert("B", Imf::Slice(Imf::FLOAT, base + 8, xs, ys));
  for (const ImageLayer& l : layers) {
    auto* values = reinterpret_cast<char*>(const_cast<float*>(l.values.data()));
    fb.insert(l.name, Imf::Slice(Imf::FLOAT, values, sizeof(float), sizeof(float) * std::size_t(film.width())));
  }
  file.setFrameBuffer(fb);
  file.writePixels(film.height());
  return std::move(stream.data());
}

Film read(const std::string& path) {
  Imf::InputFile file(path.c_str());
  const auto dw = file.header().dataWindow();
  const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
  Film film(w, h);
  auto* base = reinterpret_cast<char*>(const_cast<Color*>(film.pixels().data())) -
               (std::ptrdiff_t(dw.min.x) + std::ptrdiff_t(dw.min.y) * w) * std::ptrdiff_t(sizeof(Color));
  Imf::FrameBuffer fb;
  const std::size_t xs = sizeof(Color), ys = sizeof(Color) * w;
  fb.insert("R", Imf::Slice(Imf::FLOAT, base + 0, xs, ys));
  fb.insert("G", Imf::Slice(Imf::FLOAT, base + 4, xs, ys));
  fb.insert("B", Imf::Slice(Imf::FLOAT, base + 8, xs, ys));
  file.setFrameBuffer(fb);
  file.readPixels(dw.min.y, dw.max.y);
  return film;
}

std::vector<ImageLayer> read_channels(const std::string& path) {
  Imf::InputFile file(path.c_str());
  const auto dw = file.header().dataWindow();
  const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
  std::vector<ImageLayer> out;
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
    out.push_back({it.name(), std::vector<float>(std::size_t(w) * std::size_t(h))});
  }
  Imf::FrameBuffer fb;
  for (ImageLayer& l : out) {
    char* base = reinterpret_cast<char*>(l.values.data()) -
                 (std::ptrdiff_t(dw.min.x) + std::ptrdiff_t(dw.min.y) * w) * std::ptrdiff_t(sizeof(float));
    fb.insert(l.name, Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * std::size_t(w)));
  }
  file.setFrameBuffer(fb);
  file.readPixels(dw.min.y, dw.max.y);
  return out;
}

constexpr ExrCodec kCodec{encode, read, read_channels};

}  // namespace
}  // namespace raylab

/// The module's entry point (exr_codec.h, kExrCodecSymbol): the one symbol it exports.
extern "C" __attribute__((visibility("default"))) const raylab::ExrCodec* raylab_exr_codec() { return &raylab::kCodec; }
