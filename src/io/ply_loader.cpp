#include "raylab/io/ply_loader.h"

#include <bit>
#include <string>
#include <utility>
#include <vector>

#include "ply/ply_body.h"
#include "ply/ply_header.h"
#include "ply/ply_mesh.h"
#include "raylab/io/read_file.h"
#include "raylab/io/text_scanner.h"

// The reader is split by idea under ply/: scalar types, the header, the mesh both bodies fill,
// and one file per body encoding. This file only ties them together.

namespace raylab {
namespace {

// parse_ply, adding the warnings to `warnings` when given.
MeshLoadReport read_ply(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object,
                        std::vector<std::string>* warnings) {
  using namespace ply_detail;
  TextScanner scanner(file, bytes, 0);
  const Header header = parse_header(scanner);
  const std::size_t body_offset = scanner.offset();
  check_counts(header, bytes.size() - body_offset, file);
  MeshSink mesh(geometry, object);
  if (header.encoding == Encoding::kAscii) {
    read_ascii_body(header, scanner, mesh);
  } else {
    const bool big = header.encoding == Encoding::kBigEndian;
    read_binary_body(header, bytes, body_offset, big != (std::endian::native == std::endian::big), file, mesh);
  }
  if (warnings != nullptr) {
    for (std::string& w : skipped_line_warnings(header, file)) warnings->push_back(std::move(w));
  }
  return mesh.report;
}

}  // namespace

MeshLoadReport parse_ply(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object) {
  return read_ply(bytes, file, geometry, object, nullptr);
}

MeshLoadReport load_ply(const std::string& path, Scene& scene, std::uint32_t object) {
  const std::string bytes = read_file(path);
  return read_ply(bytes, path, scene.geometry, object, &scene.warnings);
}

}  // namespace raylab
