// libFuzzer entry for the NFF reader: any bytes must either parse or be refused with an
// InputError; a crash, a sanitizer report, a hang or any other exception is a bug.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "raylab/core/error.h"
#include "raylab/io/nff_loader.h"
#include "raylab/scene/nff_builder.h"
#include "raylab/scene/scene.h"

/// Parses `data` as an NFF file into a fresh Scene and finishes the builder.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  raylab::Scene scene;
  raylab::NffSceneBuilder builder(scene);
  try {
    raylab::parse_nff(text, "fuzz.nff", builder);
    builder.finish();
  } catch (const raylab::InputError&) {
    // Refusing bad input with a located message is the reader's job.
  }
  return 0;
}
