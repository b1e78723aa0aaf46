#include "ply_header.h"

#include <charconv>
#include <optional>
#include <string_view>

#include "raylab/core/error.h"

namespace raylab::ply_detail {
namespace {

std::optional<Scalar> scalar_named(std::string_view name) {
  struct Named {
    std::string_view name;
    Scalar type;
  };
  static constexpr Named kNames[] = {
      {"char", Scalar::kI8},   {"int8", Scalar::kI8},     {"uchar", Scalar::kU8},   {"uint8", Scalar::kU8},
      {"short", Scalar::kI16}, {"int16", Scalar::kI16},   {"ushort", Scalar::kU16}, {"uint16", Scalar::kU16},
      {"int", Scalar::kI32},   {"int32", Scalar::kI32},   {"uint", Scalar::kU32},   {"uint32", Scalar::kU32},
      {"float", Scalar::kF32}, {"float32", Scalar::kF32}, {"double", Scalar::kF64}, {"float64", Scalar::kF64}};
  for (const Named& n : kNames) {
    if (n.name == name) return n.type;
  }
  return std::nullopt;
}

// The next token on the current line; fails naming `what` when the line has ended.
Token word(TextScanner& s, std::string_view what) {
  const Token t = s.next_on_line();
  if (t.text.empty()) s.fail(t, (s.at_end() ? "unexpected end of file, expected " : "expected ") + std::string(what));
  return t;
}

// Checks that nothing more is on the current line and moves to the next one.
void end_of_line(TextScanner& s) {
  const Token t = s.next_on_line();
  if (!t.text.empty()) s.fail(t, "unexpected " + quoted(t.text) + " at the end of the line");
  s.skip_line();
}

Scalar scalar_type(const TextScanner& s, const Token& t) {
  if (const std::optional<Scalar> type = scalar_named(t.text)) return *type;
  s.fail(t, "unknown PLY type " + quoted(t.text) +
                " (expected char, uchar, short, ushort, int, uint, float, double, or int8 ... float64)");
}

Encoding parse_format(TextScanner& s) {
  const Token name = word(s, "a PLY format (ascii, binary_little_endian or binary_big_endian)");
  Encoding encoding = Encoding::kAscii;
  if (name.text == "binary_little_endian") {
    encoding = Encoding::kLittleEndian;
  } else if (name.text == "binary_big_endian") {
    encoding = Encoding::kBigEndian;
  } else if (name.text != "ascii") {
    s.fail(name,
           "unknown PLY format " + quoted(name.text) + " (expected ascii, binary_little_endian or binary_big_endian)");
  }
  const Token version = word(s, "a format version");
  if (version.text != "1.0" && version.text != "1") {
    s.fail(version, "unsupported PLY version " + quoted(version.text) + " (expected 1.0)");
  }
  return encoding;
}

Element parse_element(TextScanner& s) {
  Element e;
  e.name = std::string(word(s, "an element name").text);
  const Token count = word(s, "an element count");
  const char* end = count.text.data() + count.text.size();
  const auto [ptr, ec] = std::from_chars(count.text.data(), end, e.count);
  if (ec != std::errc() || ptr != end) {
    s.fail(count, "expected an element count (a non-negative integer), found " + quoted(count.text));
  }
  e.line = count.line;
  e.col = count.col;
  return e;
}

Property parse_property(TextScanner& s) {
  Property p;
  const Token type = word(s, "a property type");
  p.line = type.line;
  p.col = type.col;
  if (type.text == "list") {
    p.list = true;
    const Token count = word(s, "a list length type");
    p.count_type = scalar_type(s, count);
    if (!is_integer(p.count_type)) s.fail(count, "a list length must have an integer type");
    p.type = scalar_type(s, word(s, "a list item type"));
  } else {
    p.type = scalar_type(s, type);
  }
  p.name = std::string(word(s, "a property name").text);
  return p;
}

// Fewest bytes one record of `e` can take: its binary size with empty lists, or two characters
// (a digit and a separator) per value in ASCII.
std::uint64_t min_record_bytes(const Element& e, bool ascii) {
  std::uint64_t n = 0;
  for (const Property& p : e.properties) n += ascii ? 2 : size_of(p.list ? p.count_type : p.type);
  return n;
}

// Skipped header lines listed one by one in the warnings; the rest are counted. A binary body
// read as header for want of an `end_header` must not make thousands of warnings.
constexpr std::size_t kSkippedListed = 5;

// Skips the rest of the line that `first` starts, which is no PLY keyword, noting it in `header`;
// returns it.
SkippedLine skip_unknown_line(TextScanner& s, const Token& first, Header& header) {
  std::string_view text = first.text;
  for (Token t = s.next_on_line(); !t.text.empty(); t = s.next_on_line()) {
    text = std::string_view(first.text.data(),
                            static_cast<std::size_t>(t.text.data() + t.text.size() - first.text.data()));
  }
  s.skip_line();
  const SkippedLine skipped{quoted(text), first.line, first.col};
  if (header.skipped.size() < kSkippedListed) header.skipped.push_back(skipped);
  ++header.skipped_count;
  return skipped;
}

// For a refusal after skipped lines: the first of them, which may be what went wrong.
std::string skipped_note(const Header& header) {
  if (header.skipped_count == 0) return "";
  const SkippedLine& first = header.skipped.front();
  return " (" + std::to_string(header.skipped_count) + " header line" + (header.skipped_count == 1 ? "" : "s") +
         " starting with no PLY keyword skipped, the first " + first.text + " at line " + std::to_string(first.line) +
         ")";
}

}  // namespace

Header parse_header(TextScanner& s) {
  const Token magic = s.next_on_line();
  if (magic.text != "ply") s.fail(magic, "not a PLY file (the first line must be 'ply')");
  end_of_line(s);
  Header header;
  bool have_format = false;
  std::optional<SkippedLine> skipped_since_element;
  for (;;) {
    if (s.at_end()) s.fail_here("unexpected end of file, expected 'end_header'" + skipped_note(header));
    const Token key = s.next("'end_header'");
    if (key.text == "end_header") {
      if (!have_format) s.fail(key, "the header has no 'format' line");
      end_of_line(s);
      return header;
    }
    if (key.text == "comment" || key.text == "obj_info") {
      s.skip_line();
      continue;
    }
    if (key.text == "format") {
      if (have_format) s.fail(key, "a second 'format' line");
      header.encoding = parse_format(s);
      have_format = true;
    } else if (key.text == "element") {
      header.elements.push_back(parse_element(s));
      skipped_since_element.reset();
    } else if (key.text == "property") {
      if (skipped_since_element) {
        s.fail(key, "a property after the skipped header line " + skipped_since_element->text + " (line " +
                        std::to_string(skipped_since_element->line) +
                        "), which starts with no PLY keyword: is it a misspelt 'element'?");
      }
      if (header.elements.empty()) s.fail(key, "a property before any element");
      header.elements.back().properties.push_back(parse_property(s));
    } else {
      skipped_since_element = skip_unknown_line(s, key, header);
      continue;
    }
    end_of_line(s);
  }
}

std::vector<std::string> skipped_line_warnings(const Header& header, const std::string& file) {
  std::vector<std::string> out;
  for (const SkippedLine& l : header.skipped) {
    out.push_back(file + ":" + std::to_string(l.line) + ":" + std::to_string(l.col) + ": header line " + l.text +
                  " starts with no PLY keyword; skipped");
  }
  if (header.skipped_count > header.skipped.size()) {
    out.push_back(file + ": " + std::to_string(header.skipped_count - header.skipped.size()) +
                  " more such header lines skipped");
  }
  return out;
}

void check_counts(const Header& header, std::uint64_t body_bytes, const std::string& file) {
  const bool ascii = header.encoding == Encoding::kAscii;
  std::uint64_t budget = body_bytes + (ascii ? 1 : 0);  // the last ASCII value needs no separator
  for (const Element& e : header.elements) {
    const std::uint64_t min = min_record_bytes(e, ascii);
    if (min == 0) continue;
    if (e.count > budget / min) {
      throw InputError(file, e.line, e.col,
                       "unexpected end of file: element " + quoted(e.name) + " announces " + std::to_string(e.count) +
                           " records of at least " + std::to_string(min) + " bytes" + (ascii ? " (as text)" : "") +
                           ", but the rest of the file has room for at most " + std::to_string(budget / min));
    }
    budget -= e.count * min;
  }
}

}  // namespace raylab::ply_detail
