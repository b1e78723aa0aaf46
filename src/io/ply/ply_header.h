#pragma once
// Internal to the PLY reader: the header (format, elements and their properties), parsed before
// any of the body is read, and the check that its element counts can fit in the body.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ply_scalar.h"
#include "raylab/io/text_scanner.h"

namespace raylab::ply_detail {

/// One property of an element: a scalar, or a list with a length type and an item type.
struct Property {
  std::string name;
  Scalar type = Scalar::kF32;       ///< the value's type, or a list's item type
  Scalar count_type = Scalar::kU8;  ///< a list's length type
  bool list = false;
  int line = 0, col = 0;  ///< where it is declared, for errors about how it is used
};

/// One element of the header: `count` records, each of `properties` in order.
struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  int line = 0, col = 0;  ///< of its count
};

/// How the body is stored.
enum class Encoding { kAscii, kLittleEndian, kBigEndian };

/// A header line that starts with no PLY keyword (exporters write lines such as `Created by
/// ...`), skipped.
struct SkippedLine {
  std::string text;  ///< the line, quoted for a message
  int line = 0, col = 0;
};

/// What the header declares.
struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  std::vector<SkippedLine> skipped;  ///< the first few skipped lines
  std::size_t skipped_count = 0;     ///< all of them
};

/// Reads the header; leaves `s` at the first byte of the body. Fails at the offending token. A
/// line that starts with no PLY keyword is skipped, but a property after it (before the next
/// element) is refused: the line may have been a misspelt `element`, whose properties must not
/// be given to the element before it.
Header parse_header(TextScanner& s);

/// One warning `file:line:col: ...` for each skipped header line, and one for those not listed.
std::vector<std::string> skipped_line_warnings(const Header& header, const std::string& file);

/// Refuses element counts that `body_bytes` bytes of body cannot hold, before anything is
/// allocated for them.
void check_counts(const Header& header, std::uint64_t body_bytes, const std::string& file);

}  // namespace raylab::ply_detail
