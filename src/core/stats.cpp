#include "raylab/core/stats.h"

namespace raylab {

const char* ray_kind_name(RayKind kind) {
  switch (kind) {
    case RayKind::kPrimary:
      return "primary";
    case RayKind::kShadow:
      return "shadow";
    case RayKind::kReflection:
      return "reflection";
    case RayKind::kRefraction:
      return "refraction";
    case RayKind::kCount:
      break;
  }
  return "unknown";
}

}  // namespace raylab
