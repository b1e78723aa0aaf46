#pragma once
/// \file
/// What every subcommand sets up alike: its arguments held for the runner, and the options
/// several commands share with the same words.

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "commands.h"
#include "raylab/scene/scene.h"

namespace raylab::cli {

/// Adds subcommand `name` to `app`: `add_options` binds its options to an Args that lives as long
/// as the returned runner, which calls `run` with it after parsing.
template <class Args>
CommandRunner add_command(CLI::App& app, const std::string& name, const std::string& description,
                          void (*add_options)(CLI::App&, Args&), int (*run)(const Args&)) {
  auto args = std::make_shared<Args>();
  add_options(*app.add_subcommand(name, description), *args);
  return [args, run] { return run(*args); };
}

/// Adds the required SCENE argument of the commands that measure a scene (compare, quality, bench).
void add_scene_argument(CLI::App& cmd, std::string& scene);

/// Adds --threads (0 to 1024, 0 = all cores), described by `description`. A count above this
/// machine's cores gets one note on stderr (the library uses the cores there are).
void add_threads_option(CLI::App& cmd, int& threads, const std::string& description = "Worker threads; 0 = all cores");

/// Usage and input errors about the table outputs of compare and quality, before the work: a
/// --plot that is not .svg, a --csv, --json or --plot that cannot be written (empty: not asked).
void check_table_outputs(const std::string& csv, const std::string& json, const std::string& plot);

/// Usage error when one of `outputs` (empty: not asked, "-": stdout) is one of the files `scene`
/// was read from (Scene::source_files): checked once the scene is loaded, before the work.
void check_not_inputs(const Scene& scene, std::initializer_list<const std::string*> outputs);

/// Adds the table outputs of compare and quality (checked by check_table_outputs): --csv and
/// --json, the table as such a file, and --plot, an SVG chart described by `plot_description`.
void add_table_output_options(CLI::App& cmd, std::string& csv, std::string& json, std::string& plot,
                              const std::string& plot_description);

/// Prints "wrote PATH" on stderr for each of `paths` that is not empty.
void print_written(std::initializer_list<const std::string*> paths);

/// Adds --allow-outside-paths: a scene file may reference files outside its own folder.
void add_allow_outside_paths_flag(CLI::App& cmd, bool& allow);

/// Adds the flags of a command that loads a scene and reports on stderr: --allow-outside-paths,
/// then -q,--quiet, described by what it silences (`quiet_description`).
void add_loading_flags(CLI::App& cmd, bool& allow_outside_paths, bool& quiet, const std::string& quiet_description);

}  // namespace raylab::cli
