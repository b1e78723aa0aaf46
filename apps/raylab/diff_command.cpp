// `raylab diff`: compares two images by RMSE (in 8-bit display steps).

#include <fmt/core.h>

#include <memory>
#include <optional>
#include <string>

#include "command_setup.h"
#include "commands.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/image_io.h"

namespace raylab::cli {
namespace {

struct DiffArgs {
  std::string first, second;
  std::optional<double> max_rmse;
  std::optional<std::string> image;  ///< where to write the difference image
  float scale = 1.f;                 ///< its amplification
};

int compare(const DiffArgs& args) {
  if (args.image) check_writable(*args.image);  // fail before reading, not after
  const Film a = read_image(args.first);
  const Film b = read_image(args.second);
  if (a.width() != b.width() || a.height() != b.height()) {
    throw InputError(args.first, fmt::format("size {}x{} differs from {}'s {}x{}", a.width(), a.height(), args.second,
                                             b.width(), b.height()));
  }
  const double rmse = image_rmse(a, b);
  fmt::print("rmse {:.4f} (8-bit sRGB steps) over {}x{} pixels\n", rmse, a.width(), a.height());
  if (args.image) {
    write_image(difference_image(a, b, args.scale), *args.image);
    fmt::print("wrote {} (|difference| x {})\n", *args.image, args.scale);
  }
  if (args.max_rmse && rmse > *args.max_rmse) {
    fmt::print(stderr, "raylab diff: images differ: rmse {:.4f} > {:.4f}\n", rmse, *args.max_rmse);
    return kExitImagesDiffer;
  }
  return 0;
}

int run(const DiffArgs& args) {
  try {
    return compare(args);
  } catch (const InputError& e) {
    // As cmp does, 1 is the answer "they differ"; a file that could not be compared at all gets
    // a code of its own, so that a script can tell the two apart.
    fmt::print(stderr, "{}\n", e.what());
    return kExitCannotCompare;
  }
}

void add_options(CLI::App& cmd, DiffArgs& args) {
  cmd.option_defaults()->group("Images");
  cmd.add_option("first", args.first, "First image")->required();
  cmd.add_option("second", args.second, "Second image")->required();
  cmd.option_defaults()->group("Threshold");
  cmd.add_option("--max-rmse", args.max_rmse,
                 "Exit with 1 when the RMSE exceeds this (5: an image cannot be read or the sizes differ)")
      ->check(CLI::NonNegativeNumber);
  cmd.option_defaults()->group("Difference image");
  cmd.add_option("--image", args.image,
                 "Also write where the images differ: |first - second| of the display values, times --scale, "
                 "black where they agree");
  cmd.add_option("--scale", args.scale, "Amplification of the --image difference")
      ->check(CLI::Range(1e-3, 1e6))
      ->capture_default_str();
}

}  // namespace

CommandRunner add_diff_command(CLI::App& app) {
  return add_command<DiffArgs>(app, "diff", "Compare two images (.png .exr .pfm) by RMSE in 8-bit sRGB steps",
                               add_options, run);
}

}  // namespace raylab::cli
