#include "raylab/io/scene_paths.h"

#include <filesystem>

namespace raylab {

namespace fs = std::filesystem;

std::string folder_of(const std::string& file) {
  const fs::path parent = fs::path(file).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

std::string resolve_scene_path(const std::string& base_dir, const std::string& reference, bool allow_outside) {
  const fs::path ref(reference);
  const fs::path joined = ref.is_absolute() ? ref : fs::path(base_dir) / ref;
  if (allow_outside) return joined.lexically_normal().string();
  std::error_code ec;
  // weakly_canonical resolves symbolic links of the part that exists, so a link inside the
  // folder that points outside it is caught too.
  const fs::path base = fs::weakly_canonical(fs::absolute(base_dir), ec);
  if (ec) return {};
  const fs::path target = fs::weakly_canonical(fs::absolute(joined), ec);
  if (ec) return {};
  const fs::path rel = target.lexically_relative(base);
  if (rel.empty() || *rel.begin() == "..") return {};
  return joined.lexically_normal().string();
}

}  // namespace raylab
