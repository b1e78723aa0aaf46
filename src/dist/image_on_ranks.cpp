#include "raylab/dist/image_on_ranks.h"

#include "raylab/core/interrupt.h"
#include "raylab/dist/rank_failure.h"
#include "raylab/io/atomic_file.h"
#include "raylab/render/tile_renderer.h"

namespace raylab::dist {

ImageOnRanks render_image_on_ranks(Channel& channel, const Scene& scene, const Accelerator& accel,
                                   DistributedOptions options) {
  const bool root = channel.rank() == 0;
  const RenderSettings& s = scene.settings;
  options.render.should_stop = [] { return interrupt_signal() != 0; };
  TileRenderer renderer(scene, accel, options.render);
  ImageOnRanks out;
  out.film = Film(root ? s.width : 0, root ? s.height : 0);
  // From here the first signal stops handing out tiles and saves what is done.
  install_interrupt_handlers(remove_pending_temporary_files, false);
  try {
    out.result = render_distributed(channel, renderer, out.film, options);
  } catch (const std::exception& e) {
    // Not a rank's failure the protocol reports (those end the run in order): a bug or a
    // resource running out here. The others must not wait for this rank until they time out.
    out.exit_status = fail_outside_protocol(channel, e);
    return out;
  }
  const bool complete = out.result.outcome == DistributedOutcome::kComplete;
  if (!root) {
    const int signal = interrupt_signal();
    out.exit_status = complete ? 0 : signal != 0 ? interrupt_exit_status(signal) : 1;
    return out;
  }
  // Saved once already as the run ended; again now that rank 0's own last tiles are in.
  if (!complete) options.render.on_checkpoint(*options.render.progress);
  return out;
}

}  // namespace raylab::dist
