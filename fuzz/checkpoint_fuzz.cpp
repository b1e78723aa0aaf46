// libFuzzer target: decode_checkpoint on arbitrary bytes must either succeed or throw InputError.
// The input is taken as a checkpoint without its checksum, which is computed and appended: a
// random checksum would stop nearly every input at the first check, and the parsing behind it is
// what needs exploring.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/core/hash64.h"
#include "raylab/io/checkpoint_file.h"

/// Decodes `data` plus its checksum; InputError is the expected outcome of bad input.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<unsigned char> bytes(data, data + size);
  raylab::Hash64 checksum;
  checksum.bytes(bytes.data(), bytes.size());
  const std::uint64_t sum = checksum.value();
  const auto* raw = reinterpret_cast<const unsigned char*>(&sum);
  bytes.insert(bytes.end(), raw, raw + sizeof sum);
  try {
    raylab::decode_checkpoint(bytes, "fuzz.ckpt");
  } catch (const raylab::InputError&) {
  }
  return 0;
}
