// A 5x7 bitmap font drawn for raylab's legends: wide enough that 0/O, 1/I, 5/S, 8/B and 2/Z are
// told apart at a glance, which the 3x5 font it replaces could not do.

#include "raylab/io/bitmap_font.h"

#include <cctype>

namespace raylab {
namespace {

// Seven rows of five pixels per glyph, '#' = ink, row after row from the top.
struct Glyph {
  char c;
  const char* rows;  // 35 characters
};
// clang-format off
constexpr Glyph kFont[] = {
    {'0', " ### " "#   #" "#  ##" "# # #" "##  #" "#   #" " ### "},
    {'1', "  #  " " ##  " "  #  " "  #  " "  #  " "  #  " " ### "},
    {'2', " ### " "#   #" "    #" "   # " "  #  " " #   " "#####"},
    {'3', "#####" "   # " "  #  " "   # " "    #" "#   #" " ### "},
    {'4', "   # " "  ## " " # # " "#  # " "#####" "   # " "   # "},
    {'5', "#####" "#    " "#### " "    #" "    #" "#   #" " ### "},
    {'6', "  ## " " #   " "#    " "#### " "#   #" "#   #" " ### "},
    {'7', "#####" "    #" "   # " "  #  " " #   " " #   " " #   "},
    {'8', " ### " "#   #" "#   #" " ### " "#   #" "#   #" " ### "},
    {'9', " ### " "#   #" "#   #" " ####" "    #" "   # " " ##  "},
    {'A', " ### " "#   #" "#   #" "#####" "#   #" "#   #" "#   #"},
    {'B', "#### " "#   #" "#   #" "#### " "#   #" "#   #" "#### "},
    {'C', " ### " "#   #" "#    " "#    " "#    " "#   #" " ### "},
    {'D', "#### " "#   #" "#   #" "#   #" "#   #" "#   #" "#### "},
    {'E', "#####" "#    " "#    " "#### " "#    " "#    " "#####"},
    {'F', "#####" "#    " "#    " "#### " "#    " "#    " "#    "},
    {'G', " ### " "#   #" "#    " "# ###" "#   #" "#   #" " ####"},
    {'H', "#   #" "#   #" "#   #" "#####" "#   #" "#   #" "#   #"},
    {'I', " ### " "  #  " "  #  " "  #  " "  #  " "  #  " " ### "},
    {'J', "  ###" "   # " "   # " "   # " "   # " "#  # " " ##  "},
    {'K', "#   #" "#  # " "# #  " "##   " "# #  " "#  # " "#   #"},
    {'L', "#    " "#    " "#    " "#    " "#    " "#    " "#####"},
    {'M', "#   #" "## ##" "# # #" "# # #" "#   #" "#   #" "#   #"},
    {'N', "#   #" "#   #" "##  #" "# # #" "#  ##" "#   #" "#   #"},
    {'O', " ### " "#   #" "#   #" "#   #" "#   #" "#   #" " ### "},
    {'P', "#### " "#   #" "#   #" "#### " "#    " "#    " "#    "},
    {'Q', " ### " "#   #" "#   #" "#   #" "# # #" "#  # " " ## #"},
    {'R', "#### " "#   #" "#   #" "#### " "# #  " "#  # " "#   #"},
    {'S', " ####" "#    " "#    " " ### " "    #" "    #" "#### "},
    {'T', "#####" "  #  " "  #  " "  #  " "  #  " "  #  " "  #  "},
    {'U', "#   #" "#   #" "#   #" "#   #" "#   #" "#   #" " ### "},
    {'V', "#   #" "#   #" "#   #" "#   #" "#   #" " # # " "  #  "},
    {'W', "#   #" "#   #" "#   #" "# # #" "# # #" "# # #" " # # "},
    {'X', "#   #" "#   #" " # # " "  #  " " # # " "#   #" "#   #"},
    {'Y', "#   #" "#   #" " # # " "  #  " "  #  " "  #  " "  #  "},
    {'Z', "#####" "    #" "   # " "  #  " " #   " "#    " "#####"},
    {'.', "     " "     " "     " "     " "     " " ##  " " ##  "},
    {',', "     " "     " "     " "     " " ##  " "  #  " " #   "},
    {'-', "     " "     " "     " " ### " "     " "     " "     "},
    {'+', "     " "  #  " "  #  " "#####" "  #  " "  #  " "     "},
    {'=', "     " "     " "#####" "     " "#####" "     " "     "},
    {'/', "    #" "    #" "   # " "  #  " " #   " "#    " "#    "},
    {':', "     " " ##  " " ##  " "     " " ##  " " ##  " "     "},
    {'(', "   # " "  #  " " #   " " #   " " #   " "  #  " "   # "},
    {')', " #   " "  #  " "   # " "   # " "   # " "  #  " " #   "},
    {'_', "     " "     " "     " "     " "     " "     " "#####"},
    {'%', "##   " "##  #" "   # " "  #  " " #   " "#  ##" "   ##"},
    {'^', "  #  " " # # " "#   #" "     " "     " "     " "     "},
    {'\'', "  #  " "  #  " " #   " "     " "     " "     " "     "},
    {' ', "     " "     " "     " "     " "     " "     " "     "},
};
// clang-format on

const char* glyph_rows(char c) {
  const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kFont) {
    if (g.c == up) return g.rows;
  }
  return nullptr;
}

}  // namespace

bool has_glyph(char c) { return glyph_rows(c) != nullptr; }

void draw_text(Rgb8Image& image, int x, int y, std::string_view text, Rgb8 colour, int scale) {
  for (const char c : text) {
    if (const char* rows = glyph_rows(c)) {
      for (int gy = 0; gy < kGlyphHeight; ++gy) {
        for (int gx = 0; gx < kGlyphWidth; ++gx) {
          if (rows[gy * kGlyphWidth + gx] != '#') continue;
          for (int sy = 0; sy < scale; ++sy) {
            for (int sx = 0; sx < scale; ++sx) image.put(x + gx * scale + sx, y + gy * scale + sy, colour);
          }
        }
      }
    }
    x += (kGlyphWidth + 1) * scale;
  }
}

int text_width(std::string_view text, int scale) {
  return text.empty() ? 0 : ((kGlyphWidth + 1) * static_cast<int>(text.size()) - 1) * scale;
}

}  // namespace raylab
