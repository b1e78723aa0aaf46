// libFuzzer target: parse_off on arbitrary bytes must either succeed or throw InputError.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "raylab/core/error.h"
#include "raylab/geometry/geometry.h"
#include "raylab/io/off_loader.h"

/// Parses `data` as an OFF file into a fresh Geometry; InputError is the expected outcome of bad input.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  raylab::Geometry geometry;
  try {
    raylab::parse_off(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.off", geometry, 0);
  } catch (const raylab::InputError&) {
  }
  return 0;
}
