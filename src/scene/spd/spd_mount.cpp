// PLACEHOLDER: the SPD 'mount' generator is being written; this stub emits nothing.
#include "spd_generators.h"

namespace raylab::spd {

SpdGenerator mount() {
  return {"mount", "(not yet written)", 1, 1, [](int, NffSceneBuilder&) {}};
}

}  // namespace raylab::spd
