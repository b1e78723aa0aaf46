// The camera flags through the real binary: --up and its detection for meshes, --camera-from,
// --camera-at, --camera-up, --fov and --orbit for any scene, each changing the image as it says;
// their usage errors; their place in a checkpoint; and the default look of a bare mesh.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "../test_paths.h"
#include "cli_fixture.h"
#include "raylab/io/checkpoint_file.h"
#include "raylab/io/checkpoint_resume.h"
#include "raylab/io/image_io.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/render_progress.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/scene_fingerprint.h"

namespace raylab {
namespace {

using namespace cli_test;

const std::string kWhitted = "'" + raylab::test::source_dir() + "/scenes/whitted.json'";
// whitted.json's own camera, as its file gives it.
const std::string kWhittedCamera = "--camera-from 0,1.6,6 --camera-at 0,0.9,0 --camera-up 0,1,0 --fov 40";
const std::string kSmall = " --width 48 --height 30 --spp 1 --sampler center -q";

// A square pyramid standing on its base in the z = 0 plane, apex up +Z, as scanners and CAD
// programs write their meshes.
const char kZUpPyramid[] =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 0 2\n"
    "f 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";

// A UV sphere of radius 1, with faces that no light of the fitted camera reaches.
std::string sphere_obj() {
  const int rings = 12, segments = 24;
  std::string text = "v 0 1 0\nv 0 -1 0\n";
  for (int r = 1; r < rings; ++r) {
    const double theta = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      text += "v " + std::to_string(std::sin(theta) * std::cos(phi)) + " " + std::to_string(std::cos(theta)) + " " +
              std::to_string(std::sin(theta) * std::sin(phi)) + "\n";
    }
  }
  const auto ring_vertex = [&](int r, int s) { return std::to_string(3 + (r - 1) * segments + s % segments); };
  for (int s = 0; s < segments; ++s) {
    text += "f 1 " + ring_vertex(1, s + 1) + " " + ring_vertex(1, s) + "\n";
    text += "f 2 " + ring_vertex(rings - 1, s) + " " + ring_vertex(rings - 1, s + 1) + "\n";
    for (int r = 1; r + 1 < rings; ++r) {
      text += "f " + ring_vertex(r, s) + " " + ring_vertex(r, s + 1) + " " + ring_vertex(r + 1, s + 1) + " " +
              ring_vertex(r + 1, s) + "\n";
    }
  }
  return text;
}

// Mean absolute difference per channel of two images of one size.
double difference(const Film& a, const Film& b) {
  double sum = 0.0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Color d = a.at(x, y) - b.at(x, y);
      sum += std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    }
  }
  return sum / (3.0 * a.width() * a.height());
}

// Pixels that differ from the top-left one (the background of a framed mesh).
int covered(const Film& f) {
  int n = 0;
  for (const Color& c : f.pixels()) n += !(c == f.pixels()[0]);
  return n;
}

class CameraFlags : public Cli {
 protected:
  // Renders `scene` with `flags` to a PFM in `out`; returns it (an empty film on failure).
  Film render(const std::string& scene, const std::string& flags, const std::string& name = "r.pfm") {
    const CliResult r = run("render " + scene + " " + flags + " -o '" + out_file(name) + "'");
    EXPECT_EQ(r.code, 0) << r.err;
    return r.code == 0 ? read_image(out_file(name)) : Film(1, 1);
  }
  // Runs `args`, which must be refused as a usage error naming `flag`, leaving nothing behind.
  void expect_usage_error(const std::string& args, const std::string& flag) {
    SCOPED_TRACE(args);
    // Only render takes an output image; compare and quality would refuse -o before the flag.
    const std::string output = args.starts_with("render") ? " -q -o '" + out_file("bad.png") + "'" : " -q";
    const CliResult r = run(args + output);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
    expect_out_empty();
  }
};

TEST_F(CameraFlags, TheScenesOwnCameraGivenAsFlagsGivesTheSameImage) {
  const Film own = render(kWhitted, kSmall);
  const Film flags = render(kWhitted, kSmall + " " + kWhittedCamera);
  EXPECT_EQ(difference(own, flags), 0.0);
  // Another eye is another image.
  EXPECT_GT(difference(own, render(kWhitted, kSmall + " --camera-from 2,1.6,6")), 0.01);
}

TEST_F(CameraFlags, AWholeOrbitIsNoOrbitAndAHalfOrbitLooksFromBehind) {
  const Film own = render(kWhitted, kSmall);
  EXPECT_EQ(difference(own, render(kWhitted, kSmall + " --orbit 360")), 0.0);
  const Film half = render(kWhitted, kSmall + " --orbit 180");
  EXPECT_GT(difference(own, half), 0.01);
  // Turned half way about +Y through 'at' (0, 0.9, 0), the eye (0, 1.6, 6) goes to (0, 1.6, -6).
  EXPECT_LT(difference(half, render(kWhitted, kSmall + " --camera-from 0,1.6,-6")), 1e-4);
}

TEST_F(CameraFlags, AnUpsideDownUpTurnsTheImageHalfWay) {
  const Film own = render(kWhitted, kSmall);
  const Film turned = render(kWhitted, kSmall + " --camera-up 0,-1,0");
  Film back(own.width(), own.height());
  for (int y = 0; y < own.height(); ++y) {
    for (int x = 0; x < own.width(); ++x) back.at(x, y) = turned.at(own.width() - 1 - x, own.height() - 1 - y);
  }
  EXPECT_LT(difference(own, back), 0.01);
  EXPECT_GT(difference(own, turned), 0.01);
}

TEST_F(CameraFlags, AWiderFovShowsTheMeshSmaller) {
  const std::string cube = "'" + obj("sphere.obj", sphere_obj()) + "'";
  const int fitted = covered(render(cube, kSmall));              // 40 degrees
  const int wide = covered(render(cube, kSmall + " --fov 80"));  // tan 20 / tan 40: 0.43 the size
  ASSERT_GT(fitted, 100);
  EXPECT_GT(wide, 0.12 * fitted);
  EXPECT_LT(wide, 0.28 * fitted);
}

// The pyramid's flat base tells +Z: its apex is at the top of the image, narrow above and wide
// below (seen along +Y's convention, from the front and above, it would show its square base).
TEST_F(CameraFlags, AFlatBaseMakesItsAxisUp) {
  const std::string mesh = "'" + obj("pyramid.obj", kZUpPyramid) + "'";
  const Film detected = render(mesh, kSmall);
  EXPECT_EQ(difference(detected, render(mesh, kSmall + " --up z")), 0.0);
  EXPECT_GT(difference(detected, render(mesh, kSmall + " --up y")), 0.01);
  int top = detected.height(), bottom = -1;
  for (int y = 0; y < detected.height(); ++y) {
    for (int x = 0; x < detected.width(); ++x) {
      if (detected.at(x, y) == detected.at(0, 0)) continue;
      top = std::min(top, y);
      bottom = std::max(bottom, y);
    }
  }
  ASSERT_GT(bottom - top, 8);
  const auto row_width = [&](int y) {
    int n = 0;
    for (int x = 0; x < detected.width(); ++x) n += !(detected.at(x, y) == detected.at(0, 0));
    return n;
  };
  const int quarter = (bottom - top) / 4;
  EXPECT_LT(2 * row_width(top + quarter), row_width(bottom - quarter));
}

TEST_F(CameraFlags, NefertitiStandsOnItsCutBase) {
  const std::string path = raylab::test::source_dir() + "/../shared/scenes/nefertiti.obj";
  if (!fs::exists(path)) GTEST_SKIP() << "no " << path;
  const std::string mesh = "'" + path + "'";
  const Film detected = render(mesh, kSmall);
  EXPECT_EQ(difference(detected, render(mesh, kSmall + " --up z")), 0.0);
  EXPECT_GT(difference(detected, render(mesh, kSmall + " --up y")), 0.01);
}

TEST_F(CameraFlags, BadValuesAreUsageErrorsNamingTheFlag) {
  const std::string whitted = "render " + kWhitted;
  expect_usage_error(whitted + " --camera-from abc", "--camera-from");
  expect_usage_error(whitted + " --camera-from 1,2", "X,Y,Z");
  expect_usage_error(whitted + " --camera-at 0,1.6,6", "--camera-at");  // the scene camera's eye
  expect_usage_error(whitted + " --camera-from 0,5,0 --camera-at 0,0,0", "parallel");
  expect_usage_error(whitted + " --camera-up 0,0,0", "--camera-up");
  for (const char* fov : {"0", "180", "-5", "abc", "nan"}) expect_usage_error(whitted + " --fov " + fov, "--fov");
  expect_usage_error(whitted + " --orbit abc", "--orbit");
  expect_usage_error(whitted + " --orbit inf", "--orbit");
  expect_usage_error("render '" + obj("p.obj", kZUpPyramid) + "' --up w", "--up");
  expect_usage_error(whitted + " --up z", "--up");  // the scene has its own camera
  const std::string orbit_scene = "'" + raylab::test::source_dir() + "/scenes/orbit.json'";
  expect_usage_error("render " + orbit_scene + " --frames 0:1 --orbit 30", "--frames");
  expect_usage_error("compare " + kWhitted + " --accels bvh --camera-up 1", "--camera-up");
  expect_usage_error("quality " + kWhitted + " --fov 200", "--fov");
}

TEST_F(CameraFlags, CompareAndQualityTakeTheFlags) {
  const CliResult c = run("compare " + kWhitted + " --accels bvh --width 16 --repeat 1 -q --orbit 90");
  EXPECT_EQ(c.code, 0) << c.err;
}

// A checkpoint records the camera flags given: --resume alone goes on with them, other camera
// flags are refused as other settings are.
TEST_F(CameraFlags, ACheckpointKeepsTheCameraFlags) {
  Scene demo = load_scene("demo");
  RenderSettings s = demo.settings;
  s.width = 16;
  s.height = 16;
  s.spp = 1;
  CameraOverride orbit;
  orbit.orbit_degrees = 30.f;
  RenderCheckpoint checkpoint{"demo", scene_fingerprint(demo),
                              image_settings(s, resolve_sampler_name(s), RenderOptions{}.tile_size, 1, "bvh"),
                              start_progress(16, 16, RenderOptions{}.tile_size, 1, 1, 0)};
  for (const auto& part : camera_settings(orbit)) checkpoint.settings.push_back(part);
  const std::string ckpt = (work() / "r.ckpt").string();
  write_checkpoint(ckpt, checkpoint);

  const CliResult other = run("render demo --resume '" + ckpt + "' --orbit 40 -q -o '" + out_file("r.pfm") + "'");
  EXPECT_EQ(other.code, 1);
  EXPECT_NE(other.err.find("orbit: 30 in the checkpoint, 40 now"), std::string::npos) << other.err;
  const CliResult more = run("render demo --resume '" + ckpt + "' --fov 30 -q -o '" + out_file("r.pfm") + "'");
  EXPECT_EQ(more.code, 1);
  EXPECT_NE(more.err.find("fov: (not recorded) in the checkpoint, 30 now"), std::string::npos) << more.err;

  const Film resumed = render("demo", "--resume '" + ckpt + "' -q", "resumed.pfm");
  const Film fresh = render("demo", "--width 16 --height 16 --spp 1 --orbit 30 -q", "fresh.pfm");
  EXPECT_EQ(difference(resumed, fresh), 0.0);
  EXPECT_GT(difference(fresh, render("demo", "--width 16 --height 16 --spp 1 -q", "plain.pfm")), 0.001);
}

// A bare mesh gets a little ambient light (no pure black where no light reaches) and four
// jittered samples per pixel unless told otherwise.
TEST_F(CameraFlags, ABareMeshIsAntialiasedAndNeverPureBlack) {
  const std::string sphere = "'" + obj("sphere.obj", sphere_obj()) + "'";
  const CliResult r = run("render " + sphere + " --width 48 --aov samples -q -o '" + out_file("s.exr") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const Film film = read_image(out_file("s.exr"));
  ASSERT_EQ(film.height(), 36);
  float darkest = 1e9f;
  for (const Color& c : film.pixels()) darkest = std::min(darkest, max_component(c));
  EXPECT_GT(darkest, 0.03f);  // ambient 0.12 x kd 0.9 x grey 0.75 = 0.081 at the least lit
  int samples_found = 0;
  for (const ImageLayer& layer : read_exr_channels(out_file("s.exr"))) {
    if (layer.name != "samples.Y") continue;
    for (float v : layer.values) EXPECT_EQ(v, 4.f);
    ++samples_found;
  }
  EXPECT_EQ(samples_found, 1);
  // --spp says otherwise: one sample.
  const CliResult one = run("render " + sphere + " --width 48 --spp 1 --aov samples -q -o '" + out_file("o.exr") + "'");
  ASSERT_EQ(one.code, 0) << one.err;
  for (const ImageLayer& layer : read_exr_channels(out_file("o.exr"))) {
    if (layer.name == "samples.Y") {
      EXPECT_EQ(layer.values.front(), 1.f);
    }
  }
}

}  // namespace
}  // namespace raylab
