// libFuzzer target for the scene-file reader: any bytes must either load or be refused with an
// InputError; a crash, a sanitizer report, a hang or any other exception is a bug. References
// to other files resolve in an empty folder, so the fuzzer exercises the reader itself. SPD
// generator objects are capped at size 3: a sphereflake of size 7 is 5 million spheres and minutes
// of work, a valid scene but a timeout for the fuzzer.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "raylab/core/error.h"
#include "raylab/io/scene_json.h"

/// Parses `data` as a scene file.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    raylab::LoadOptions options;
    options.max_spd_size = 3;
    raylab::parse_scene_json(text, "fuzz.json", "/nonexistent-raylab-fuzz-folder", options);
  } catch (const raylab::InputError&) {
    // Refusing bad input with a located message is the reader's job.
  }
  return 0;
}
