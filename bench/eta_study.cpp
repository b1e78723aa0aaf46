// What the progress bar's ETA is worth (issue 21, item 6): renders a scene with the tiles row by
// row and with the tiles scattered (RenderOptions::scattered_tiles), noting when each tile
// finished, and prints the ETA's error after 20%, 40% and 60% of the tiles against the time that
// really remained. Three estimates: the share of tiles done (ProgressBar::eta_seconds) in each
// order, and, row by row, one weighted by measured tile cost (each tile not yet rendered is taken
// to cost what the finished tiles of its column cost on average). One thread, so that the tiles
// finish in the order they start and the time between two is the cost of the second.
//
//   raylab_eta_study SCENE WIDTH HEIGHT SPP

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "raylab/accel/two_level.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/progress.h"
#include "raylab/render/renderer.h"

namespace {

using namespace raylab;

// When each tile finished (seconds since the render started), in the order they finished.
std::vector<double> finish_times(const Scene& scene, const Accelerator& accel, bool scattered) {
  Film film(scene.settings.width, scene.settings.height);
  RenderOptions options;
  options.threads = 1;
  options.scattered_tiles = scattered;
  std::vector<double> times;
  const auto start = std::chrono::steady_clock::now();
  options.on_progress = [&](int, int) {
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  };
  render(scene, accel, film, options);
  return times;
}

// The ETA's error, as a share of the time that really remained, once `fraction` of the tiles are
// done; `eta(done)` is the estimate then.
template <class Eta>
double eta_error(const std::vector<double>& times, double fraction, Eta eta) {
  const int done = static_cast<int>(std::lround(fraction * static_cast<double>(times.size())));
  const double remaining = times.back() - times[static_cast<std::size_t>(done - 1)];
  return (eta(done) - remaining) / remaining;
}

// Row by row: the tiles left, each at the mean cost of the finished tiles of its column.
double cost_weighted_eta(const std::vector<double>& times, int done, int columns) {
  std::vector<double> cost(static_cast<std::size_t>(columns), 0.0);
  std::vector<int> count(static_cast<std::size_t>(columns), 0);
  for (int t = 0; t < done; ++t) {
    const double took = times[static_cast<std::size_t>(t)] - (t > 0 ? times[static_cast<std::size_t>(t - 1)] : 0.0);
    cost[static_cast<std::size_t>(t % columns)] += took;
    ++count[static_cast<std::size_t>(t % columns)];
  }
  const double elapsed = times[static_cast<std::size_t>(done - 1)];
  double left = 0.0;
  for (int t = done; t < static_cast<int>(times.size()); ++t) {
    const auto c = static_cast<std::size_t>(t % columns);
    left += count[c] > 0 ? cost[c] / count[c] : elapsed / done;
  }
  return left;
}

void print_row(const std::string& scene, const std::string& how, const std::vector<double>& times, auto eta) {
  fmt::print("| {} | {} |", scene, how);
  for (double f : {0.2, 0.4, 0.6}) fmt::print(" {:+.0f}% |", 100.0 * eta_error(times, f, eta));
  fmt::print(" {:.1f} |\n", times.back());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    fmt::print(stderr, "usage: raylab_eta_study SCENE WIDTH HEIGHT SPP\n");
    return 2;
  }
  Scene scene = load_scene(argv[1]);
  scene.settings.width = std::atoi(argv[2]);
  scene.settings.height = std::atoi(argv[3]);
  scene.settings.spp = std::atoi(argv[4]);
  const std::unique_ptr<Accelerator> accel =
      make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, SceneAccelOptions{});
  const int columns = (scene.settings.width + RenderOptions{}.tile_size - 1) / RenderOptions{}.tile_size;
  const std::string name = argv[1];
  const std::vector<double> rows = finish_times(scene, *accel, false);
  const std::vector<double> scattered = finish_times(scene, *accel, true);
  const int total = static_cast<int>(rows.size());
  print_row(name, "row by row, share of tiles", rows,
            [&](int done) { return ProgressBar::eta_seconds(done, total, rows[std::size_t(done - 1)]); });
  print_row(name, "row by row, weighted by tile cost", rows,
            [&](int done) { return cost_weighted_eta(rows, done, columns); });
  print_row(name, "scattered, share of tiles", scattered,
            [&](int done) { return ProgressBar::eta_seconds(done, total, scattered[std::size_t(done - 1)]); });
  return 0;
}
