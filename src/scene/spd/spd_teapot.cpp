// PLACEHOLDER: the SPD 'teapot' generator is being written; this stub emits nothing.
#include "spd_generators.h"

namespace raylab::spd {

SpdGenerator teapot() {
  return {"teapot", "(not yet written)", 1, 1, [](int, NffSceneBuilder&) {}};
}

}  // namespace raylab::spd
