// PLACEHOLDER: the SPD 'balls' generator is being written; this stub emits nothing.
#include "spd_generators.h"

namespace raylab::spd {

SpdGenerator balls() {
  return {"balls", "(not yet written)", 1, 1, [](int, NffSceneBuilder&) {}};
}

}  // namespace raylab::spd
