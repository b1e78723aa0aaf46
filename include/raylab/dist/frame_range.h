#pragma once
/// \file
/// The frames of an animation as a user names them ("12:48"), and the file each frame goes to.

#include <optional>
#include <string>
#include <utility>

namespace raylab::dist {

/// The frames of "A:B" (A to B inclusive) or "A"; nullopt when the text is not one (numbers of
/// at most 9 digits, A <= B).
std::optional<std::pair<int, int>> parse_frame_range(const std::string& text);

/// `output` for frame `frame` (>= 0): a run of '#' in the name replaced by the zero-padded number
/// ("f.####.png" -> "f.0007.png"), else the number (4 digits) before the extension
/// ("out.png" -> "out.0007.png").
std::string frame_output(const std::string& output, int frame);

}  // namespace raylab::dist
