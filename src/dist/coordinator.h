#pragma once
// Internal to the dist module: rank 0's side of a distributed render (see distributed_render.h).

#include "raylab/dist/distributed_render.h"

namespace raylab::dist {

/// Runs rank 0: hands out tiles, renders some itself, gathers the sums, develops `film`.
DistributedResult coordinate(Channel& channel, TileRenderer& renderer, Film& film, const DistributedOptions& options);

/// Runs any other rank: renders the tiles rank 0 sends until told to stop.
DistributedResult serve(Channel& channel, TileRenderer& renderer, const DistributedOptions& options);

/// "60 s", "0.5 s": a timeout for messages.
std::string seconds_text(double seconds);

}  // namespace raylab::dist
