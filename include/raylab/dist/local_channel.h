#pragma once
/// \file
/// Channels between threads of one process: the ranks of a distributed render simulated in one
/// test binary, with a way to make a rank fall silent as a crashed process would.

#include <memory>
#include <vector>

#include "raylab/dist/channel.h"

namespace raylab::dist {

/// `size` connected channels, one per rank (index = rank), sharing one set of mailboxes; each
/// may be used by its own thread.
std::vector<std::unique_ptr<Channel>> make_local_channels(int size);

/// Makes `channel` (from make_local_channels) behave like a dead process: from now on what it
/// sends is lost and nothing reaches it.
void silence(Channel& channel);

}  // namespace raylab::dist
