#pragma once
/// \file
/// Where an interrupted render puts the image of its samples so far, so that stopping a
/// re-render never replaces a finished image with a half-black one.

#include <string>

namespace raylab {

/// The file beside `target` for a partial image: the extension kept, ".partial" before it
/// ("out/good.png" -> "out/good.partial.png"; "frame" -> "frame.partial").
std::string partial_image_beside(const std::string& target);

/// Where an interrupted render of `target` writes its partial image. `target_existed`: the
/// target was there before the render started; `render_wrote_target`: this render has since
/// written a whole image of its own there (a finished pass of --passes). A file of the user's
/// is never replaced by a partial image: it goes beside it (partial_image_beside); otherwise
/// the target itself holds the partial image, as nothing is lost by it.
std::string partial_image_path(const std::string& target, bool target_existed, bool render_wrote_target);

}  // namespace raylab
