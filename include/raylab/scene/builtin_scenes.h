#pragma once
/// \file
/// Scenes built into raylab, addressed by name.

#include <span>
#include <string_view>

#include "raylab/scene/scene.h"

namespace raylab {

/// A built-in scene's name and what it shows.
struct BuiltinScene {
  std::string_view name;         ///< "demo", "cornell", ...
  std::string_view description;  ///< one line for --list-scenes
};

/// The built-in scenes, in the order of builtin_scene_names().
std::span<const BuiltinScene> builtin_scenes();

/// Names of the built-in scenes.
std::span<const std::string_view> builtin_scene_names();

/// True when `name` is a built-in scene.
bool is_builtin_scene(std::string_view name);

/// Builds the built-in scene `name`; throws UsageError listing the names when unknown.
Scene make_builtin_scene(std::string_view name);

/// The demo: Whitted's classic image revisited. A checkered floor, a mirror sphere, a glass
/// sphere, a Phong-shaded sphere, a smooth torus mesh, two point lights and a quad area light.
Scene make_demo_scene();

/// The Cornell box with its published dimensions (millimetres), camera and colours; the light is
/// a quad area light with an emissive quad in its place.
Scene make_cornell_scene();

/// The material showcase: a row of spheres of every physically based model and named metal on
/// a checkered ground, under a lat-long sky with a sun; renders with the path integrator.
Scene make_showcase_scene();

}  // namespace raylab
