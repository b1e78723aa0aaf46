#include "raylab/io/svg_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

#include "raylab/io/svg_chart.h"

namespace raylab {
namespace {

constexpr double kBoldFactor = 1.08;

// Advance of `c` in ems, rounded up from DejaVu Sans, the widest of the common sans-serif
// fonts (Liberation Sans and Helvetica are narrower); bytes of UTF-8 sequences count as one
// wide character each for the lead byte and nothing for the rest.
double advance(unsigned char c) {
  if (c >= 0x80) return (c & 0xC0) == 0x80 ? 0.0 : 0.75;
  if (std::strchr("il.,:;'|!`", c) != nullptr) return 0.32;
  if (std::strchr("fjtrI ()[]{}/\\-\"", c) != nullptr) return 0.42;
  if (std::strchr("mwMW%@", c) != nullptr) return 1.0;
  if (std::isupper(c) != 0) return 0.78;
  if (std::isdigit(c) != 0) return 0.64;
  if (std::islower(c) != 0) return 0.64;
  return 0.85;  // symbols: & # = + < > ? * ~ ^ _ $
}

// The words of `text` on lines of at most `max_width` at `font_size`, breaking a word that is
// too long for a line by itself.
std::vector<std::string> wrap_to_width(std::string_view text, double max_width, double font_size) {
  std::vector<std::string> lines;
  std::string line;
  auto fits = [&](const std::string& s) { return estimate_text_width(s, font_size, true) <= max_width; };
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t start = text.find_first_not_of(' ', pos);
    if (start == std::string_view::npos) break;
    const std::size_t end = std::min(text.find(' ', start), text.size());
    std::string word(text.substr(start, end - start));
    pos = end;
    if (!line.empty() && fits(line + " " + word)) {
      line += " " + word;
      continue;
    }
    if (!line.empty()) lines.push_back(line);
    line.clear();
    while (!fits(word) && word.size() > 1) {  // a piece as long as fits, then the rest
      std::size_t n = 1;
      while (n < word.size() && fits(word.substr(0, n + 1))) ++n;
      lines.push_back(word.substr(0, n));
      word.erase(0, n);
    }
    line = word;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

double estimate_text_width(std::string_view text, double font_size, bool bold) {
  double ems = 0.0;
  for (const char c : text) ems += advance(static_cast<unsigned char>(c));
  return ems * font_size * (bold ? kBoldFactor : 1.0);
}

SvgTitle fit_svg_title(std::string_view text, double max_width, double font_size, double min_font_size) {
  SvgTitle title;
  const double width = estimate_text_width(text, font_size, true);
  if (width <= max_width) {
    title.font_size = font_size;
    title.lines = {std::string(text)};
    return title;
  }
  // Width scales with the size: the size that just fits, unless that is below the smallest.
  const double shrunk = font_size * max_width / width;
  if (shrunk >= min_font_size) {
    title.font_size = std::floor(shrunk * 10.0) / 10.0;  // one decimal, rounded down: still fits
    title.lines = {std::string(text)};
    return title;
  }
  title.font_size = min_font_size;
  title.lines = wrap_to_width(text, max_width, min_font_size);
  return title;
}

std::string svg_title_element(const SvgTitle& title, double x, double y) {
  std::string out = fmt::format("<text class=\"title\" x=\"{}\" y=\"{}\" font-size=\"{}\" font-weight=\"bold\">", x, y,
                                title.font_size);
  for (std::size_t i = 0; i < title.lines.size(); ++i) {
    if (i == 0) {
      out += xml_escape(title.lines[i]);
    } else {
      out += fmt::format("<tspan x=\"{}\" dy=\"{}\">{}</tspan>", x, title.line_height(), xml_escape(title.lines[i]));
    }
  }
  return out + "</text>\n";
}

}  // namespace raylab
