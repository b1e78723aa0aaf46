#pragma once
/// \file
/// The environment a user names: a constant colour or a lat-long image file (the command
/// line's --env).

#include <string>
#include <string_view>

#include "raylab/scene/environment.h"

namespace raylab {

/// The environment `spec_or_path` names, turned by `rotate_degrees` about +y
/// (Environment::rotate_degrees), at scale 1:
///  - "R,G,B": three finite numbers >= 0 separated by commas (spaces allowed around them), a
///    constant radiance; this reading wins over a file of the same name;
///  - otherwise the path of a lat-long image (scene/environment.h gives the mapping) that
///    read_image reads: OpenEXR or PFM for high dynamic range, PNG (decoded to linear) for low.
///    Radiance .hdr files are refused with a message, not misread as 8-bit pictures.
/// `argument` names where the spec came from in messages: the option ("--env") or a scene
/// file's field ("environment image"). Throws UsageError for a negative colour, a
/// non-finite rotation, or a spec that is neither a colour nor an existing file ("--env: '1,2'
/// is neither R,G,B nor a readable image file: no such file"); InputError naming the file and the
/// option ("sky.exr: --env: pixel (3, 1) is (-1, 0, 0): ...") for a file that cannot be
/// read or decoded, or that holds a negative or non-finite pixel.
Environment load_environment(const std::string& spec_or_path, float rotate_degrees,
                             std::string_view argument = "--env");

}  // namespace raylab
