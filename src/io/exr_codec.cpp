// Loading the EXR module (exr_codec.h) on first use.

#include "exr_codec.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace raylab {
namespace {

// The module beside this library: the folder of the file that holds exr_codec.
std::string exr_module_path() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&exr_codec), &info) == 0 || info.dli_fname == nullptr) {
    return kExrModuleFile;  // the loader's own search, as a last resort
  }
  const std::string library = info.dli_fname;
  const std::size_t slash = library.rfind('/');
  return (slash == std::string::npos ? std::string() : library.substr(0, slash + 1)) + kExrModuleFile;
}

// The codec, or why there is none: loaded once (never unloaded), whatever the outcome.
struct LoadedCodec {
  const ExrCodec* codec = nullptr;
  std::string error;

  LoadedCodec() {
    const std::string path = exr_module_path();
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) {
      const char* why = dlerror();
      error = std::string("cannot load raylab's EXR module: ") + (why ? why : path.c_str());
      return;
    }
    const auto entry = reinterpret_cast<const ExrCodec* (*)()>(dlsym(module, kExrCodecSymbol));
    if (entry == nullptr) {
      error = path + " has no " + kExrCodecSymbol;
      return;
    }
    codec = entry();
  }
};

}  // namespace

const ExrCodec& exr_codec() {
  static const LoadedCodec loaded;  // thread-safe, once
  if (loaded.codec == nullptr) throw std::runtime_error(loaded.error);
  return *loaded.codec;
}

}  // namespace raylab
