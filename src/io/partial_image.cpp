#include "raylab/io/partial_image.h"

#include <filesystem>

namespace raylab {

std::string partial_image_beside(const std::string& target) {
  const std::filesystem::path p(target);
  return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

std::string partial_image_path(const std::string& target, bool target_existed, bool render_wrote_target) {
  return target_existed && !render_wrote_target ? partial_image_beside(target) : target;
}

}  // namespace raylab
