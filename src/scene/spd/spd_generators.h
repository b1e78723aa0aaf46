#pragma once
// Internal: the seven SPD generators, one file each; registered in spd.cpp.

#include "raylab/scene/spd.h"

namespace raylab::spd {

/// Each returns its generator's registry entry.
SpdGenerator balls();
SpdGenerator gears();
SpdGenerator mount();
SpdGenerator rings();
SpdGenerator teapot();
SpdGenerator tetra();
SpdGenerator tree();

}  // namespace raylab::spd
