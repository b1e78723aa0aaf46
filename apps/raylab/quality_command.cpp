// placeholder: `raylab quality` is being written.
#include "commands.h"

namespace raylab::cli {

CommandRunner add_quality_command(CLI::App& app) {
  app.add_subcommand("quality", "Compare samplers against a reference image (being written)");
  return [] { return 2; };
}

}  // namespace raylab::cli
