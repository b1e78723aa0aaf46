// Modules loaded from the folder of the library asking for them (src/core/sibling_module.h).

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "../../src/core/sibling_module.h"
#include "../../src/io/exr_codec.h"
#include "raylab/version.h"

namespace raylab {
namespace {

// Anchored at a function of libraylab, the EXR module beside it is found and gives its entry.
TEST(SiblingModule, FindsTheModuleBesideTheLibrary) {
  void* entry = sibling_module_symbol(reinterpret_cast<const void*>(&version), kExrModuleFile, kExrCodecSymbol,
                                      ModuleScope::kLocal);
  ASSERT_NE(entry, nullptr);
  const ExrCodec* codec = reinterpret_cast<const ExrCodec* (*)()>(entry)();
  ASSERT_NE(codec, nullptr);
  EXPECT_EQ(codec, &exr_codec());  // one module, loaded once
}

// A missing module or symbol is an error that names it, not a crash.
TEST(SiblingModule, AMissingModuleOrSymbolIsNamed) {
  const auto message = [](const char* file, const char* symbol) {
    try {
      sibling_module_symbol(reinterpret_cast<const void*>(&version), file, symbol, ModuleScope::kLocal);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("libraylab_no_such_module.so", "x").find("libraylab_no_such_module.so"), std::string::npos);
  EXPECT_NE(message(kExrModuleFile, "no_such_symbol").find("no_such_symbol"), std::string::npos);
}

}  // namespace
}  // namespace raylab
