#pragma once
// Internal to the io module: the names scene files give the material models ("type"), one
// table for the reader and the writer.

#include <array>
#include <optional>
#include <string_view>
#include <utility>

#include "raylab/scene/material.h"

namespace raylab::detail {

/// Every model with its scene-file name, in the order the documentation lists them.
inline constexpr std::array<std::pair<std::string_view, MaterialModel>, 6> kMaterialModelNames = {{
    {"phong", MaterialModel::kPhong},
    {"diffuse", MaterialModel::kDiffuse},
    {"conductor", MaterialModel::kConductor},
    {"dielectric", MaterialModel::kDielectric},
    {"plastic", MaterialModel::kPlastic},
    {"metallic_roughness", MaterialModel::kMetallicRoughness},
}};

/// The scene-file name of `model`.
constexpr std::string_view material_model_name(MaterialModel model) {
  for (const auto& [name, m] : kMaterialModelNames) {
    if (m == model) return name;
  }
  return "phong";
}

}  // namespace raylab::detail
