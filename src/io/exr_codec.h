#pragma once
/// \file
/// Internal to src/io: the EXR encoder and readers, which live in a module of their own
/// (libraylab_exr, exr_module.cpp) loaded on first use. Linked into the library, OpenEXR and the
/// four libraries it brings (Imath, Iex, IlmThread, zlib) were loaded by every process, about
/// 2.3 ms each time on the AMD EPYC Zen 5 machine (docs/performance.md, "Page faults on a
/// virtual machine"), though most renders never touch an EXR file.

#include <span>
#include <string>
#include <vector>

#include "raylab/io/image_io.h"
#include "raylab/render/film.h"

namespace raylab {

/// What the module gives. Each throws std::exception (OpenEXR's own) when the file or the data
/// is not what it needs; the callers in image_io.cpp word the error.
struct ExrCodec {
  /// `film` and `layers` (already checked) as the bytes of an EXR file.
  std::vector<unsigned char> (*encode)(const Film& film, std::span<const ImageLayer> layers);
  /// The R, G and B channels of EXR file `path`.
  Film (*read)(const std::string& path);
  /// Every channel of EXR file `path`, as read_exr_channels gives them.
  std::vector<ImageLayer> (*read_channels)(const std::string& path);
};

/// The codec, the module loaded at the first call (from the folder of the library itself; safe
/// from many threads). Throws std::runtime_error when the module cannot be loaded.
const ExrCodec& exr_codec();

/// The file name of the module, which lies beside libraylab (build tree, install and wheel).
inline constexpr const char* kExrModuleFile = "libraylab_exr.so";
/// The module's one entry point, `const ExrCodec* raylab_exr_codec()`.
inline constexpr const char* kExrCodecSymbol = "raylab_exr_codec";

}  // namespace raylab
