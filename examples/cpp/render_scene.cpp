// render_scene: renders a scene with the raylab library and writes the image.
//
//   render_scene SCENE OUTPUT [WIDTH HEIGHT]
//
// SCENE is anything `raylab render` takes: a scene file (.json, .nff), a mesh (.obj, .ply, .stl,
// .off, .gltf, .glb), a built-in scene ("demo", "cornell") or an SPD generator ("spd:balls").
// OUTPUT is a .png (8-bit sRGB), .exr or .pfm file. The steps are those of `raylab render`
// without its options: load the scene, build the acceleration structure, render, write.

#include <raylab/accel/two_level.h>
#include <raylab/core/error.h>
#include <raylab/io/image_io.h>
#include <raylab/io/scene_loader.h>
#include <raylab/render/film.h>
#include <raylab/render/renderer.h>
#include <raylab/version.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>

namespace {

// A size argument: a whole number from 1 to 16384, else 0.
int parse_size(const char* text) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return (*end == '\0' && value >= 1 && value <= 16384) ? static_cast<int>(value) : 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: render_scene SCENE OUTPUT [WIDTH HEIGHT]\n");
    return 2;
  }
  // The headers were compiled into this program; raylab::version() is the shared library that
  // was loaded. Before 1.0 the two must be the same minor release.
  if (std::strcmp(raylab::version(), RAYLAB_VERSION_STRING) != 0) {
    std::fprintf(stderr, "warning: built with raylab %s headers, running with library %s\n", RAYLAB_VERSION_STRING,
                 raylab::version());
  }
  try {
    // Everything about the image (size, samples per pixel, sampler, filter, depth) comes with
    // the scene, as RenderSettings; a program may change any of it before rendering.
    raylab::Scene scene = raylab::load_scene(argv[1]);
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    if (argc == 5) {
      scene.settings.width = parse_size(argv[3]);
      scene.settings.height = parse_size(argv[4]);
      if (scene.settings.width == 0 || scene.settings.height == 0) {
        std::fprintf(stderr, "render_scene: WIDTH and HEIGHT must be whole numbers from 1 to 16384\n");
        return 2;
      }
    }
    // Fail on an unknown output format before the render rather than after it.
    raylab::check_image_extension(argv[2]);

    // The structure `raylab render` builds by default: a BVH, with each mesh and each instance
    // as one item of a top level (the default options of SceneAccelOptions). It keeps pointers
    // into the scene, which must outlive it.
    const std::unique_ptr<raylab::Accelerator> accel =
        raylab::make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, raylab::SceneAccelOptions{});

    // The film holds the image; render() fills it from all cores, the same bits for any number
    // of threads.
    raylab::Film film(scene.settings.width, scene.settings.height);
    const raylab::RenderResult result = raylab::render(scene, *accel, film);
    for (const std::string& notice : result.notices) std::fprintf(stderr, "note: %s\n", notice.c_str());

    // The format follows the extension. The file appears whole or not at all.
    raylab::write_image(film, argv[2]);
    std::printf("%s: %d x %d, %d spp, %.3f s (raylab %s)\n", argv[2], film.width(), film.height(), scene.settings.spp,
                result.seconds, raylab::version());
    return 0;
  } catch (const raylab::UsageError& e) {  // a request that cannot be met: unknown scene name, format
    std::fprintf(stderr, "render_scene: %s\n", e.what());
    return 2;
  } catch (const raylab::InputError& e) {  // bad input data, with file:line:col where there is one
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_scene: %s\n", e.what());
    return 1;
  }
}
