#include "raylab/io/environment_io.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>
#include <system_error>
#include <utility>

#include "raylab/core/error.h"
#include "raylab/io/camera_override.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/image_io.h"
#include "raylab/sampling/distribution.h"

namespace raylab {
namespace {

// What the spec should have been, for the message of one that is neither.
constexpr std::string_view kExpected =
    "is neither R,G,B (three numbers >= 0, such as 0.5,0.5,0.5) nor a readable image file";

// Why `path` names no file that read_image could open; empty when it names one.
std::string missing_file_reason(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found || path.empty()) return "no such file";
  if (std::filesystem::is_directory(status)) return "it is a folder";
  return "";
}

// read_image's film for `path`, its errors reworded as "path: --env: reason" so that they say
// which option the file came from.
Film read_film(const std::string& path, std::string_view argument) {
  try {
    return read_image(path);
  } catch (const InputError& e) {
    std::string_view reason = e.what();
    if (const std::string prefix = path + ": "; reason.starts_with(prefix)) reason.remove_prefix(prefix.size());
    throw InputError(path, fmt::format("{}: {}", argument, reason));
  }
}

// The image at `path` as an environment image; InputError naming the file for any pixel that
// is not a radiance (the sampling distribution weighs texels by luminance, and one NaN or
// negative texel would poison every CDF entry after it).
std::shared_ptr<const EnvironmentImage> read_environment_image(const std::string& path, std::string_view argument) {
  if (lowercase_extension(path) == ".hdr") {
    // read_image hands unknown extensions to stb_image, which would tone-map a Radiance file
    // to 8 bits: the light would be clipped at 1 without a word.
    throw InputError(path, fmt::format("{}: Radiance .hdr is not supported: convert it to .exr or .pfm", argument));
  }
  const Film film = read_film(path, argument);
  if (film.width() > kMaxDistributionBins || film.height() > kMaxDistributionBins) {
    throw InputError(path,
                     fmt::format("{}: {} x {} pixels is too large to sample", argument, film.width(), film.height()));
  }
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      const Color c = film.at(x, y);
      if (!is_finite(c) || c.x < 0.f || c.y < 0.f || c.z < 0.f) {
        throw InputError(path, fmt::format("{}: pixel ({}, {}) is ({}, {}, {}): radiance must be finite and "
                                           ">= 0",
                                           argument, x, y, c.x, c.y, c.z));
      }
    }
  }
  auto image = std::make_shared<EnvironmentImage>();
  image->width = film.width();
  image->height = film.height();
  image->texels.assign(film.pixels().begin(), film.pixels().end());
  image->path = path;
  return image;
}

}  // namespace

Environment load_environment(const std::string& spec_or_path, float rotate_degrees, std::string_view argument) {
  if (!std::isfinite(rotate_degrees)) {
    throw UsageError(
        fmt::format("{}: the rotation must be a finite number of degrees, not {}", argument, rotate_degrees));
  }
  Environment env;
  env.rotate_degrees = rotate_degrees;
  if (const std::optional<Vec3> color = parse_vec3(spec_or_path)) {
    if (color->x < 0.f || color->y < 0.f || color->z < 0.f) {
      throw UsageError(
          fmt::format("{}: '{}' has a negative component: R,G,B must each be >= 0", argument, spec_or_path));
    }
    env.color = *color;
    return env;
  }
  if (const std::string reason = missing_file_reason(spec_or_path); !reason.empty()) {
    throw UsageError(fmt::format("{}: '{}' {}: {}", argument, spec_or_path, kExpected, reason));
  }
  env.image = read_environment_image(spec_or_path, argument);
  return env;
}

}  // namespace raylab
