#include "json_document.h"

#include "json_syntax_error.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <vector>

#include "raylab/core/error.h"

namespace raylab {
namespace {

using nlohmann::json;

// Forward iterator over the text that tells the parser's reads to a shared counter, so the SAX
// handler knows how far the lexer has read when an event arrives (nlohmann reports positions
// only for syntax errors).
struct CountingIterator {
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* p = nullptr;
  std::size_t* consumed = nullptr;
  const char* base = nullptr;

  reference operator*() const { return *p; }
  CountingIterator& operator++() {
    ++p;
    *consumed = static_cast<std::size_t>(p - base);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p == o.p; }
  bool operator!=(const CountingIterator& o) const { return p != o.p; }
};

constexpr std::size_t kMaxDepth = 64;

// Builds the DOM and records positions. Containers are recorded at their opening bracket, keys
// at their opening quote.
class PositionSax {
 public:
  PositionSax(std::string_view text, const std::size_t* consumed, const LineIndex& lines, JsonDocument& doc, json& root)
      : m_text(text), m_consumed(consumed), m_lines(lines), m_doc(doc), m_root(root) {}

  bool null() { return add(json(nullptr)); }
  bool boolean(bool v) { return add(json(v)); }
  bool number_integer(json::number_integer_t v) { return add(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return add(json(v)); }
  bool number_float(json::number_float_t v, const std::string&) { return add(json(v)); }
  bool string(std::string& v) { return add(json(std::move(v))); }
  bool binary(json::binary_t&) { return add(json(nullptr)); }

  bool start_object(std::size_t) { return open(json::object()); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(std::string& k) {
    // The lexer has just read the closing quote; walk back to the opening one.
    std::size_t end = *m_consumed;  // one past the closing quote
    std::size_t start = end >= 2 ? end - 2 : 0;
    while (start > 0 && !(m_text[start] == '"' && m_text[start - 1] != '\\')) --start;
    Frame& f = m_stack.back();
    if (f.value->contains(k)) {
      const TextPosition pos = m_lines.at(start);
      throw InputError(m_doc.file(), pos.line, pos.col, "duplicate key '" + k + "'");
    }
    f.key = k;
    m_doc.record(f.pointer + "/" + json_pointer_escape(k), m_lines.at(start));
    return true;
  }

  bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& e) {
    // nlohmann's message starts "[json.exception.parse_error.101] parse error at line L, column C: ".
    std::string message = e.what();
    if (const auto colon = message.find(": "); colon != std::string::npos) message = message.substr(colon + 2);
    (void)token;
    std::optional<OpenContainer> open;
    if (!m_stack.empty()) {
      const Frame& f = m_stack.back();
      open = OpenContainer{f.value->is_object(), f.open_offset, f.key, f.name};
    }
    throw_json_syntax_error(m_text, m_lines, m_doc.file(), position, std::move(message), open);
  }

 private:
  struct Frame {
    json* value;
    std::string pointer;
    std::string key;              // object frames: the key whose value comes next
    std::size_t open_offset = 0;  // of the opening bracket
    std::string name;             // its key in the parent object, if it has one
  };

  // Where the next value goes: its slot in the parent, and its JSON pointer.
  std::pair<json*, std::string> slot() {
    if (m_stack.empty()) return {&m_root, ""};
    Frame& f = m_stack.back();
    if (f.value->is_array()) {
      const std::string pointer = f.pointer + "/" + std::to_string(f.value->size());
      f.value->push_back(nullptr);
      return {&f.value->back(), pointer};
    }
    json* v = &(*f.value)[f.key];
    return {v, f.pointer + "/" + json_pointer_escape(f.key)};
  }

  bool add(json v) {
    *slot().first = std::move(v);
    return true;
  }

  bool open(json container) {
    if (m_stack.size() >= kMaxDepth) {
      const TextPosition pos = m_lines.at(*m_consumed - 1);
      throw InputError(m_doc.file(), pos.line, pos.col, "JSON nested deeper than 64 levels");
    }
    auto [v, pointer] = slot();
    *v = std::move(container);
    // Object members are recorded at their key already; array elements and the root here.
    m_doc.record(pointer, m_lines.at(*m_consumed - 1));
    const bool member = !m_stack.empty() && m_stack.back().value->is_object();
    m_stack.push_back({v, pointer, {}, *m_consumed - 1, member ? m_stack.back().key : std::string()});
    return true;
  }

  bool close() {
    m_stack.pop_back();
    return true;
  }

  std::string_view m_text;
  const std::size_t* m_consumed;
  const LineIndex& m_lines;
  JsonDocument& m_doc;
  json& m_root;
  std::vector<Frame> m_stack;
};

}  // namespace

std::string json_pointer_escape(std::string_view key) {
  std::string out;
  for (const char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

JsonDocument::JsonDocument(std::string_view text, std::string file) : m_file(std::move(file)) {
  const LineIndex lines(text);
  std::size_t consumed = 0;
  PositionSax sax(text, &consumed, lines, *this, m_root);
  const CountingIterator first{text.data(), &consumed, text.data()};
  const CountingIterator last{text.data() + text.size(), &consumed, text.data()};
  json::sax_parse(first, last, &sax);
}

TextPosition JsonDocument::where(const std::string& pointer) const {
  std::string p = pointer;
  for (;;) {
    if (const auto it = m_positions.find(p); it != m_positions.end()) return it->second;
    if (p.empty()) return {};
    p.erase(p.rfind('/'));
  }
}

void JsonDocument::fail(const std::string& pointer, const std::string& message) const {
  const TextPosition pos = where(pointer);
  throw InputError(m_file, pos.line, pos.col, message);
}

}  // namespace raylab
