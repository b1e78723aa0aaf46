#pragma once
/// \file
/// Text that fits its SVG canvas. An SVG writer cannot measure text (the viewer picks the font),
/// so widths are estimated per character from the advances of common sans-serif fonts, on the
/// wide side, and a title is shrunk, then wrapped, until the estimate fits.

#include <string>
#include <string_view>
#include <vector>

namespace raylab {

/// Estimated width in SVG user units of `text` set in a sans-serif font of `font_size`: each
/// character's advance as a fraction of the font size (narrow i, l, punctuation; wide m, w;
/// capitals wider than lower case), 8% more in bold. Meant to be at least the width that
/// DejaVu Sans, Liberation Sans (Arial) and Helvetica give, so that a text that fits by the
/// estimate fits on screen.
double estimate_text_width(std::string_view text, double font_size, bool bold = false);

/// A title fitted to a width: its font size and its lines (one unless it had to wrap).
struct SvgTitle {
  double font_size = 0.0;          ///< in SVG user units
  std::vector<std::string> lines;  ///< each within the width by estimate_text_width

  /// Distance between two lines' baselines.
  double line_height() const { return font_size * 1.25; }
  /// The height the lines after the first add to the title.
  double extra_height() const { return lines.size() > 1 ? line_height() * static_cast<double>(lines.size() - 1) : 0; }
};

/// `text` set in bold at `font_size`, shrunk as far as `min_font_size` when that makes it fit
/// `max_width` on one line, else wrapped at spaces at `min_font_size` (a word too long for a
/// line alone is broken inside it).
SvgTitle fit_svg_title(std::string_view text, double max_width, double font_size, double min_font_size);

/// `title` as one bold SVG <text> element, its first baseline at (x, y), further lines as
/// <tspan>s below it; the text XML-escaped.
std::string svg_title_element(const SvgTitle& title, double x, double y);

}  // namespace raylab
