#include "raylab/io/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/read_file.h"
#include "raylab/io/scene_paths.h"
#include "raylab/io/texture_io.h"
#include "raylab/scene/normal_maps.h"

namespace raylab {
namespace {

struct Location {
  int line = 0;
  int col = 0;
};

// Number of whitespace-separated tokens in `text` from `pos` on.
std::size_t count_tokens(std::string_view text, std::size_t pos) {
  std::size_t n = 0;
  while ((pos = text.find_first_not_of(" \t\r", pos)) != std::string::npos) {
    ++n;
    pos = text.find_first_of(" \t\r", pos);
  }
  return n;
}

// Finds where the `token_index`-th token after the keyword of the `ordinal`-th statement with
// keyword `keyword` is. tinyobjloader keeps no positions, so a bad index found after parsing is
// located by counting statements in the file again (only on the error path).
Location locate(const std::string& path, const std::string& keyword, std::size_t ordinal, std::size_t token_index) {
  std::ifstream in(path);
  std::string text;
  std::size_t seen = 0;
  for (int line_no = 1; std::getline(in, text); ++line_no) {
    std::size_t p = text.find_first_not_of(" \t");
    if (p == std::string::npos || text.compare(p, keyword.size(), keyword) != 0) continue;
    const std::size_t after = p + keyword.size();
    if (after < text.size() && !std::isspace(static_cast<unsigned char>(text[after]))) continue;
    // tinyobjloader drops faces of fewer than 3 corners without a trace, so they do not count.
    if (keyword == "f" && count_tokens(text, after) < 3) continue;
    if (seen++ != ordinal) continue;
    // Walk to the requested token.
    std::size_t pos = after;
    for (std::size_t t = 0;; ++t) {
      pos = text.find_first_not_of(" \t\r", pos);
      if (pos == std::string::npos) return {line_no, static_cast<int>(p) + 1};
      if (t == token_index) return {line_no, static_cast<int>(pos) + 1};
      pos = text.find_first_of(" \t\r", pos);
      if (pos == std::string::npos) return {line_no, static_cast<int>(p) + 1};
    }
  }
  return {};
}

// Column of the first corner of face statement `text` with an index of 0 (which tinyobjloader
// rejects without saying where), or 0 if there is none.
int zero_index_column(const std::string& text) {
  std::size_t p = text.find_first_not_of(" \t");
  if (p == std::string::npos || text.compare(p, 1, "f") != 0) return 0;
  for (p += 1; (p = text.find_first_not_of(" \t\r", p)) != std::string::npos;) {
    const std::size_t end = std::min(text.find_first_of(" \t\r", p), text.size());
    // Each corner is v, v/vt, v//vn or v/vt/vn; any present part that reads as 0 is the culprit.
    for (std::size_t q = p; q < end;) {
      const std::size_t slash = std::min(text.find('/', q), end);
      if (slash > q && std::atoi(text.substr(q, slash - q).c_str()) == 0) return static_cast<int>(p) + 1;
      q = slash + 1;
    }
    p = end;
  }
  return 0;
}

// tinyobjloader reports "... line N ..." in some messages; keep its text but lead with file:line
// (and the column, for the zero index it rejects in a face).
[[noreturn]] void throw_reader_error(const std::string& path, const std::string& message) {
  int line = 0;
  const auto at = message.find("line ");
  if (at != std::string::npos) line = std::atoi(message.c_str() + at + 5);
  if (line > 0 && message.find("`f' line") != std::string::npos) {
    std::ifstream in(path);
    std::string text;
    for (int n = 1; n <= line && std::getline(in, text); ++n) {
    }
    if (const int col = zero_index_column(text); col > 0) {
      throw InputError(path, line, col, "face index 0 is not valid (OBJ indices start at 1; negative ones count back)");
    }
  }
  std::string text = message;
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  throw InputError(path, line, 0, text.empty() ? "cannot parse OBJ file" : text);
}

// Calls `fn(line_no, line)` for each line of `text`, 1-based, without its line end.
template <class Fn>
void for_each_line(const std::string& text, Fn&& fn) {
  std::size_t start = 0;
  for (int line_no = 1; start < text.size(); ++line_no) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line(text.data() + start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    fn(line_no, line);
    start = end + 1;
  }
}

// Checks every vertex coordinate, in file order. tinyobjloader reads a word it cannot parse
// ("nan", "inf", "1.5x") as 0 without complaint, so the text of each `v` statement is checked
// here, as well as the value it gave (1e999 overflows to infinity). `values` are its coordinates.
// Works on the file's text already in memory: this pass is a large part of an OBJ load.
void check_vertex_coordinates(const std::string& path, const std::string& file_text,
                              const std::vector<tinyobj::real_t>& values) {
  std::size_t vertex = 0;
  for_each_line(file_text, [&](int line_no, std::string_view text) {
    std::size_t p = text.find_first_not_of(" \t");
    if (p == std::string_view::npos || text[p] != 'v' || p + 1 >= text.size() ||
        (text[p + 1] != ' ' && text[p + 1] != '\t')) {
      return;
    }
    p += 1;
    for (std::size_t k = 0; k < 3; ++k) {
      p = text.find_first_not_of(" \t\r", p);
      if (p == std::string_view::npos) break;  // a missing coordinate reads as 0, as OBJ readers do
      const std::size_t end = std::min(text.find_first_of(" \t\r", p), text.size());
      double value = 0.0;
      const std::size_t digits = text[p] == '+' ? p + 1 : p;  // from_chars takes no '+'; OBJ may
      const auto [ptr, ec] = std::from_chars(text.data() + digits, text.data() + end, value);
      const bool parsed = ptr == text.data() + end && (ec == std::errc() || ec == std::errc::result_out_of_range);
      const std::size_t i = 3 * vertex + k;
      if (!parsed || (ec == std::errc() && !std::isfinite(value)) || (i < values.size() && !std::isfinite(values[i]))) {
        throw InputError(path, line_no, static_cast<int>(p) + 1,
                         "vertex coordinate '" + std::string(text.substr(p, end - p)) + "' is not a finite number");
      }
      p = end;
    }
    ++vertex;
  });
}

// Where the rest of `line` starts when its first word is `keyword`; npos otherwise.
std::size_t after_keyword(std::string_view line, std::string_view keyword) {
  const std::size_t p = line.find_first_not_of(" \t");
  if (p == std::string_view::npos || line.compare(p, keyword.size(), keyword) != 0) return std::string_view::npos;
  const std::size_t after = p + keyword.size();
  if (after < line.size() && line[after] != ' ' && line[after] != '\t') return std::string_view::npos;
  return after;
}

// A file name written in a statement, and where.
struct FileRef {
  std::string name;
  Location at;
};

// The file names of every `mtllib` statement, split as tinyobjloader splits them: at blanks, a
// backslash keeping the next character (an escaped space) in the name.
std::vector<FileRef> mtllib_refs(const std::string& text) {
  std::vector<FileRef> refs;
  for_each_line(text, [&](int line_no, std::string_view line) {
    std::size_t p = after_keyword(line, "mtllib");
    while (p < line.size()) {
      if (line[p] == ' ' || line[p] == '\t') {
        ++p;
        continue;
      }
      FileRef ref{{}, {line_no, static_cast<int>(p) + 1}};
      for (; p < line.size() && line[p] != ' ' && line[p] != '\t'; ++p) {
        if (line[p] == '\\' && p + 1 < line.size()) ++p;
        ref.name += line[p];
      }
      refs.push_back(std::move(ref));
    }
  });
  return refs;
}

// The names of `usemtl` statements, where they are written (tinyobjloader keeps no positions).
std::vector<FileRef> usemtl_refs(const std::string& text) {
  std::vector<FileRef> refs;
  for_each_line(text, [&](int line_no, std::string_view line) {
    const std::size_t after = after_keyword(line, "usemtl");
    if (after == std::string_view::npos) return;
    const std::size_t p = line.find_first_not_of(" \t", after);
    if (p == std::string_view::npos) return;
    const std::size_t end = std::min(line.find_first_of(" \t", p), line.size());
    refs.push_back({std::string(line.substr(p, end - p)), {line_no, static_cast<int>(p) + 1}});
  });
  return refs;
}

constexpr std::uint8_t kWritesTexcoord = 1;
constexpr std::uint8_t kWritesNormal = 2;

// For each face corner in file order (faces of 3 or more corners, as tinyobjloader keeps them):
// whether its text has a texture-coordinate part and a normal part. tinyobjloader resolves a
// relative index that points before the first element to -1, the value it also uses for "no
// such part"; only the text tells the two apart.
std::vector<std::uint8_t> corner_parts(const std::string& text) {
  std::vector<std::uint8_t> parts;
  for_each_line(text, [&](int, std::string_view line) {
    std::size_t p = after_keyword(line, "f");
    if (p == std::string_view::npos || count_tokens(line, p) < 3) return;
    while ((p = line.find_first_not_of(" \t", p)) != std::string_view::npos) {
      const std::size_t end = std::min(line.find_first_of(" \t", p), line.size());
      const std::string_view corner = line.substr(p, end - p);
      const std::size_t s1 = corner.find('/');
      const std::size_t s2 = s1 == std::string_view::npos ? s1 : corner.find('/', s1 + 1);
      std::uint8_t flags = 0;
      if (s1 != std::string_view::npos && s1 + 1 < corner.size() && corner[s1 + 1] != '/') flags |= kWritesTexcoord;
      if (s2 != std::string_view::npos && s2 + 1 < corner.size()) flags |= kWritesNormal;
      parts.push_back(flags);
      p = end;
    }
  });
  return parts;
}

// One statement of a material in a .mtl file: where its keyword is, and the column of its last
// word (the file name of a texture statement, after any options).
struct MtlStatement {
  Location at;
  int last_word_col = 0;
};

// A `newmtl` block: its file and the first statement of each keyword in it.
struct MtlBlock {
  std::string file;
  std::map<std::string, MtlStatement, std::less<>> statements;
};

// Records every material block of .mtl text `text` read from `file`. The first block of a name
// wins, across files too, as in tinyobjloader's material map.
void index_mtl(const std::string& file, const std::string& text, std::map<std::string, MtlBlock>& index) {
  MtlBlock* block = nullptr;
  for_each_line(text, [&](int line_no, std::string_view line) {
    line = line.substr(0, line.find_last_not_of(" \t") + 1);
    const std::size_t p = line.find_first_not_of(" \t");
    if (p == std::string_view::npos || line[p] == '#') return;
    const std::size_t end = std::min(line.find_first_of(" \t", p), line.size());
    const std::string_view keyword = line.substr(p, end - p);
    if (keyword == "newmtl") {
      // tinyobjloader takes the rest of the line after one separator as the name.
      const std::string name(end + 1 < line.size() ? line.substr(end + 1) : std::string_view{});
      const bool first = index.find(name) == index.end();
      block = first ? &index[name] : nullptr;
      if (block != nullptr) block->file = file;
      return;
    }
    if (block == nullptr) return;
    const std::size_t last = line.find_last_of(" \t");
    const int last_col = last == std::string_view::npos ? 0 : static_cast<int>(last) + 2;
    block->statements.emplace(std::string(keyword), MtlStatement{{line_no, static_cast<int>(p) + 1}, last_col});
  });
}

// One name per file however it is written (`a.mtl`, `./a.mtl`, a link), to read it only once.
std::string canonical_key(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : canonical.string();
}

// Hands tinyobjloader the materials raylab read and checked itself, at its first `mtllib`
// statement. Reading every library up front (rather than letting tinyobjloader open them) is what
// lets a missing or outside library be an error at its position, before any file is opened, and
// loads all libraries of one `mtllib` line as the MTL format means, where tinyobjloader would
// stop at the first it can read.
class PreloadedMaterials final : public tinyobj::MaterialReader {
 public:
  PreloadedMaterials(const std::vector<tinyobj::material_t>& materials, const std::map<std::string, int>& map)
      : m_materials(materials), m_map(map) {}

  bool operator()(const std::string&, std::vector<tinyobj::material_t>* materials, std::map<std::string, int>* map,
                  std::string*, std::string*) override {
    if (!m_given) {
      *materials = m_materials;
      *map = m_map;
      m_given = true;
    }
    return true;
  }

 private:
  const std::vector<tinyobj::material_t>& m_materials;
  const std::map<std::string, int>& m_map;
  bool m_given = false;
};

// The materials of an OBJ's libraries, turned into raylab materials and objects on first use.
class ObjMaterials {
 public:
  ObjMaterials(const std::string& obj_path, Scene& scene, std::uint32_t fallback, const ObjLoadOptions& options)
      : m_obj_path(obj_path), m_folder(folder_of(obj_path)), m_scene(scene), m_fallback(fallback), m_options(options) {}

  // Checks and reads every library that `mtllib` statements of `obj_text` name.
  void read_libraries(const std::string& obj_text) {
    std::vector<std::string> seen;
    for (const FileRef& ref : mtllib_refs(obj_text)) {
      // A missing library is a missing optional part: its faces get the default material.
      const std::string path =
          resolve_reference(ref.name, m_obj_path, ref.at, "material library", "; its faces use the default material");
      if (path.empty()) continue;
      const std::string canonical = canonical_key(path);
      if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) continue;
      seen.push_back(canonical);
      const std::string text = read_file(path);
      std::istringstream stream(text);
      std::string warn, err;
      tinyobj::LoadMtl(&m_map, &m_materials, &stream, &warn, &err);
      index_mtl(path, text, m_blocks);
    }
  }

  // Notes `usemtl` names that no library defines: their faces silently fall back to the
  // object's material otherwise.
  void note_unknown_names(const std::string& obj_text) {
    if (m_materials.empty()) return;
    for (const FileRef& ref : usemtl_refs(obj_text)) {
      if (m_map.find(ref.name) != m_map.end()) continue;
      m_scene.warnings.push_back(m_obj_path + ":" + std::to_string(ref.at.line) + ":" + std::to_string(ref.at.col) +
                                 ": no material library defines material '" + ref.name + "'; its faces use '" +
                                 fallback_name() + "'s material");
    }
  }

  std::unique_ptr<tinyobj::MaterialReader> reader() const {
    return std::make_unique<PreloadedMaterials>(m_materials, m_map);
  }

  // The object for faces of material `id` (-1: none), created with its material on first use.
  std::uint32_t object_for(int id) {
    if (id < 0 || static_cast<std::size_t>(id) >= m_materials.size()) return m_fallback;
    if (m_objects.size() < m_materials.size()) m_objects.resize(m_materials.size());
    std::optional<std::uint32_t>& object = m_objects[static_cast<std::size_t>(id)];
    if (!object) {
      const tinyobj::material_t& m = m_materials[static_cast<std::size_t>(id)];
      const std::uint32_t material = m_scene.add_material(convert(m));
      object = m_scene.add_object(fallback_name() + "/" + m.name, material);
    }
    return *object;
  }

 private:
  std::string fallback_name() const {
    if (m_fallback < m_scene.objects.size()) return m_scene.objects[m_fallback].name;
    return std::filesystem::path(m_obj_path).stem().string();
  }

  // The path of `reference`, relative to the OBJ's folder; an InputError at `at` of file `in`
  // when it leaves that folder (unless allowed). When it is not a file: empty, after a warning
  // at `at` that ends with `consequence`.
  std::string resolve_reference(const std::string& reference, const std::string& in, Location at,
                                const std::string& what, const std::string& consequence) const {
    const std::string path = resolve_scene_path(m_folder, reference, m_options.allow_outside_paths);
    if (path.empty()) {
      throw InputError(in, at.line, at.col,
                       what + " '" + reference + "' is outside the folder of " + m_obj_path +
                           " (reading files from elsewhere needs allow_outside_paths)");
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      m_scene.warnings.push_back(in + ":" + std::to_string(at.line) + ":" + std::to_string(at.col) + ": " + what +
                                 " '" + reference + "' not found (looked for " + path + ")" + consequence);
      return {};
    }
    return path;
  }

  // Statement `keyword` of material `block`, if written.
  static const MtlStatement* statement(const MtlBlock* block, std::string_view keyword) {
    if (block == nullptr) return nullptr;
    const auto it = block->statements.find(keyword);
    return it == block->statements.end() ? nullptr : &it->second;
  }

  // Throws unless every one of `values` (of statement `keyword`) is finite.
  void check_finite(const tinyobj::material_t& m, const MtlBlock* block, const char* keyword,
                    std::initializer_list<tinyobj::real_t> values) const {
    if (std::all_of(values.begin(), values.end(), [](tinyobj::real_t v) { return std::isfinite(v); })) return;
    const MtlStatement* s = statement(block, keyword);
    const std::string message = std::string(keyword) + " of material '" + m.name + "' is not a finite number";
    if (s == nullptr) throw InputError(m_obj_path, message);
    throw InputError(block->file, s->at.line, s->at.col, message);
  }

  Material convert(const tinyobj::material_t& m) {
    const auto found = m_blocks.find(m.name);
    const MtlBlock* block = found == m_blocks.end() ? nullptr : &found->second;
    check_finite(m, block, "Kd", {m.diffuse[0], m.diffuse[1], m.diffuse[2]});
    check_finite(m, block, "Ks", {m.specular[0], m.specular[1], m.specular[2]});
    check_finite(m, block, "Ke", {m.emission[0], m.emission[1], m.emission[2]});
    check_finite(m, block, "Ns", {m.shininess});
    check_finite(m, block, "d", {m.dissolve});
    check_finite(m, block, "Ni", {m.ior});

    Material out;
    out.name = m.name;
    // A texture that is missing leaves the material untextured (a warning says so).
    const std::shared_ptr<const TextureImage> image = m.diffuse_texname.empty() ? nullptr : texture(m, block);
    const bool textured = image != nullptr;
    if (statement(block, "Kd") != nullptr) {
      out.color = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
    } else if (textured) {
      out.color = {1.f, 1.f, 1.f};  // tinyobjloader would make it 0.6 grey, darkening the texture
    }
    out.ks = std::max(0.f, std::max({m.specular[0], m.specular[1], m.specular[2]}));
    // tinyobjloader's default exponent is 1, a highlight all over; keep raylab's unless written.
    if (statement(block, "Ns") != nullptr) out.shininess = std::max(0.f, m.shininess);
    // `dissolve` is `d`, or 1 - Tr when only the non-standard Tr is written.
    out.transmittance = std::clamp(1.f - m.dissolve, 0.f, 1.f);
    out.ior = m.ior > 0.f ? m.ior : 1.f;
    out.emission = {std::max(0.f, m.emission[0]), std::max(0.f, m.emission[1]), std::max(0.f, m.emission[2])};
    // illum 3 to 7 are the models with ray-traced reflection; Ks is their mirror colour.
    if (m.illum >= 3 && m.illum <= 7) out.reflectivity = out.ks;
    if (textured) out.texture = Texture::from_image(image);
    add_maps(m, block, out);
    return out;
  }

  // The maps beyond the colour: map_Ke, norm, and map_Bump (also written map_bump or bump),
  // which exporters use for height maps (its meaning in the MTL specification) and for normal
  // maps alike (Blender's does): an image that looks like a normal map is read as one.
  void add_maps(const tinyobj::material_t& m, const MtlBlock* block, Material& out) {
    if (!m.emissive_texname.empty())
      out.maps.emission = texture(m, block, m.emissive_texname, {"map_Ke"}, TextureEncoding::kSrgb);
    if (!m.normal_texname.empty())
      out.maps.normal = texture(m, block, m.normal_texname, {"norm"}, TextureEncoding::kLinear);
    if (!m.bump_texname.empty() && !out.maps.normal) {
      auto image = texture(m, block, m.bump_texname, {"map_Bump", "map_bump", "bump"}, TextureEncoding::kLinear);
      if (image && looks_like_normal_map(*image)) {
        out.maps.normal = std::move(image);
      } else {
        out.maps.bump = std::move(image);
        out.maps.bump_scale = std::isfinite(m.bump_texopt.bump_multiplier) ? m.bump_texopt.bump_multiplier : 1.f;
      }
    }
  }

  // The diffuse texture (map_Kd).
  std::shared_ptr<const TextureImage> texture(const tinyobj::material_t& m, const MtlBlock* block) {
    return texture(m, block, m.diffuse_texname, {"map_Kd"}, TextureEncoding::kSrgb);
  }

  // The image `name` that statement `keywords` (its spellings) of material `m` refers to, decoded
  // with `encoding`, or nullptr (with a warning) when the file is missing.
  std::shared_ptr<const TextureImage> texture(const tinyobj::material_t& m, const MtlBlock* block,
                                              const std::string& name, std::initializer_list<std::string_view> keywords,
                                              TextureEncoding encoding) {
    const MtlStatement* s = nullptr;
    for (const std::string_view k : keywords) s = s != nullptr ? s : statement(block, k);
    const std::string in = s != nullptr ? block->file : m_obj_path;
    const Location at = s != nullptr ? Location{s->at.line, s->last_word_col} : Location{};
    const std::string path =
        resolve_reference(name, in, at, "texture", "; material '" + m.name + "' renders without it");
    if (path.empty()) return nullptr;
    const std::pair<std::string, TextureEncoding> key{canonical_key(path), encoding};
    if (const auto it = m_textures.find(key); it != m_textures.end()) return it->second;
    try {
      return m_textures[key] = load_texture(path, encoding);
    } catch (const InputError& e) {
      throw InputError(in, at.line, at.col, e.what());
    }
  }

  std::string m_obj_path;
  std::string m_folder;
  Scene& m_scene;
  std::uint32_t m_fallback;
  ObjLoadOptions m_options;
  std::vector<tinyobj::material_t> m_materials;
  std::map<std::string, int> m_map;
  std::map<std::string, MtlBlock> m_blocks;
  std::vector<std::optional<std::uint32_t>> m_objects;
  // By file and encoding: one image may serve as colour (sRGB) and as data (linear).
  std::map<std::pair<std::string, TextureEncoding>, std::shared_ptr<const TextureImage>> m_textures;
};

// Parses `text` (the OBJ file `path`) with tinyobjloader, handing it `materials` when given.
void parse_obj(const std::string& path, const std::string& text, tinyobj::MaterialReader* materials,
               tinyobj::attrib_t& attrib, std::vector<tinyobj::shape_t>& shapes) {
  // A stream over the text in place: an istringstream would copy the whole file once more.
  struct MemoryBuffer : std::streambuf {
    explicit MemoryBuffer(const std::string& t) {
      char* p = const_cast<char*>(t.data());  // read only: streambuf's get area is non-const
      setg(p, p, p + t.size());
    }
  } buffer(text);
  std::istream stream(&buffer);
  std::vector<tinyobj::material_t> unused;
  std::string warn, err;
  // No triangulation there: it reads vertices through unchecked indices. No vertex colours.
  if (!tinyobj::LoadObj(&attrib, &shapes, &unused, &warn, &err, &stream, materials, false, false)) {
    throw_reader_error(path, err);
  }
}

void check_normals(const std::string& path, const tinyobj::attrib_t& attrib, std::vector<Vec3>& normals) {
  normals.resize(attrib.normals.size() / 3);
  for (std::size_t i = 0; i < normals.size(); ++i) {
    normals[i] = {attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]};
    if (!is_finite(normals[i])) {
      const std::size_t bad = std::isfinite(normals[i].x) ? (std::isfinite(normals[i].y) ? 2 : 1) : 0;
      const Location at = locate(path, "vn", i, bad);
      throw InputError(path, at.line, at.col, "normal is not a finite number");
    }
  }
}

void check_texcoords(const std::string& path, const tinyobj::attrib_t& attrib, std::vector<Vec2>& uvs) {
  uvs.resize(attrib.texcoords.size() / 2);
  for (std::size_t i = 0; i < uvs.size(); ++i) {
    uvs[i] = {attrib.texcoords[2 * i], attrib.texcoords[2 * i + 1]};
    if (!std::isfinite(uvs[i].x) || !std::isfinite(uvs[i].y)) {
      const Location at = locate(path, "vt", i, std::isfinite(uvs[i].x) ? 1 : 0);
      throw InputError(path, at.line, at.col, "texture coordinate is not a finite number");
    }
  }
}

// Checks one corner's index into an attribute array of `count` elements (`noun` names one,
// `plural` many). -1 means the corner has none, unless its text writes one (`written`).
void check_attribute_index(int index, std::size_t count, bool written, const char* noun, const char* plural,
                           const std::string& path, std::size_t face, std::size_t corner) {
  if (index >= 0 && static_cast<std::size_t>(index) < count) return;
  if (index == -1 && !written) return;
  const Location at = locate(path, "f", face, corner);
  throw InputError(
      path, at.line, at.col,
      std::string(noun) + " index out of range (the file has " + std::to_string(count) + " " + plural + ")");
}

}  // namespace

MeshLoadReport load_obj(const std::string& path, Scene& scene, std::uint32_t object) {
  return load_obj(path, scene, object, ObjLoadOptions{});
}

MeshLoadReport load_obj(const std::string& path, Scene& scene, std::uint32_t object, const ObjLoadOptions& options) {
  const std::string text = read_file(path);
  ObjMaterials materials(path, scene, object, options);
  std::unique_ptr<tinyobj::MaterialReader> reader;
  if (options.use_materials) {
    materials.read_libraries(text);
    reader = materials.reader();
  }
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  parse_obj(path, text, reader.get(), attrib, shapes);
  if (options.use_materials) materials.note_unknown_names(text);

  MeshLoadReport report;
  const std::size_t vertex_count = attrib.vertices.size() / 3;
  report.vertices = vertex_count;
  check_vertex_coordinates(path, text, attrib.vertices);
  std::vector<Vec3> normals;
  check_normals(path, attrib, normals);
  std::vector<Vec2> texcoords;
  check_texcoords(path, attrib, texcoords);
  // Only a relative vt or vn index can come out as the ambiguous -1.
  const std::vector<std::uint8_t> written =
      text.find("/-") != std::string::npos ? corner_parts(text) : std::vector<std::uint8_t>{};
  auto writes = [&](std::size_t corner, std::uint8_t part) {
    return corner < written.size() && (written[corner] & part) != 0;
  };
  auto vertex = [&](int i) {
    return Vec3{attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]};
  };

  std::size_t face_ordinal = 0;    // faces in file order, across shapes
  std::size_t corner_ordinal = 0;  // their corners, in the same order
  std::vector<Vec3> positions, face_normals;
  std::vector<Vec2> face_uvs;
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t offset = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t fv = shape.mesh.num_face_vertices[f];
      positions.clear();
      face_normals.clear();
      face_uvs.clear();
      bool all_normals = true, all_uvs = true;
      for (std::size_t k = 0; k < fv; ++k, ++corner_ordinal) {
        const tinyobj::index_t idx = shape.mesh.indices[offset + k];
        // Relative (negative) indices were resolved by the reader against the elements read so
        // far; an out-of-range one comes out negative or past the end.
        if (idx.vertex_index < 0 || static_cast<std::size_t>(idx.vertex_index) >= vertex_count) {
          const Location at = locate(path, "f", face_ordinal, k);
          throw InputError(path, at.line, at.col,
                           "vertex index out of range (the file has " + std::to_string(vertex_count) + " vertices)");
        }
        check_attribute_index(idx.normal_index, normals.size(), writes(corner_ordinal, kWritesNormal), "normal",
                              "normals", path, face_ordinal, k);
        check_attribute_index(idx.texcoord_index, texcoords.size(), writes(corner_ordinal, kWritesTexcoord),
                              "texture coordinate", "texture coordinates", path, face_ordinal, k);
        positions.push_back(vertex(idx.vertex_index));
        all_normals = all_normals && idx.normal_index >= 0;
        all_uvs = all_uvs && idx.texcoord_index >= 0;
        if (all_normals) face_normals.push_back(normals[static_cast<std::size_t>(idx.normal_index)]);
        if (all_uvs) face_uvs.push_back(texcoords[static_cast<std::size_t>(idx.texcoord_index)]);
      }
      offset += fv;
      ++face_ordinal;
      if (!all_normals) face_normals.clear();
      if (!all_uvs) face_uvs.clear();
      const int material_id = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      add_polygon(scene.geometry, positions, face_normals, face_uvs, materials.object_for(material_id), report);
    }
  }
  return report;
}

}  // namespace raylab
