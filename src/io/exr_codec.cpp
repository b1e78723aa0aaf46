// Loading the EXR module (exr_codec.h) on first use.

#include "exr_codec.h"

#include <stdexcept>
#include <string>

#include "../core/sibling_module.h"

namespace raylab {
namespace {

// The codec, or why there is none: loaded once, whatever the outcome.
struct LoadedCodec {
  const ExrCodec* codec = nullptr;
  std::string error;

  LoadedCodec() {
    try {
      void* entry = sibling_module_symbol(reinterpret_cast<const void*>(&exr_codec), kExrModuleFile, kExrCodecSymbol,
                                          ModuleScope::kLocal);
      codec = reinterpret_cast<const ExrCodec* (*)()>(entry)();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
};

}  // namespace

const ExrCodec& exr_codec() {
  static const LoadedCodec loaded;  // thread-safe, once
  if (loaded.codec == nullptr) throw std::runtime_error(loaded.error);
  return *loaded.codec;
}

}  // namespace raylab
