#pragma once
/// \file
/// A built-in 5x7-pixel font for the labels of heat map legends, so that no font library is
/// needed: digits, capital letters and the punctuation of numbers and titles.

#include <string_view>

#include "raylab/io/rgb8_image.h"

namespace raylab {

/// Width of a glyph in font pixels; glyphs are one font pixel apart.
inline constexpr int kGlyphWidth = 5;
/// Height of a glyph in font pixels (capitals and digits fill it; ',' reaches its last row).
inline constexpr int kGlyphHeight = 7;

/// Draws `text` at (x, y) (top-left), each font pixel a `scale` x `scale` square, clipped to the
/// image. Letters are drawn as capitals; characters without a glyph as blanks.
void draw_text(Rgb8Image& image, int x, int y, std::string_view text, Rgb8 colour, int scale);

/// Width in pixels of `text` as draw_text draws it at `scale` (0 for an empty text).
int text_width(std::string_view text, int scale);

/// True when draw_text has a glyph for `c` (a space is a glyph with no ink).
bool has_glyph(char c);

}  // namespace raylab
