#include "command_setup.h"

namespace raylab::cli {

void add_scene_argument(CLI::App& cmd, std::string& scene) {
  cmd.add_option("scene", scene, "Scene: a built-in name, an SPD generator (spd:balls) or a file")->required();
}

void add_threads_option(CLI::App& cmd, int& threads, const std::string& description) {
  cmd.add_option("--threads", threads, description)->check(CLI::Range(0, 1024))->capture_default_str();
}

void add_allow_outside_paths_flag(CLI::App& cmd, bool& allow) {
  cmd.add_flag("--allow-outside-paths", allow, "Let a scene file reference files outside its own folder");
}

}  // namespace raylab::cli
