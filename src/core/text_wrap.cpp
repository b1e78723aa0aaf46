#include "raylab/core/text_wrap.h"

#include <algorithm>

namespace raylab {
namespace {

// Splits a word longer than `width` into pieces that fit, preferring to end a piece after a
// comma or '|' (the separators of option choices such as {box,tent,gaussian}).
void split_long_word(std::string_view word, std::size_t width, std::vector<std::string>& lines) {
  while (word.size() > width) {
    std::size_t cut = width;
    const std::size_t sep = word.substr(0, width).find_last_of(",|");
    if (sep != std::string_view::npos && sep > 0) cut = sep + 1;
    lines.emplace_back(word.substr(0, cut));
    word.remove_prefix(cut);
  }
  lines.emplace_back(word);
}

// Spaces inside a line are kept as written (so are a paragraph's leading ones, an indentation);
// those at a break are dropped.
void wrap_paragraph(std::string_view text, std::size_t width, std::vector<std::string>& lines) {
  std::string line;
  std::size_t pos = 0;
  bool first_word = true;
  while (pos < text.size()) {
    const std::size_t word_start = text.find_first_not_of(' ', pos);
    if (word_start == std::string_view::npos) break;  // trailing spaces
    const std::string_view gap = text.substr(pos, word_start - pos);
    const std::size_t end = std::min(text.find(' ', word_start), text.size());
    const std::string_view word = text.substr(word_start, end - word_start);
    pos = end;
    const bool fits = line.size() + gap.size() + word.size() <= width;
    if (fits && (!line.empty() || first_word)) {
      line += gap;
      line += word;
      first_word = false;
      continue;
    }
    first_word = false;
    std::string_view rest = word;
    if (!line.empty() && word.size() > width && line.size() + gap.size() < width) {
      // A word that must be split anyway starts on this line, up to a separator that fits.
      const std::size_t room = width - line.size() - gap.size();
      const std::size_t sep = word.substr(0, room).find_last_of(",|");
      if (sep != std::string_view::npos && sep > 0) {
        line += gap;
        line += word.substr(0, sep + 1);
        rest.remove_prefix(sep + 1);
      }
    }
    if (!line.empty()) lines.push_back(std::move(line));
    line.clear();
    if (rest.size() > width) {
      split_long_word(rest, width, lines);
      line = std::move(lines.back());  // the last piece may take more words
      lines.pop_back();
    } else {
      line = rest;
    }
  }
  lines.push_back(std::move(line));
}

}  // namespace

std::vector<std::string> wrap_text(std::string_view text, std::size_t width) {
  width = std::max<std::size_t>(width, 1);
  std::vector<std::string> lines;
  if (text.ends_with('\n')) text.remove_suffix(1);  // a final newline ends the text, not a line
  if (text.empty()) return lines;
  std::size_t start = 0;
  while (true) {
    const std::size_t nl = text.find('\n', start);
    wrap_paragraph(text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start), width,
                   lines);
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  return lines;
}

std::string wrap_hanging(std::string_view text, std::size_t width, std::size_t indent) {
  std::string out;
  const std::size_t room = width > indent ? width - indent : 1;
  bool first = true;
  for (const std::string& line : wrap_text(text, room)) {
    if (!first) out.append(indent, ' ');
    out += line;
    out += '\n';
    first = false;
  }
  return out;
}

}  // namespace raylab
