#include "scene_json_camera.h"

#include <cstdint>
#include <string>

namespace raylab::scene_json_detail {
namespace {

// The last frame a key may have: the reader checks the camera at every frame of a path, which
// must stay quick (a million frames are 11.5 hours at 24 frames per second).
constexpr std::int64_t kMaxFrame = 1'000'000;

// A camera that cannot render is a mistake at the object that describes it, or at its 'up'.
void check_camera(const Node& n, const CameraSpec& c, const std::string& what) {
  const CameraFault fault = camera_fault(c);
  if (fault == CameraFault::kEyeAtTarget) n.fail(what + " 'from' and 'at' are the same point");
  if (fault == CameraFault::kUpAlongView) {
    n.fail_at("up", what + " 'up' is parallel to the viewing direction (or zero)");
  }
}

// One key: a field the key does not give is the camera object's own.
CameraKey read_key(const Node& k, std::size_t index, const CameraSpec& base, const CameraKey* previous) {
  k.check_keys({"frame", "from", "at", "up", "fov", "hither"});
  const std::string what = "camera path key " + std::to_string(index);
  if (!k.has("frame")) k.fail(what + " needs 'frame'");
  CameraKey key;
  key.frame = static_cast<int>(k.integer("frame", 0, 0, kMaxFrame));
  if (previous && key.frame <= previous->frame) {
    k.fail_at("frame", "'frame' is " + std::to_string(key.frame) + ", must be greater than the previous key's (" +
                           std::to_string(previous->frame) + "): keys go in increasing frame order");
  }
  key.camera = base;
  key.camera.from = k.vec3("from", base.from);
  key.camera.at = k.vec3("at", base.at);
  key.camera.up = k.vec3("up", base.up);
  key.camera.vfov_degrees = k.real("fov", base.vfov_degrees, kPositive, 179.0);
  key.camera.hither = k.real("hither", base.hither, 0.0);
  check_camera(k, key.camera, what + " (frame " + std::to_string(key.frame) + "):");
  return key;
}

CameraPath read_path(const Node& p, const CameraSpec& base) {
  p.check_keys({"interpolation", "keys"});
  CameraPath path;
  path.interpolation = p.choice("interpolation", {"linear", "smooth"}, "linear") == "smooth"
                           ? CameraPath::Interpolation::kSmooth
                           : CameraPath::Interpolation::kLinear;
  if (!p.has("keys")) p.fail("the camera path needs 'keys' (an array of 1 or more keys)");
  const Node keys = p.child("keys", "'keys'");
  if (!keys.value().is_array() || keys.value().empty()) {
    keys.fail("'keys' must be an array of 1 or more keys, found " + type_name(keys.value()) +
              (keys.value().is_array() ? " of 0" : ""));
  }
  for (std::size_t i = 0; i < keys.value().size(); ++i) {
    const Node k = keys.element(i, "camera path key " + std::to_string(i));
    path.keys.push_back(read_key(k, i, base, path.keys.empty() ? nullptr : &path.keys.back()));
  }
  // Valid keys can still interpolate to a camera that cannot render (an 'up' turning through
  // zero, an eye passing through the point it looks at): refused here, not mid-animation.
  if (const auto problem = path.check()) p.fail("camera path: " + *problem);
  return path;
}

}  // namespace

void read_camera(const Node& n, CameraSpec& camera, CameraPath& path) {
  n.check_keys({"from", "at", "up", "fov", "fov_span", "hither", "path"});
  camera.from = n.vec3("from");
  camera.at = n.vec3("at");
  camera.up = n.vec3("up", Vec3{0.f, 1.f, 0.f});
  camera.vfov_degrees = n.real("fov", 45.0, kPositive, 179.0);
  camera.fov_span = n.choice("fov_span", {"edges", "pixel-centres"}, "edges") == "edges"
                        ? CameraSpec::FovSpan::kImageEdges
                        : CameraSpec::FovSpan::kPixelCentres;
  camera.hither = n.real("hither", 0.0, 0.0);
  check_camera(n, camera, "camera");
  path = n.has("path") ? read_path(n.child("path", "'path'"), camera) : CameraPath{};
}

}  // namespace raylab::scene_json_detail
