// `raylab convert IN OUT`: writes any scene source as a raylab scene file, NFF, OBJ (with its
// MTL) or binary PLY, and says what the target format cannot carry.

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>

#include "command_setup.h"
#include "commands.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/format_losses.h"
#include "raylab/io/mtl_writer.h"
#include "raylab/io/nff_writer.h"
#include "raylab/io/obj_writer.h"
#include "raylab/io/ply_writer.h"
#include "raylab/io/scene_json_writer.h"
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

// `name` beside `output` (in its folder).
std::string beside(const std::string& output, const std::string& name) {
  return (std::filesystem::path(output).parent_path() / name).string();
}

void write_text(const std::string& path, const std::string& bytes) { write_text_atomically(path, bytes); }

// A bare mesh gets a camera and lights made up by the loader: a format without them loses
// nothing of the source.
bool is_bare_mesh(const std::string& source) {
  const std::string ext = lowercase_extension(source);
  return ext == ".obj" || ext == ".gltf" || ext == ".glb" || ext == ".ply" || ext == ".off" || ext == ".stl";
}

int run(const ConvertArgs& args) {
  const std::string ext = lowercase_extension(args.output);
  if (ext != ".json" && ext != ".nff" && ext != ".obj" && ext != ".ply") {
    throw UsageError("cannot write '" + args.output + "': unsupported output format '" + ext +
                     "' (supported: .json .nff .obj .ply)");
  }
  check_writable(args.output);
  LoadOptions load;
  load.allow_outside_paths = args.allow_outside_paths;
  Scene scene = load_scene(args.input, load);
  check_not_an_input(args.output, scene.source_files);
  for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  bake_instances(scene);  // the formats written have no instancing: each placement becomes a copy
  const std::vector<std::string> losses = format_losses(scene, ext, is_bare_mesh(args.input));
  const std::string stem = std::filesystem::path(args.output).stem().string();
  // Files the output refers to are written first, each atomically, so that the output never
  // names a file that is missing or half written.
  std::string bytes;
  if (ext == ".json") {
    SceneJsonFiles files = encode_scene_json(scene, stem);
    for (const SidecarFile& mesh : files.meshes) write_text(beside(args.output, mesh.name), mesh.bytes);
    for (const SidecarFile& image : files.textures) write_text(beside(args.output, image.name), image.bytes);
    bytes = std::move(files.json);
  } else if (ext == ".nff") {
    // NFF keeps spheres and cones analytic.
    bytes = encode_nff(scene);
  } else {
    TessellationOptions t;
    t.segments = args.segments;
    t.rings = std::max(2, args.segments / 2);
    scene.geometry = tessellate(scene.geometry, t);
    if (ext == ".obj") {
      const std::string mtl = stem + ".mtl";
      write_text(beside(args.output, mtl), encode_mtl(scene));
      bytes = encode_obj(scene, mtl);
    } else {
      bytes = encode_ply(scene.geometry);
    }
  }
  write_text(args.output, bytes);
  if (!args.quiet) {
    if (!losses.empty()) fmt::print(stderr, "warning: {}\n", losses_message(args.output, losses));
    fmt::print("wrote {} ({} primitives, {:.1f} MiB)\n", args.output, scene.geometry.size(), bytes.size() / 1048576.0);
  }
  return 0;
}

void add_options(CLI::App& cmd, ConvertArgs& args) {
  cmd.option_defaults()->group("Files");
  cmd.add_option("input", args.input, "Scene: built-in name, spd:NAME[?size=N], or a scene or mesh file")->required();
  cmd.add_option(
         "output", args.output,
         "Output file: .json (a raylab scene), .nff (analytic shapes kept), .obj with .mtl, or .ply (tessellated)")
      ->required();
  cmd.option_defaults()->group("Tessellation");
  cmd.add_option("--segments", args.segments, "Segments around tessellated spheres, cylinders and disks")
      ->check(CLI::Range(3, 1024))
      ->capture_default_str();
  cmd.option_defaults()->group("Reporting");
  add_loading_flags(cmd, args.allow_outside_paths, args.quiet, "No summary");
}

}  // namespace

CommandRunner add_convert_command(CLI::App& app) {
  return add_command<ConvertArgs>(
      app, "convert", "Write a scene as a raylab scene file, NFF, OBJ or binary PLY (format from OUT's extension)",
      add_options, run);
}

}  // namespace raylab::cli
