#include "raylab/lab/quality_reference.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "raylab/core/error.h"
#include "raylab/core/hash64.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/image_io.h"
#include "raylab/io/read_file.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

void check_size(const Film& film, const RenderSettings& s, const std::string& path) {
  if (film.width() == s.width && film.height() == s.height) return;
  throw InputError(path, fmt::format("the reference image is {}x{} but the study renders {}x{} (give --width {} "
                                     "--height {}, or another reference)",
                                     film.width(), film.height(), s.width, s.height, film.width(), film.height()));
}

// A cached file that cannot be read (truncated by a crash of another writer, an older format)
// is not an error: the reference is rendered again and the file replaced.
bool try_read_cached(const std::string& path, const RenderSettings& s, Film& out) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return false;
  try {
    Film f = read_image(path);
    if (f.width() != s.width || f.height() != s.height) return false;
    out = std::move(f);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

std::string default_reference_cache_dir() {
  if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty()) {
    return (fs::path(xdg) / "raylab" / "references").string();
  }
  if (const std::string home = env("HOME"); !home.empty()) {
    return (fs::path(home) / ".cache" / "raylab" / "references").string();
  }
  return ".raylab-cache";
}

std::string scene_source_key(const std::string& source) {
  std::error_code ec;
  if (!fs::is_regular_file(source, ec)) return source;
  return fmt::format("{} hash64:{:016x}", source, Hash64::of(read_file(source)));
}

Film load_reference_file(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".exr" && ext != ".pfm") {
    throw UsageError("--reference '" + path + "': the reference must be a float image (valid: .exr, .pfm) or 'auto'");
  }
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "cannot open the reference image: no such file");
  return read_image(path);
}

ReferenceImage obtain_reference(const Scene& scene, const Accelerator& accel, const QualityOptions& options,
                                const std::function<void(int, int)>& on_progress) {
  const RenderSettings& s = scene.settings;
  ReferenceImage ref;
  if (options.reference != "auto") {
    ref.film = load_reference_file(options.reference);
    check_size(ref.film, s, options.reference);
    ref.path = options.reference;
    ref.description = options.reference;
    return ref;
  }
  const RenderSettings rs = reference_settings(s, options);
  const std::string what = fmt::format("auto: {} spp jittered, seed {:#x}", rs.spp, rs.seed);
  if (!options.cache_dir.empty()) {
    ref.path = (fs::path(options.cache_dir) / reference_file_name(s, options)).string();
    if (try_read_cached(ref.path, s, ref.film)) {
      ref.from_cache = true;
      ref.description = what + ", cached at " + ref.path;
      return ref;
    }
    std::error_code ec;
    fs::create_directories(options.cache_dir, ec);
    if (ec || !fs::is_directory(options.cache_dir)) {
      throw InputError(options.cache_dir, "cannot create the reference cache folder: " +
                                              (ec ? ec.message() : std::string("a file has that name")));
    }
    check_writable(ref.path);  // before the long render, not after it
  }
  ref.film = render_reference(scene, accel, options, on_progress);
  ref.rendered = true;
  if (!ref.path.empty()) {
    write_image(ref.film, ref.path);
    ref.description = what + ", rendered and cached at " + ref.path;
  } else {
    ref.description = what + ", rendered (not cached)";
  }
  return ref;
}

}  // namespace raylab
