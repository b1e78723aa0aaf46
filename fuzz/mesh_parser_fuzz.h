#pragma once
// What every mesh-parser fuzz target does with one input: parse the bytes into a fresh Geometry.
// Success and InputError are the two allowed outcomes; anything else (another exception, a
// crash, a sanitizer report) is a bug the fuzzer should stop at.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "raylab/core/error.h"
#include "raylab/geometry/geometry.h"

/// Parses `data` with `parse` (parse_ply, parse_off, ...) as file `file` into a fresh Geometry,
/// letting InputError pass; returns libFuzzer's 0.
template <class Parse>
int fuzz_mesh_parser(const std::uint8_t* data, std::size_t size, const std::string& file, Parse parse) {
  raylab::Geometry geometry;
  try {
    parse(std::string_view(reinterpret_cast<const char*>(data), size), file, geometry, 0);
  } catch (const raylab::InputError&) {
  }
  return 0;
}
