// `raylab render --frames A:B`: an animation along the scene's camera path. Frames are the unit
// of work: in one process they are rendered one after the other; under MPI rank 0 hands them
// out as ranks finish the last (the same coordination over a one-rank channel in one process).

#include <fmt/core.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <optional>

#include "raylab/core/error.h"
#include "raylab/core/index_ranges.h"
#include "raylab/core/interrupt.h"
#include "raylab/core/stopwatch.h"
#include "raylab/dist/distributed_frames.h"
#include "raylab/dist/launcher.h"
#include "raylab/dist/local_channel.h"
#include "raylab/dist/mpi_channel.h"
#include "raylab/io/atomic_file.h"
#include "raylab/render/progress.h"
#include "render_modes.h"

namespace raylab::cli {

std::optional<std::pair<int, int>> parse_frame_range(const std::string& text) {
  const std::size_t colon = text.find(':');
  auto number = [](const std::string& t) -> std::optional<int> {
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return std::stoi(t);
  };
  const std::optional<int> a = number(text.substr(0, colon));
  const std::optional<int> b = colon == std::string::npos ? a : number(text.substr(colon + 1));
  if (!a || !b || *b < *a) return std::nullopt;
  return std::pair{*a, *b};
}

std::string frame_output(const std::string& output, int frame) {
  const std::size_t hash = output.find('#');
  if (hash != std::string::npos) {
    const std::size_t end = output.find_first_not_of('#', hash);
    const std::size_t width = (end == std::string::npos ? output.size() : end) - hash;
    return output.substr(0, hash) + fmt::format("{:0{}}", frame, width) + output.substr(hash + width);
  }
  const std::string number = fmt::format(".{:04}", frame);
  const std::size_t dot = output.rfind('.');
  const std::size_t slash = output.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return output + number;
  return output.substr(0, dot) + number + output.substr(dot);
}

int run_frames(const RenderArgs& given) {
  if (given.passes || given.checkpoint || given.resume) {
    throw UsageError(
        "--frames renders each frame in one go: no --passes, --checkpoint or --resume (frames "
        "already written can be skipped by giving a later --frames range)");
  }
  const auto [first, last] = *parse_frame_range(*given.frames);
  install_interrupt_handlers(remove_pending_temporary_files, true);
  std::optional<dist::MpiSession> session;
  std::vector<std::unique_ptr<dist::Channel>> local;
  dist::Channel* channel = nullptr;
  if (dist::launched_by_mpi()) {
    require_mpi_build();
    session.emplace();
    channel = &session->channel();
  } else {
    local = dist::make_local_channels(1);
    channel = local[0].get();
  }
  const bool root = channel->rank() == 0;
  std::unique_ptr<RenderSetup> prepared;
  try {
    if (root) check_writable(frame_output(given.output, first));
    prepared = prepare_render(given, false);
    if (prepared->scene.camera_path.empty()) {
      throw UsageError("--frames needs a camera path, and the scene '" + given.scene +
                       "' has none (a scene file's \"camera\": {\"path\": ...}; see docs/scene-format.md)");
    }
  } catch (const std::exception& e) {
    return fail_outside_protocol(*channel, e);  // (one process: rethrown, there is no other rank)
  }
  RenderSetup& setup = *prepared;
  const RenderArgs& args = setup.args;
  const RenderSettings& s = setup.scene.settings;

  dist::FramesOptions options;
  for (int f = first; f <= last; ++f) options.frames.push_back(f);
  options.agreement = render_agreement(setup);
  options.threads = render_thread_count(render_options(setup));
  options.rank_timeout_seconds = args.rank_timeout;
  options.host = session ? session->host() : "local";
  options.should_stop = [] { return interrupt_signal() != 0; };
  // One frame at a time per process: the scene's camera is set for the frame, then rendered.
  options.render_frame = [&](int frame) {
    setup.scene.camera = setup.scene.camera_path.at(frame);
    dist::RenderedFrame out;
    out.frame = frame;
    out.film = Film(s.width, s.height);
    RenderOptions render_opts = render_options(setup);
    render_opts.should_stop = [] { return interrupt_signal() != 0; };
    out.result = render(setup.scene, *setup.accel, out.film, render_opts);
    return out;
  };
  const bool interactive = ::isatty(STDERR_FILENO) != 0;
  std::optional<ProgressBar> bar;
  int written = 0;
  const int total = last - first + 1;
  RenderStats totals;
  if (root) {
    if (!args.quiet) bar.emplace("frames", stderr, interactive);
    options.on_frame = [&](const dist::RenderedFrame& f) {
      const std::string path = frame_output(args.output, f.frame);
      write_outputs(args, path, f.film, f.result.samples_per_pixel);
      totals += f.result.stats;
      ++written;
      if (bar) bar->update(written, total);
      if (!args.quiet && !interactive) fmt::print(stderr, "frame {}: wrote {}\n", f.frame, path);
    };
    options.on_stopping = print_stopping;
  }
  // From here the first signal stops handing out frames; the frames written stay.
  install_interrupt_handlers(remove_pending_temporary_files, false);
  const auto start = std::chrono::steady_clock::now();
  dist::FramesResult result;
  try {
    result = dist::render_frames_distributed(*channel, options);
  } catch (const std::exception& e) {
    return fail_outside_protocol(*channel, e);
  }
  const double seconds = seconds_since(start);
  if (!root) {
    if (result.outcome == dist::DistributedOutcome::kComplete) return 0;
    return interrupt_signal() != 0 ? interrupt_exit_status(interrupt_signal()) : 1;
  }
  if (result.outcome != dist::DistributedOutcome::kComplete) {
    if (bar) bar->finish(result.outcome == dist::DistributedOutcome::kFailed ? "failed" : "interrupted");
    fmt::print(stderr, "raylab: {} of {} frames written; not rendered: {}\n", written, total,
               index_ranges(result.unfinished));
    if (result.outcome == dist::DistributedOutcome::kFailed) return 1;
    return interrupt_exit_status(interrupt_signal() != 0 ? interrupt_signal() : SIGTERM);
  }
  if (bar) bar->finish(fmt::format("{} frames, {}x{}, {} rays", total, s.width, s.height, totals.total_rays()));
  if (args.stats) {
    print_stats(totals, setup.accel->info(), seconds);
    print_rank_table(result.ranks, "frames");
  }
  if (!args.quiet) {
    fmt::print("wrote frames {}-{} as {} ({}x{}, --accel {}, {} rank{}) in {}\n", first, last,
               frame_output(args.output, first), s.width, s.height, args.accel, channel->size(),
               channel->size() > 1 ? "s" : "", ProgressBar::format_duration(seconds));
  }
  return 0;
}

}  // namespace raylab::cli
