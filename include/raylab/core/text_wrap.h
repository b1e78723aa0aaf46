#pragma once
/// \file
/// Breaking text into lines that fit a terminal, for help text and messages.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

/// `text` broken into lines of at most `width` characters (at least 1): at spaces where it can,
/// a word longer than a line after its commas or vertical bars, else anywhere. Newlines in `text`
/// start new lines; runs of spaces at a break are dropped. An empty text gives no lines.
std::vector<std::string> wrap_text(std::string_view text, std::size_t width);

/// wrap_text(text, width - indent) with every line after the first indented by `indent` spaces,
/// each line ended by a newline: a paragraph that hangs beside a column of names.
std::string wrap_hanging(std::string_view text, std::size_t width, std::size_t indent);

}  // namespace raylab
