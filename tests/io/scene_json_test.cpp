// The scene format: every shipped scene loads and renders; every mistake a user can make in a
// scene file is reported at its line and column with a message that says what is valid.

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <span>

#include "../test_paths.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/io/format_losses.h"
#include "raylab/io/scene_json.h"
#include "raylab/io/scene_json_writer.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/camera_path.h"
#include "raylab/scene/environment.h"
#include "raylab/scene/scene_merge.h"
#include "raylab/scene/spd.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(raylab::test::source_dir()) / "scenes";

// Parses `text` as a scene file in `dir`; returns the InputError message, or "" on success.
std::string error_of(const std::string& text, const std::string& dir = ".", LoadOptions options = {}) {
  try {
    parse_scene_json(text, "s.json", dir, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kMinimal = R"({"version": 1, "materials": {"m": {}}, "objects": [
  {"type": "sphere", "material": "m", "center": [0, 0, 0], "radius": 1}]})";

TEST(SceneJson, EveryShippedSceneLoadsAndRenders) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "scene.schema.json") continue;
    SCOPED_TRACE(entry.path().string());
    Scene scene = load_scene(entry.path().string());
    ASSERT_GT(scene.geometry.size(), 0u);
    ASSERT_FALSE(scene.lights.empty());
    scene.settings.width = 48;
    scene.settings.height = 32;
    scene.settings.spp = 1;
    const auto accel = make_accelerator("bvh", scene.geometry);
    Film film(48, 32);
    RenderOptions options;
    options.threads = 1;
    render(scene, *accel, film, options);
    // The camera must see the scene: some pixels differ from the background, and none is NaN.
    int differing = 0;
    for (int y = 0; y < 32; ++y) {
      for (int x = 0; x < 48; ++x) {
        const Color c = film.at(x, y);
        ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
        const Color d = c - scene.settings.background;
        differing += std::abs(d.x) + std::abs(d.y) + std::abs(d.z) > 0.02f;
      }
    }
    EXPECT_GT(differing, 48 * 32 / 10);
    ++count;
  }
  EXPECT_GE(count, 4);
}

TEST(SceneJson, MinimalSceneGetsFittedCameraAndDefaults) {
  const Scene s = parse_scene_json(kMinimal, "s.json", ".");
  EXPECT_EQ(s.geometry.spheres.size(), 1u);
  EXPECT_EQ(s.settings.width, RenderSettings{}.width);
  // No camera in the file: framed from the bounds, looking at the sphere's centre.
  EXPECT_NEAR(s.camera.at.x, 0.f, 1e-6f);
  EXPECT_GT(length(s.camera.from - s.camera.at), 1.f);
  EXPECT_FALSE(s.lights.empty());
}

TEST(SceneJson, SettingsCameraMaterialsAndLightsAreRead) {
  const Scene s = parse_scene_json(R"({"version": 1,
    "camera": {"from": [1, 2, 3], "at": [0, 1, 0], "up": [0, 0, 1], "fov": 30, "fov_span": "pixel-centres", "hither": 0.5},
    "render": {"width": 33, "height": 17, "spp": 9, "max_depth": 3, "seed": 7, "background": [0.1, 0.2, 0.3]},
    "materials": {"glass": {"color": 0.5, "transmittance": 0.9, "ior": 1.33, "fresnel": false}},
    "lights": [{"type": "point", "position": [0, 5, 0], "intensity": [1, 0.5, 0.25], "falloff": true},
               {"type": "directional", "direction": [0, -2, 0]}],
    "objects": [{"type": "sphere", "material": "glass", "center": [0, 0, 0], "radius": 2}]})",
                                   "s.json", ".");
  EXPECT_EQ(s.settings.width, 33);
  EXPECT_EQ(s.settings.height, 17);
  EXPECT_EQ(s.settings.spp, 9);
  EXPECT_EQ(s.settings.max_depth, 3);
  EXPECT_EQ(s.settings.seed, 7u);
  EXPECT_FLOAT_EQ(s.settings.background.z, 0.3f);
  EXPECT_FLOAT_EQ(s.camera.from.z, 3.f);
  EXPECT_FLOAT_EQ(s.camera.up.z, 1.f);
  EXPECT_FLOAT_EQ(s.camera.vfov_degrees, 30.f);
  EXPECT_EQ(s.camera.fov_span, CameraSpec::FovSpan::kPixelCentres);
  EXPECT_FLOAT_EQ(s.camera.hither, 0.5f);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "glass");
  EXPECT_FLOAT_EQ(s.materials[0].color.y, 0.5f);
  EXPECT_FLOAT_EQ(s.materials[0].ior, 1.33f);
  EXPECT_FALSE(s.materials[0].fresnel);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_TRUE(s.lights[0].falloff);
  EXPECT_FLOAT_EQ(s.lights[0].intensity.z, 0.25f);
  EXPECT_EQ(s.lights[1].kind, Light::Kind::kDirectional);
  EXPECT_FLOAT_EQ(s.lights[1].direction.y, -1.f);  // normalised
}

TEST(SceneJson, TransformsApplyInTheOrderWritten) {
  const fs::path dir = fs::temp_directory_path() / ("raylab-json-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "tri.obj") << "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n";
  // Scale by 2, then rotate 90 degrees about z (x -> y), then translate by (10, 0, 0):
  // (1, 0, 0) -> (2, 0, 0) -> (0, 2, 0) -> (10, 2, 0).
  const std::string text =
      R"({"version": 1, "materials": {"m": {}}, "lights": [{"type": "point", "position": [0, 9, 0]}],
    "camera": {"from": [0, 0, 9], "at": [0, 0, 0]},
    "meshes": {"t": {"file": "tri.obj"}},
    "objects": [
      {"type": "mesh", "file": "tri.obj", "material": "m",
       "transform": [{"scale": 2}, {"rotate": {"axis": [0, 0, 1], "degrees": 90}}, {"translate": [10, 0, 0]}]},
      {"type": "instance", "mesh": "t", "transform": {"matrix": [1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}},
      {"type": "instance", "mesh": "t", "transform": {"scale": [-1, 1, 1]}}]})";
  Scene s = parse_scene_json(text, (dir / "s.json").string(), dir.string());
  // The two placements of mesh "t" are instances of one stored prototype; baked into copies,
  // they follow the mesh object's triangle.
  ASSERT_EQ(s.geometry.triangles.size(), 1u);
  ASSERT_EQ(s.prototypes.size(), 1u);
  ASSERT_EQ(s.instances.size(), 2u);
  EXPECT_EQ(s.primitive_count(), 3u);
  bake_instances(s);
  ASSERT_EQ(s.geometry.triangles.size(), 3u);
  const Triangle& a = s.geometry.triangles[0];
  EXPECT_NEAR(a.p0.x, 10.f, 1e-5f);
  EXPECT_NEAR(a.p0.y, 2.f, 1e-5f);
  EXPECT_NEAR(a.p0.z, 0.f, 1e-5f);
  EXPECT_NEAR(s.geometry.triangles[1].p0.x, 6.f, 1e-6f);
  // The mirror keeps the outward side outward: the winding is flipped back.
  const Vec3 n_orig = triangle_normal(Triangle{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  const Vec3 n_mirror = triangle_normal(s.geometry.triangles[2]);
  EXPECT_LT(n_mirror.x * n_orig.x, 0.f);  // x component mirrored
  EXPECT_GT(n_mirror.y * n_orig.y, 0.f);  // others kept: the normal is the mirror image
  fs::remove_all(dir);
}

TEST(SceneJson, SpdGeneratorObjectBringsItsCameraAndLights) {
  const Scene s = parse_scene_json(R"({"version": 1, "objects": [{"type": "spd", "generator": "balls", "size": 1}]})",
                                   "s.json", ".");
  const Scene direct = make_spd_scene("spd:balls?size=1");
  EXPECT_EQ(s.geometry.spheres.size(), direct.geometry.spheres.size());
  EXPECT_EQ(s.lights.size(), direct.lights.size());
  EXPECT_FLOAT_EQ(s.camera.from.x, direct.camera.from.x);
}

// Each mistake, the position reported, and the words the message must contain.
struct BadScene {
  std::string text;
  const char* position;
  const char* words;
};

// Expects the scene text of each of `cases` to be refused with its position and words.
void expect_refused(std::span<const BadScene> cases) {
  for (const BadScene& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string message = error_of(c.text);
    EXPECT_TRUE(message.starts_with(c.position)) << message;
    EXPECT_NE(message.find(c.words), std::string::npos) << message;
  }
}

TEST(SceneJson, MistakesAreReportedWithLineColumnAndValidChoices) {
  const BadScene cases[] = {
      {R"({"version": 1, "objcts": []})", "s.json:1:16:", "unknown key 'objcts' in the scene (valid: $schema, version"},
      {"{\"version\": 1,\n \"objects\": [\n  {\"type\": \"sphere\", \"material\": \"m\", \"centre\": [0,0,0]}]}",
       "s.json:3:39:", "unknown key 'centre' in object 0 (valid: type, name, material, center, radius)"},
      {R"({"version": 2, "objects": []})", "s.json:1:2:", "version 2 is not supported"},
      {R"({"objects": []})", "s.json:1:1:", "needs \"version\": 1"},
      {R"({"version": 1, "render": {"width": "wide"}, "objects": []})",
       "s.json:1:27:", "'width' must be an integer, found a string"},
      {R"({"version": 1, "render": {"spp": 0}, "objects": []})", "s.json:1:27:", "'spp' is 0, must be in [1, 65536]"},
      {R"({"version": 1, "render": {"sampler": "halton"}, "objects": []})",
       "s.json:1:27:", "(valid: auto, center, regular, random, jittered, cmj, sobol, adaptive-corners, adaptive)"},
      {R"({"version": 1, "objects": [{"type": "sphere", "material": "nope", "center": [0,0,0], "radius": 1}]})",
       "s.json:1:47:", "unknown material 'nope' (the scene defines no materials)"},
      {R"({"version": 1, "objects": [{"type": "blob"}]})", "s.json:1:29:", "'type' is 'blob' (valid: sphere,"},
      {R"({"version": 1, "materials": {"m": {}}, "objects": [{"type": "sphere", "material": "m", )"
       R"("center": [0,0], "radius": 1}]})",
       "s.json:1:88:", "'center' must be an array of 3 numbers, found an array of 2"},
      {R"({"version": 1, "materials": {"m": {}}, "objects": [{"type": "sphere", "material": "m", )"
       R"("center": [0,0,0], "radius": -1}]})",
       "s.json:1:107:", "'radius' is -1, must be greater than 0"},
      {"{\"version\": 1,\n \"objects\": [}", "s.json:2:14:", "JSON"},
      {R"({"version": 1, "version": 1})", "s.json:1:16:", "duplicate key 'version'"},
      {R"({"version": 1, "objects": [{"type": "instance", "mesh": "bunny"}]})", "s.json:1:49:", "unknown mesh 'bunny'"},
      {R"({"version": 1, "objects": [{"type": "spd", "generator": "balls", "transform": {"scale": [1, 2, 1]}}]})",
       "s.json:1:28:", "non-uniform scale"},
      {R"({"version": 1, "objects": [{"type": "spd", "generator": "ballz"}]})",
       "s.json:1:28:", "unknown SPD scene 'ballz'"},
      {"[1, 2]", "s.json:1:1:", "must be an object"},
      {"", "s.json:1:1:", "JSON"},
      {R"({"version": 1, "objects": []})", "s.json:1:16:", "no primitives"},
      // A mesh file whose extension no loader reads (once an uncaught UsageError, found by the fuzzer).
      {R"({"version": 1, "meshes": {"t": {"file": "t.~obj"}}, "objects": []})",
       "s.json:1:33:", "unsupported format '.~obj'"},
      {R"({"version": 1, "objects": [{"type": "mesh", "file": "t.xyz"}]})",
       "s.json:1:45:", "unsupported format '.xyz'"},
      // Material maps: an unknown map, a key a map does not take, a missing file.
      {R"({"version": 1, "materials": {"m": {"maps": {"height": {"file": "h.png"}}}}, "objects": []})",
       "s.json:1:45:", "unknown key 'height' in maps of material 'm' (valid: metallic_roughness, emission,"},
      {R"({"version": 1, "materials": {"m": {"maps": {"emission": {"file": "e.png", "scale": 2}}}}, "objects": []})",
       "s.json:1:75:", "unknown key 'scale' in emission map (valid: file)"},
      {R"({"version": 1, "materials": {"m": {"maps": {"normal": {"file": "n.png"}}}}, "objects": []})",
       "s.json:1:56:", "map file 'n.png' not found"},
  };
  expect_refused(cases);
}

// A scene whose camera (text from line 3 on) is `camera`.
std::string with_camera(const std::string& camera) {
  return "{\"version\": 1, \"materials\": {\"m\": {}}, \"lights\": [{\"type\": \"point\", \"position\": [0, 9, "
         "0]}],\n\"objects\": [{\"type\": \"sphere\", \"material\": \"m\", \"center\": [0, 0, 0], \"radius\": "
         "1}],\n\"camera\": " +
         camera + "}";
}

TEST(SceneJson, CameraPathIsReadWithFieldsFromTheCameraObject) {
  const Scene s = parse_scene_json(with_camera(R"({"from": [1, 2, 3], "at": [0, 1, 0], "up": [0, 0, 1], "fov": 30,
    "fov_span": "pixel-centres", "hither": 0.5,
    "path": {"interpolation": "smooth", "keys": [
      {"frame": 0},
      {"frame": 24, "from": [10, 2, 0], "fov": 20},
      {"frame": 48, "at": [0, 1, 1], "up": [0, 1, 0], "hither": 0.25}]}})"),
                                   "s.json", ".");
  // The still camera is the camera object's own.
  EXPECT_EQ(s.camera.from, Vec3(1.f, 2.f, 3.f));
  EXPECT_EQ(s.camera.at, Vec3(0.f, 1.f, 0.f));
  EXPECT_FLOAT_EQ(s.camera.vfov_degrees, 30.f);
  const CameraPath& p = s.camera_path;
  EXPECT_EQ(p.interpolation, CameraPath::Interpolation::kSmooth);
  ASSERT_EQ(p.keys.size(), 3u);
  EXPECT_EQ(p.keys[0].frame, 0);
  EXPECT_EQ(p.keys[1].frame, 24);
  EXPECT_EQ(p.keys[2].frame, 48);
  // Key 0 gives nothing: the camera object's values.
  EXPECT_EQ(p.keys[0].camera.from, s.camera.from);
  EXPECT_EQ(p.keys[0].camera.up, s.camera.up);
  EXPECT_FLOAT_EQ(p.keys[0].camera.hither, 0.5f);
  // Key 1: its own from and fov, the rest inherited.
  EXPECT_EQ(p.keys[1].camera.from, Vec3(10.f, 2.f, 0.f));
  EXPECT_EQ(p.keys[1].camera.at, s.camera.at);
  EXPECT_EQ(p.keys[1].camera.up, s.camera.up);
  EXPECT_FLOAT_EQ(p.keys[1].camera.vfov_degrees, 20.f);
  EXPECT_FLOAT_EQ(p.keys[1].camera.hither, 0.5f);
  // Key 2 inherits from the camera object, not from key 1.
  EXPECT_EQ(p.keys[2].camera.from, s.camera.from);
  EXPECT_EQ(p.keys[2].camera.at, Vec3(0.f, 1.f, 1.f));
  EXPECT_EQ(p.keys[2].camera.up, Vec3(0.f, 1.f, 0.f));
  EXPECT_FLOAT_EQ(p.keys[2].camera.vfov_degrees, 30.f);
  EXPECT_FLOAT_EQ(p.keys[2].camera.hither, 0.25f);
  for (const CameraKey& k : p.keys) EXPECT_EQ(k.camera.fov_span, CameraSpec::FovSpan::kPixelCentres);

  const Scene linear = parse_scene_json(
      with_camera(R"({"from": [1, 2, 3], "at": [0, 1, 0], "path": {"keys": [{"frame": 5}]}})"), "s.json", ".");
  EXPECT_EQ(linear.camera_path.interpolation, CameraPath::Interpolation::kLinear);
  ASSERT_EQ(linear.camera_path.keys.size(), 1u);
  const Scene still = parse_scene_json(with_camera(R"({"from": [1, 2, 3], "at": [0, 1, 0]})"), "s.json", ".");
  EXPECT_TRUE(still.camera_path.empty());
}

TEST(SceneJson, CameraPathMistakesAreReportedAtTheirKey) {
  // Line 3 is `"camera": {"from": [0, 0, 5], "at": [0, 0, 0], "path": {`, with 'path' at column 48;
  // each case gives the rest of the path object, from line 4 on.
  const auto with_path = [](const std::string& path) {
    return with_camera(R"({"from": [0, 0, 5], "at": [0, 0, 0], "path": {)" + path);
  };
  const BadScene cases[] = {
      {with_path("\n \"keys\": [{\"frame\": 10},\n {\"frame\": 10, \"from\": [1, 0, 5]}]}}"),
       "s.json:5:3:", "'frame' is 10, must be greater than the previous key's (10): keys go in increasing frame order"},
      {with_path("\n \"keys\": [{\"frame\": 0},\n {\"frame\": 20, \"fov_span\": \"edges\"}]}}"),
       "s.json:5:16:", "unknown key 'fov_span' in camera path key 1 (valid: frame, from, at, up, fov, hither)"},
      {with_path("\n \"interpolation\": \"cubic\",\n \"keys\": [{\"frame\": 0}]}}"),
       "s.json:4:2:", "'interpolation' is 'cubic' (valid: linear, smooth)"},
      {with_path("\n \"keys\": [{\"frame\": 0},\n {\"frame\": 10, \"from\": [0, 0, 0]}]}}"),
       "s.json:5:2:", "camera path key 1 (frame 10): 'from' and 'at' are the same point"},
      {with_path("\n \"keys\": [{\"frame\": 0},\n {\"frame\": 3, \"up\": [0, 0, 1]}]}}"),
       "s.json:5:15:", "camera path key 1 (frame 3): 'up' is parallel to the viewing direction"},
      {with_path("\n \"keys\": [{\"frame\": 0, \"from\": [-1, 0, 0]},\n {\"frame\": 10, \"from\": [1, 0, 0]}]}}"),
       "s.json:3:48:", "camera path: the camera at frame 5 has 'from' and 'at' at the same point"},
      {with_path("\n \"bogus\": 1, \"keys\": [{\"frame\": 0}]}}"),
       "s.json:4:2:", "unknown key 'bogus' in 'path' (valid: interpolation, keys)"},
      {with_path("\n \"interpolation\": \"linear\"}}"), "s.json:3:48:", "the camera path needs 'keys'"},
      {with_path("\n \"keys\": []}}"), "s.json:4:2:", "'keys' must be an array of 1 or more keys, found an array of 0"},
      {with_path("\n \"keys\": [\n {\"from\": [1, 0, 5]}]}}"), "s.json:5:2:", "camera path key 0 needs 'frame'"},
      {with_path("\n \"keys\": [{\"frame\": -1}]}}"), "s.json:4:12:", "'frame' is -1, must be in [0, 1000000]"},
      {with_path("\n \"keys\": [{\"frame\": 0.5}]}}"), "s.json:4:12:", "'frame' must be an integer, found a number"},
      {with_path("\n \"keys\": [7]}}"), "s.json:4:2:", "camera path key 0 must be an object, found an integer"},
  };
  expect_refused(cases);
}

TEST(SceneJson, DeepNestingIsRefusedNotARecursionCrash) {
  std::string text = "{\"version\": 1, \"description\": ";
  text += std::string(100000, '[');
  const std::string message = error_of(text);
  EXPECT_NE(message.find("deeper than 64"), std::string::npos) << message;
}

TEST(SceneJson, PathsLeavingTheSceneFolderAreRefusedUnlessAllowed) {
  const fs::path root = fs::temp_directory_path() / ("raylab-paths-" + std::to_string(::getpid()));
  fs::create_directories(root / "scene");
  std::ofstream(root / "outside.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(root / "scene" / "inside.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  fs::create_symlink(root / "outside.obj", root / "scene" / "link.obj");
  auto scene_with = [](const std::string& file) {
    return "{\"version\": 1, \"materials\": {\"m\": {}},\n \"objects\": [{\"type\": \"mesh\", \"material\": \"m\", "
           "\"file\": \"" +
           file + "\"}]}";
  };
  const std::string dir = (root / "scene").string();
  EXPECT_EQ(error_of(scene_with("inside.obj"), dir), "");
  for (const std::string& bad : std::vector<std::string>{"../outside.obj", (root / "outside.obj").string(), "link.obj",
                                                         "./sub/../../outside.obj"}) {
    SCOPED_TRACE(bad);
    const std::string message = error_of(scene_with(bad), dir);
    EXPECT_TRUE(message.starts_with("s.json:2:48:")) << message;
    EXPECT_NE(message.find("--allow-outside-paths"), std::string::npos) << message;
    LoadOptions allow;
    allow.allow_outside_paths = true;
    EXPECT_EQ(error_of(scene_with(bad), dir, allow), "");
  }
  fs::remove_all(root);
}

}  // namespace
}  // namespace raylab

namespace raylab {
namespace {

TEST(SceneJson, SpdSizesOverTheCallersLimitAreRefusedAtTheObject) {
  LoadOptions capped;
  capped.max_spd_size = 3;
  // Size 7 (5 million spheres) is refused before any is made; so is a default size over the cap.
  const std::string big = R"({"version": 1, "objects": [{"type": "spd", "generator": "balls", "size": 7}]})";
  const std::string message = error_of(big, ".", capped);
  EXPECT_TRUE(message.starts_with("s.json:1:28:")) << message;
  EXPECT_NE(message.find("SPD size 7 is over this reader's limit of 3"), std::string::npos) << message;
  const std::string by_default = R"({"version": 1, "objects": [{"type": "spd", "generator": "balls"}]})";
  EXPECT_NE(error_of(by_default, ".", capped).find("SPD size 4"), std::string::npos);
  // Within the cap, and without one, the same objects load.
  EXPECT_EQ(error_of(R"({"version": 1, "objects": [{"type": "spd", "generator": "balls", "size": 2}]})", ".", capped),
            "");
  EXPECT_EQ(error_of(by_default), "");
}

TEST(SceneJson, PhysicallyBasedMembersLightObjectsAndEnvironmentRoundTrip) {
  // A lamp as in the Cornell box: a quad light that names the emissive quad drawing it.
  Scene cornell;
  Material lamp;
  lamp.emission = {1.f, 0.85f, 0.6f};
  lamp.emission_strength = 15.f;
  const std::uint32_t lamp_object = cornell.add_object("light", cornell.add_material(lamp));
  cornell.geometry.add(Quad{{0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}, {1.f, 0.f, 0.f}}, lamp_object);
  Light area;
  area.kind = Light::Kind::kQuad;
  area.object = static_cast<std::int32_t>(lamp_object);
  cornell.lights = {area};
  cornell.settings.integrator = "path";
  auto env = std::make_shared<Environment>();
  env->color = {0.1f, 0.2f, 0.3f};
  env->rotate_degrees = 15.f;
  cornell.environment = env;
  const Scene back = parse_scene_json(encode_scene_json(cornell, "c").json, "c.json", ".");
  EXPECT_EQ(back.settings.integrator, "path");
  ASSERT_EQ(back.lights.size(), 1u);
  ASSERT_GE(back.lights[0].object, 0);
  EXPECT_EQ(back.objects[static_cast<std::size_t>(back.lights[0].object)].name, "light");
  EXPECT_EQ(back.materials[0].emission_strength, 15.f);
  ASSERT_TRUE(back.environment);
  EXPECT_EQ(back.environment->color, env->color);
  EXPECT_EQ(back.environment->rotate_degrees, 15.f);
  const Scene showcase = make_builtin_scene("showcase");
  Scene flat = showcase;
  flat.environment.reset();  // the materials alone here; the sky's image below
  const Scene materials = parse_scene_json(encode_scene_json(flat, "s").json, "s.json", ".");
  // Materials come back in the file's (alphabetical) order: compare object by object.
  ASSERT_EQ(materials.objects.size(), showcase.objects.size());
  for (std::size_t i = 0; i < showcase.objects.size(); ++i) {
    const Material& a = showcase.materials[showcase.objects[i].material];
    const Material& b = materials.materials[materials.objects[i].material];
    EXPECT_EQ(a.model, b.model) << a.name;
    EXPECT_EQ(a.roughness, b.roughness) << a.name;
    EXPECT_EQ(a.conductor_eta, b.conductor_eta) << a.name;
    EXPECT_EQ(a.conductor_k, b.conductor_k) << a.name;
  }
  // The showcase's sky is an image: it goes to a float PFM beside the scene file and comes back
  // bit for bit, with its rotation and scale; only formats other than scene files lose it.
  const fs::path dir = fs::temp_directory_path() / ("raylab-env-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const SceneJsonFiles files = encode_scene_json(showcase, "sky");
  for (const SidecarFile& f : files.textures) std::ofstream(dir / f.name, std::ios::binary) << f.bytes;
  const Scene sky = parse_scene_json(files.json, (dir / "sky.json").string(), dir.string());
  ASSERT_TRUE(sky.environment && sky.environment->image);
  const EnvironmentImage &a = *showcase.environment->image, &b = *sky.environment->image;
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_TRUE(a.texels == b.texels);
  EXPECT_EQ(sky.environment->rotate_degrees, showcase.environment->rotate_degrees);
  EXPECT_EQ(sky.environment->scale, showcase.environment->scale);
  fs::remove_all(dir);
  EXPECT_EQ(losses_message("s.json", format_losses(showcase, ".json", false)).find("environment"), std::string::npos);
  EXPECT_NE(losses_message("s.obj", format_losses(showcase, ".obj", false)).find("environment"), std::string::npos);
}

TEST(SceneJson, ALightNamingNoObjectIsRefused) {
  const std::string text = R"({"version": 1, "materials": {"m": {}},
    "lights": [{"type": "quad", "corner": [0, 1, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "object": "lamp"}],
    "objects": [{"type": "sphere", "material": "m", "center": [0, 0, 0], "radius": 1}]})";
  EXPECT_NE(error_of(text).find("no object is named 'lamp'"), std::string::npos) << error_of(text);
}

}  // namespace
}  // namespace raylab
