#pragma once
// The typed access to a scene file's JSON that every part of the scene reader shares: a Node is
// one value of the document with its JSON pointer, and its accessors check type and range and
// fail with `file:line:col: message` at the offending key, listing what is valid.

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "json_document.h"
#include "raylab/core/vec3.h"

namespace raylab::scene_json_detail {

using nlohmann::json;

inline std::string type_name(const json& v) {
  if (v.is_number_integer() || v.is_number_unsigned()) return "an integer";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  return "null";
}

inline std::string join(std::span<const std::string_view> names) {
  std::string out;
  for (auto n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

constexpr double kRequired = std::numeric_limits<double>::quiet_NaN();
// As a lower bound: the value must be greater than zero.
constexpr double kPositive = std::numeric_limits<double>::denorm_min();

inline std::string number_text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

inline std::string range_text(double lo, double hi) {
  if (lo == kPositive) return hi == HUGE_VAL ? "must be greater than 0" : "must be in (0, " + number_text(hi) + "]";
  if (hi == HUGE_VAL) return "must be at least " + number_text(lo);
  if (lo == -HUGE_VAL) return "must be at most " + number_text(hi);
  return "must be in [" + number_text(lo) + ", " + number_text(hi) + "]";
}

// Typed access to one JSON object of the scene, with messages that say where and what.
class Node {
 public:
  Node(const JsonDocument& doc, const json& value, std::string pointer, std::string what)
      : m_doc(doc), m_value(value), m_pointer(std::move(pointer)), m_what(std::move(what)) {}

  const json& value() const { return m_value; }
  const std::string& pointer() const { return m_pointer; }
  [[noreturn]] void fail(const std::string& message) const { m_doc.fail(m_pointer, message); }
  [[noreturn]] void fail_at(std::string_view key, const std::string& message) const {
    m_doc.fail(child_pointer(key), message);
  }

  // Every key must be one of `valid`: a misspelt key must not be silently ignored.
  void check_keys(std::initializer_list<std::string_view> valid) const {
    if (!m_value.is_object()) fail(m_what + " must be an object, found " + type_name(m_value));
    for (const auto& item : m_value.items()) {
      bool known = false;
      for (auto v : valid) known = known || item.key() == v;
      if (!known)
        fail_at(item.key(), "unknown key '" + item.key() + "' in " + m_what + " (valid: " +
                                join(std::span<const std::string_view>(valid.begin(), valid.size())) + ")");
    }
  }
  bool has(std::string_view key) const { return m_value.contains(std::string(key)); }
  Node child(std::string_view key, const std::string& what) const {
    return Node(m_doc, m_value.at(std::string(key)), child_pointer(key), what);
  }
  Node element(std::size_t i, const std::string& what) const {
    return Node(m_doc, m_value.at(i), m_pointer + "/" + std::to_string(i), what);
  }

  // `fallback` is the value when the key is absent; NaN (kRequired) makes the key required.
  double number(std::string_view key, double fallback = kRequired, double lo = -HUGE_VAL, double hi = HUGE_VAL) const {
    if (!has(key)) {
      if (!std::isnan(fallback)) return fallback;
      fail(m_what + " needs '" + std::string(key) + "'");
    }
    const json& v = m_value.at(std::string(key));
    if (!v.is_number()) fail_at(key, "'" + std::string(key) + "' must be a number, found " + type_name(v));
    const double d = v.get<double>();
    const bool below = lo == kPositive ? !(d > 0.0) : d < lo;
    if (!std::isfinite(d) || below || d > hi)
      fail_at(key, "'" + std::string(key) + "' is " + v.dump() + ", " + range_text(lo, hi));
    return d;
  }
  float real(std::string_view key, double fallback = kRequired, double lo = -HUGE_VAL, double hi = HUGE_VAL) const {
    return static_cast<float>(number(key, fallback, lo, hi));
  }
  std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const {
    if (!has(key)) return fallback;
    const json& v = m_value.at(std::string(key));
    if (!v.is_number_integer() && !v.is_number_unsigned()) {
      fail_at(key, "'" + std::string(key) + "' must be an integer, found " + type_name(v));
    }
    if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) {
      fail_at(key, "'" + std::string(key) + "' is " + v.dump() + ", must be in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "]");
    }
    const std::int64_t i = v.get<std::int64_t>();
    if (i < lo || i > hi) {
      fail_at(key, "'" + std::string(key) + "' is " + v.dump() + ", must be in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "]");
    }
    return i;
  }
  bool boolean(std::string_view key, bool fallback) const {
    if (!has(key)) return fallback;
    const json& v = m_value.at(std::string(key));
    if (!v.is_boolean()) fail_at(key, "'" + std::string(key) + "' must be true or false, found " + type_name(v));
    return v.get<bool>();
  }
  std::string string(std::string_view key, std::optional<std::string> fallback = std::nullopt) const {
    if (!has(key)) {
      if (fallback) return *fallback;
      fail(m_what + " needs '" + std::string(key) + "'");
    }
    const json& v = m_value.at(std::string(key));
    if (!v.is_string()) fail_at(key, "'" + std::string(key) + "' must be a string, found " + type_name(v));
    return v.get<std::string>();
  }
  std::string choice(std::string_view key, std::span<const std::string_view> valid,
                     std::optional<std::string> fallback = std::nullopt) const {
    const std::string s = string(key, fallback);
    for (auto v : valid)
      if (s == v) return s;
    fail_at(key, "'" + std::string(key) + "' is '" + s + "' (valid: " + join(valid) + ")");
  }
  std::string choice(std::string_view key, std::initializer_list<std::string_view> valid,
                     std::optional<std::string> fallback = std::nullopt) const {
    return choice(key, std::span<const std::string_view>(valid.begin(), valid.size()), std::move(fallback));
  }
  Vec3 vec3(std::string_view key, std::optional<Vec3> fallback = std::nullopt) const {
    if (!has(key)) {
      if (fallback) return *fallback;
      fail(m_what + " needs '" + std::string(key) + "'");
    }
    return to_vec3(m_value.at(std::string(key)), child_pointer(key), key);
  }
  // A colour: [r, g, b], or one number for grey.
  Color color(std::string_view key, Color fallback) const {
    if (!has(key)) return fallback;
    const json& v = m_value.at(std::string(key));
    if (v.is_number()) {
      const float g = real(key, kRequired, 0.0);
      return {g, g, g};
    }
    const Vec3 c = to_vec3(v, child_pointer(key), key);
    if (c.x < 0.f || c.y < 0.f || c.z < 0.f) fail_at(key, "'" + std::string(key) + "' must not be negative");
    return c;
  }
  Vec3 to_vec3(const json& v, const std::string& pointer, std::string_view key) const {
    if (!v.is_array() || v.size() != 3) {
      m_doc.fail(pointer, "'" + std::string(key) + "' must be an array of 3 numbers, found " + type_name(v) +
                              (v.is_array() ? " of " + std::to_string(v.size()) : ""));
    }
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) {
        m_doc.fail(pointer, "'" + std::string(key) + "' must be an array of 3 finite numbers");
      }
      out[i] = v[i].get<float>();
    }
    return out;
  }
  std::string child_pointer(std::string_view key) const { return m_pointer + "/" + json_pointer_escape(key); }

 private:
  const JsonDocument& m_doc;
  const json& m_value;
  std::string m_pointer;
  std::string m_what;
};

}  // namespace raylab::scene_json_detail
