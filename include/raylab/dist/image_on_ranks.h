#pragma once
/// \file
/// One image across the ranks of a job as a program running on each rank renders it: around
/// render_distributed, the interrupt handling, the errors outside the protocol (fail_outside_protocol)
/// and the checkpoint that a run ending early always leaves. The program prepares the scene and
/// the accelerator on every rank before, and reports (rank 0) after.

#include "raylab/accel/accelerator.h"
#include "raylab/dist/channel.h"
#include "raylab/dist/distributed_render.h"
#include "raylab/render/film.h"
#include "raylab/scene/scene.h"

namespace raylab::dist {

/// What render_image_on_ranks returns.
struct ImageOnRanks {
  DistributedResult result;  ///< as render_distributed returns it
  Film film{0, 0};           ///< rank 0: the image (also of an interrupted run); other ranks: empty
  /// The exit status for this process on a rank other than 0: 0 when complete, the interrupt's
  /// (interrupt_exit_status), 1 when the run failed, or fail_outside_protocol's. Rank 0: 0 (it
  /// reports from result.outcome).
  int exit_status = 0;
};

/// Renders `scene` (at its settings, through `accel`) across the ranks of `channel`; every rank
/// calls this with a scene and settings alike. `options.render.should_stop` is set here to this
/// process's interrupt (interrupt_signal). Rank 0 must set options.render.progress and
/// options.render.on_checkpoint: a run that ends early calls on_checkpoint as it ends and again
/// once rank 0's own last tiles are in. Installs the interrupt handlers so that the first signal
/// stops handing out tiles and saves what is done (install_interrupt_handlers, temporary files
/// removed at a second). An exception out of the protocol goes through fail_outside_protocol
/// (on rank 0 it is rethrown).
ImageOnRanks render_image_on_ranks(Channel& channel, const Scene& scene, const Accelerator& accel,
                                   DistributedOptions options);

}  // namespace raylab::dist
