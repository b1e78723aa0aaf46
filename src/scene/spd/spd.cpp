#include <array>
#include <charconv>

#include "raylab/core/error.h"
#include "spd_generators.h"

namespace raylab {

std::span<const SpdGenerator> spd_generators() {
  static const std::array<SpdGenerator, 7> generators{spd::balls(),  spd::gears(), spd::mount(), spd::rings(),
                                                      spd::teapot(), spd::tetra(), spd::tree()};
  return generators;
}

bool is_spd_source(std::string_view source) { return source.starts_with("spd:"); }

SpdSource parse_spd_source(std::string_view source) {
  std::string_view rest = source.substr(4);
  std::string_view query;
  if (const auto q = rest.find('?'); q != std::string_view::npos) {
    query = rest.substr(q + 1);
    rest = rest.substr(0, q);
  }
  const SpdGenerator* generator = nullptr;
  std::string names;
  for (const SpdGenerator& g : spd_generators()) {
    if (g.name == rest) generator = &g;
    names += (names.empty() ? "" : ", ") + std::string(g.name);
  }
  if (generator == nullptr) {
    throw UsageError("unknown SPD scene '" + std::string(rest) + "' (valid: " + names + ")");
  }
  int size = generator->default_size;
  while (!query.empty()) {
    const auto amp = query.find('&');
    const std::string_view param = query.substr(0, amp);
    query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
    const auto eq = param.find('=');
    const std::string_view key = param.substr(0, eq);
    const std::string_view value = eq == std::string_view::npos ? std::string_view{} : param.substr(eq + 1);
    if (key != "size") {
      throw UsageError("unknown SPD parameter '" + std::string(key) + "' in '" + std::string(source) +
                       "' (valid: size)");
    }
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), size);
    if (value.empty() || ec != std::errc() || ptr != value.data() + value.size() || size < 1 ||
        size > generator->max_size) {
      throw UsageError("SPD size '" + std::string(value) + "' for " + std::string(generator->name) +
                       " must be an integer from 1 to " + std::to_string(generator->max_size) + " (default " +
                       std::to_string(generator->default_size) + ")");
    }
  }
  return {generator, size};
}

Scene make_spd_scene(std::string_view source) {
  const SpdSource spd = parse_spd_source(source);
  Scene scene;
  NffSceneBuilder builder(scene);
  spd.generator->generate(spd.size, builder);
  builder.finish();
  return scene;
}

}  // namespace raylab
