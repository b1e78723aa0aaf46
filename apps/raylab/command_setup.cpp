#include "command_setup.h"

#include <fmt/core.h>

#include "raylab/core/error.h"
#include "raylab/core/thread_count.h"
#include "raylab/dist/launcher.h"
#include "raylab/io/atomic_file.h"

namespace raylab::cli {

void add_scene_argument(CLI::App& cmd, std::string& scene) {
  cmd.add_option("scene", scene, "Scene: a built-in name, an SPD generator (spd:balls) or a file")->required();
}

void add_threads_option(CLI::App& cmd, int& threads, const std::string& description) {
  // The library caps the threads at the cores (usable_threads); the user hears of it once, here
  // (under MPI from rank 0 only, as every rank would say the same).
  cmd.add_option("--threads", threads, description)
      ->check(CLI::Range(0, 1024))
      ->capture_default_str()
      ->each([](const std::string& value) {
        if (dist::launched_by_mpi() && dist::launcher_rank() != 0) return;
        if (const std::string note = thread_count_notice(std::stoi(value)); !note.empty()) {
          fmt::print(stderr, "note: {}\n", note);
        }
      });
}

void check_table_outputs(const std::string& csv, const std::string& json, const std::string& plot) {
  if (!plot.empty() && !plot.ends_with(".svg")) {
    throw UsageError("cannot write '" + plot + "': the plot is an SVG file (.svg)");
  }
  for (const std::string* path : {&csv, &json, &plot}) {
    if (!path->empty()) check_writable(*path);  // fail before the work, not after it
  }
}

void check_not_inputs(const Scene& scene, std::initializer_list<const std::string*> outputs) {
  for (const std::string* path : outputs) {
    if (!path->empty() && *path != "-") check_not_an_input(*path, scene.source_files);
  }
}

void add_table_output_options(CLI::App& cmd, std::string& csv, std::string& json, std::string& plot,
                              const std::string& plot_description) {
  cmd.add_option("--csv", csv, "Also write the table as CSV to this file");
  cmd.add_option("--json", json, "Also write the table as JSON to this file");
  cmd.add_option("--plot", plot, plot_description);
}

void print_written(std::initializer_list<const std::string*> paths) {
  for (const std::string* path : paths) {
    if (!path->empty()) fmt::print(stderr, "wrote {}\n", *path);
  }
}

void add_allow_outside_paths_flag(CLI::App& cmd, bool& allow) {
  cmd.add_flag("--allow-outside-paths", allow, "Let a scene file reference files outside its own folder");
}

void add_loading_flags(CLI::App& cmd, bool& allow_outside_paths, bool& quiet, const std::string& quiet_description) {
  add_allow_outside_paths_flag(cmd, allow_outside_paths);
  cmd.add_flag("-q,--quiet", quiet, quiet_description);
}

}  // namespace raylab::cli
