#include "raylab/dist/render_agreement.h"

#include "raylab/core/hash64.h"

namespace raylab::dist {

std::uint64_t render_agreement(const RenderCheckpoint& header) {
  Hash64 h;
  h.word(header.scene_fingerprint);
  for (const auto& [name, value] : header.settings) {
    h.bytes(name.data(), name.size());
    h.bytes(value.data(), value.size());
  }
  return h.value();
}

}  // namespace raylab::dist
