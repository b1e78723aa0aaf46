#pragma once
// Reading a scene file's `camera` object: the still camera and its optional `path` of key
// frames (docs/scene-format.md, "Camera paths").

#include "raylab/scene/camera_path.h"
#include "raylab/scene/camera_spec.h"
#include "scene_json_node.h"

namespace raylab::scene_json_detail {

/// Reads the camera object `n`: its own values into `camera`, its `path` into `path` (left empty
/// when there is none). Fails at the offending key for an unknown key, a value of the wrong type
/// or range, a camera that cannot render ('from' equal to 'at', 'up' parallel to the view), keys
/// out of frame order, and a path that degenerates between its keys (naming the frame).
void read_camera(const Node& n, CameraSpec& camera, CameraPath& path);

}  // namespace raylab::scene_json_detail
