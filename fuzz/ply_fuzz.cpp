// libFuzzer target: parse_ply on arbitrary bytes must either succeed or throw InputError.

#include <cstddef>
#include <cstdint>

#include "mesh_parser_fuzz.h"
#include "raylab/io/ply_loader.h"

/// Parses `data` as an PLY file into a fresh Geometry; InputError is the expected outcome of bad input.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz_mesh_parser(data, size, "fuzz.ply", raylab::parse_ply);
}
