#include "help_format.h"

#include <algorithm>

#include "raylab/core/text_wrap.h"

namespace raylab::cli {

WrappingFormatter::WrappingFormatter(std::size_t width) : m_width(width) {
  // CLI11's 30 columns of names at 80; fewer on a narrow terminal, so descriptions keep room.
  column_width(std::clamp<std::size_t>(width * 3 / 8, 12, 30));
}

std::string WrappingFormatter::entry(const std::string& name, const std::string& description) const {
  const std::size_t column = get_column_width();
  const std::string left = "  " + name;
  if (left.size() + 1 <= column) {
    if (description.empty()) return left + '\n';
    return left + std::string(column - left.size(), ' ') + wrap_hanging(description, m_width, column);
  }
  std::string out;
  // A name too long for its column: on lines of its own (continued under itself), then the
  // description below it in the column.
  for (const std::string& line : wrap_text(name, m_width - 4)) {
    out += (out.empty() ? "  " : "    ") + line + '\n';
  }
  if (!description.empty()) out += std::string(column, ' ') + wrap_hanging(description, m_width, column);
  return out;
}

std::string WrappingFormatter::make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const {
  std::string help = CLI::Formatter::make_help(app, std::move(name), mode);
  for (std::size_t at; (at = help.find("\n\n\n")) != std::string::npos;) help.erase(at, 1);
  return help;
}

std::string WrappingFormatter::make_option(const CLI::Option* opt, bool is_positional) const {
  return entry(make_option_name(opt, is_positional) + make_option_opts(opt), make_option_desc(opt));
}

std::string WrappingFormatter::make_subcommand(const CLI::App* sub) const {
  return entry(sub->get_display_name(true), sub->get_description());
}

std::string WrappingFormatter::make_description(const CLI::App* app) const {
  return wrap_hanging(CLI::Formatter::make_description(app), m_width, 0);
}

std::string WrappingFormatter::make_usage(const CLI::App* app, std::string name) const {
  return wrap_hanging(CLI::Formatter::make_usage(app, std::move(name)), m_width, 4);
}

std::string WrappingFormatter::make_footer(const CLI::App* app) const {
  return wrap_hanging(CLI::Formatter::make_footer(app), m_width, 0);
}

}  // namespace raylab::cli
