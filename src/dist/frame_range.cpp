#include "raylab/dist/frame_range.h"

namespace raylab::dist {
namespace {

// `frame` in decimal, zero-padded to at least `width` digits.
std::string padded(int frame, std::size_t width) {
  std::string digits = std::to_string(frame);
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  return digits;
}

}  // namespace

std::optional<std::pair<int, int>> parse_frame_range(const std::string& text) {
  const std::size_t colon = text.find(':');
  auto number = [](const std::string& t) -> std::optional<int> {
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return std::stoi(t);
  };
  const std::optional<int> a = number(text.substr(0, colon));
  const std::optional<int> b = colon == std::string::npos ? a : number(text.substr(colon + 1));
  if (!a || !b || *b < *a) return std::nullopt;
  return std::pair{*a, *b};
}

std::string frame_output(const std::string& output, int frame) {
  const std::size_t hash = output.find('#');
  if (hash != std::string::npos) {
    const std::size_t end = output.find_first_not_of('#', hash);
    const std::size_t width = (end == std::string::npos ? output.size() : end) - hash;
    return output.substr(0, hash) + padded(frame, width) + output.substr(hash + width);
  }
  const std::string number = "." + padded(frame, 4);
  const std::size_t dot = output.rfind('.');
  const std::size_t slash = output.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return output + number;
  return output.substr(0, dot) + number + output.substr(dot);
}

}  // namespace raylab::dist
