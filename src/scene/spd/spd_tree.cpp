// PLACEHOLDER: the SPD 'tree' generator is being written; this stub emits nothing.
#include "spd_generators.h"

namespace raylab::spd {

SpdGenerator tree() {
  return {"tree", "(not yet written)", 1, 1, [](int, NffSceneBuilder&) {}};
}

}  // namespace raylab::spd
