#pragma once
/// \file
/// The subcommands of the raylab command line. Each registers its options on the app and returns
/// the function that runs it; exit codes: 0 success, 1 input error, 2 usage error.

#include <CLI/CLI.hpp>
#include <functional>

namespace raylab::cli {

/// The exit codes of the command line, one table for every subcommand (docs/command-line.md,
/// "Exit codes"). 0 is success.
enum ExitCode : int {
  kExitInputError = 1,     ///< bad input: an unreadable or malformed file, an unwritable output
  kExitUsageError = 2,     ///< bad usage: an unknown option or name, a value out of range
  kExitInternalError = 3,  ///< a bug
  kExitDisagreement = 4,   ///< compare, bench: two tracers disagree on some ray
  kExitImagesDiffer = 1,   ///< diff: the images differ by more than --max-rmse (as cmp's 1)
  kExitCannotCompare = 5,  ///< diff: an image cannot be read, or the sizes differ
};

/// A subcommand's body, run after parsing; returns the process exit code.
using CommandRunner = std::function<int()>;

/// `raylab render [SCENE] ...`: renders a scene to an image.
CommandRunner add_render_command(CLI::App& app);

/// `raylab diff A B [--max-rmse X]`: compares two images; exits 1 when they differ by more than
/// X, 5 when one cannot be read or their sizes differ.
CommandRunner add_diff_command(CLI::App& app);

/// `raylab info SCENE`: counts, bounds, materials, lights, camera, load time and memory.
CommandRunner add_info_command(CLI::App& app);

/// `raylab convert IN OUT`: writes a scene as NFF, OBJ or binary PLY.
CommandRunner add_convert_command(CLI::App& app);

/// `raylab compare SCENE [--accels A,B,...]`: every structure on the same rays, side by side;
/// exits 4 when two structures disagree on some ray.
CommandRunner add_compare_command(CLI::App& app);

/// `raylab quality SCENE [--reference REF|auto] [--budgets ...]`: every sampler at every budget
/// against a reference image, side by side.
CommandRunner add_quality_command(CLI::App& app);

/// `raylab bench SCENE [--rays KIND] [--against embree|none] ...`: our accelerator against Embree
/// on the same rays; exits 4 when the two disagree on some ray.
CommandRunner add_bench_command(CLI::App& app);

}  // namespace raylab::cli
