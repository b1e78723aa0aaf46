// `raylab convert IN OUT`: writes any scene source as NFF, OBJ or binary PLY.

#include <fmt/core.h>

#include <memory>
#include <string>

#include "command_setup.h"
#include "commands.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/nff_writer.h"
#include "raylab/io/obj_writer.h"
#include "raylab/io/ply_writer.h"
#include "raylab/io/scene_loader.h"
#include "raylab/scene/scene_merge.h"
#include "raylab/scene/tessellate.h"

namespace raylab::cli {
namespace {

struct ConvertArgs {
  std::string input, output;
  int segments = 32;
  bool allow_outside_paths = false;
  bool quiet = false;
};

int run(const ConvertArgs& args) {
  const std::string ext = lowercase_extension(args.output);
  if (ext != ".nff" && ext != ".obj" && ext != ".ply") {
    throw UsageError("cannot write '" + args.output + "': unsupported output format '" + ext +
                     "' (supported: .nff .obj .ply)");
  }
  check_writable(args.output);
  LoadOptions load;
  load.allow_outside_paths = args.allow_outside_paths;
  Scene scene = load_scene(args.input, load);
  check_not_an_input(args.output, scene.source_files);
  for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  bake_instances(scene);  // the formats written have no instancing: each placement becomes a copy
  std::string bytes;
  if (ext == ".nff") {
    // NFF keeps spheres and cones analytic.
    bytes = encode_nff(scene);
  } else {
    TessellationOptions t;
    t.segments = args.segments;
    t.rings = std::max(2, args.segments / 2);
    scene.geometry = tessellate(scene.geometry, t);
    bytes = ext == ".obj" ? encode_obj(scene) : encode_ply(scene.geometry);
  }
  write_file_atomically(args.output, std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
  if (!args.quiet) {
    fmt::print("wrote {} ({} primitives, {:.1f} MiB)\n", args.output, scene.geometry.size(), bytes.size() / 1048576.0);
  }
  return 0;
}

void add_options(CLI::App& cmd, ConvertArgs& args) {
  cmd.add_option("input", args.input, "Scene: built-in name, spd:NAME[?size=N], or a scene or mesh file")->required();
  cmd.add_option("output", args.output, "Output file: .nff (analytic shapes kept), .obj or .ply (tessellated)")
      ->required();
  cmd.add_option("--segments", args.segments, "Segments around tessellated spheres, cylinders and disks")
      ->check(CLI::Range(3, 1024))
      ->capture_default_str();
  add_loading_flags(cmd, args.allow_outside_paths, args.quiet, "No summary");
}

}  // namespace

CommandRunner add_convert_command(CLI::App& app) {
  return add_command<ConvertArgs>(
      app, "convert", "Write a scene as NFF, OBJ or binary PLY (format from OUT's extension)", add_options, run);
}

}  // namespace raylab::cli
