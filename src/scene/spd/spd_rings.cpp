// PLACEHOLDER: the SPD 'rings' generator is being written; this stub emits nothing.
#include "spd_generators.h"

namespace raylab::spd {

SpdGenerator rings() {
  return {"rings", "(not yet written)", 1, 1, [](int, NffSceneBuilder&) {}};
}

}  // namespace raylab::spd
