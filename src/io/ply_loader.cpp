#include "raylab/io/ply_loader.h"

#include <bit>

#include "ply/ply_body.h"
#include "ply/ply_header.h"
#include "ply/ply_mesh.h"
#include "raylab/io/read_file.h"
#include "raylab/io/text_scanner.h"

// The reader is split by idea under ply/: scalar types, the header, the mesh both bodies fill,
// and one file per body encoding. This file only ties them together.

namespace raylab {

MeshLoadReport parse_ply(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object) {
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
  return mesh.report;
}

MeshLoadReport load_ply(const std::string& path, Scene& scene, std::uint32_t object) {
  const std::string bytes = read_file(path);
  return parse_ply(bytes, path, scene.geometry, object);
}

}  // namespace raylab
