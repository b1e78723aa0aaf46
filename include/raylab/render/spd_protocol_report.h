#pragma once
/// \file
/// The SPD testing procedure's counts as text and JSON, beside the published statistics when the
/// scene is one the tables counted.

#include <string>
#include <string_view>

#include "raylab/render/spd_protocol.h"
#include "raylab/scene/spd.h"

namespace raylab {

/// The counts as a table of eye, reflection, refraction and shadow rays, cast and hit. When
/// `source` (may be null) is one of the SPD README's seven scenes at its size, a column gives
/// the README's figure for each row (eye hits; rays cast of the other kinds) and one the ratio
/// raylab / README.
std::string format_spd_protocol_table(const SpdProtocolCounts& counts, ShadowFacing facing, const SpdSource* source);

/// The same as a JSON object: scene, facing, image size, depth, seconds, the rays by kind
/// ({"cast", "hit"}), and "published": for each table that counted this scene (`source`, may be
/// null), each figure it gives with raylab's and the ratio.
std::string format_spd_protocol_json(const SpdProtocolResult& result, std::string_view scene, ShadowFacing facing,
                                     const SpdSource* source);

}  // namespace raylab
