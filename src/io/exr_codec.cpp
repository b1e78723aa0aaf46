// Loading the EXR module (exr_codec.h) on first use.

#include "exr_codec.h"

#include "../core/sibling_module.h"

namespace raylab {

const ExrCodec& exr_codec() {
  return sibling_module_entry<ExrCodec>(reinterpret_cast<const void*>(&exr_codec), kExrModuleFile, kExrCodecSymbol);
}

}  // namespace raylab
