#pragma once
/// \file
/// JSON with positions: nlohmann::json keeps no source positions, but every message about a scene
/// file must say `file:line:col`. A JsonDocument is the parsed value plus the line and column of
/// every object key and every object or array, addressed by JSON pointer ("/objects/3/radius").
/// Internal to src/io: it exposes nlohmann::json, which the installed headers must not need.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <unordered_map>

namespace raylab {

/// A 1-based line and column in a text file.
struct TextPosition {
  int line = 0;
  int col = 0;
};

/// A parsed JSON text and where each of its parts came from.
class JsonDocument {
 public:
  /// Parses `text` (named `file` in messages). Throws InputError `file:line:col: ...` for a
  /// syntax error, a duplicate key, or nesting deeper than 64 levels.
  JsonDocument(std::string_view text, std::string file);

  /// The parsed value.
  const nlohmann::json& root() const { return m_root; }
  /// The file name used in messages.
  const std::string& file() const { return m_file; }
  /// Position of the value at JSON pointer `pointer`: of its key when it is an object member,
  /// else of its opening bracket; for an array element that is a scalar, of the array. Never
  /// fails: falls back to the nearest enclosing value that has a position.
  TextPosition where(const std::string& pointer) const;
  /// Throws InputError `file:line:col: message` at the value at `pointer`.
  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const;

  /// Records a position (used while parsing).
  void record(std::string pointer, TextPosition pos) { m_positions.emplace(std::move(pointer), pos); }

 private:
  nlohmann::json m_root;
  std::string m_file;
  std::unordered_map<std::string, TextPosition> m_positions;
};

/// Escapes a key for use in a JSON pointer ("~" -> "~0", "/" -> "~1").
std::string json_pointer_escape(std::string_view key);

}  // namespace raylab
