#pragma once
/// \file
/// The help text's layout: CLI11's, with every line wrapped to the terminal's width.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

namespace raylab::cli {

/// CLI11's help formatter with names and descriptions wrapped to `width` columns: a description
/// hangs beside its option's name (on the lines below when the name is too long), and option
/// choices such as {box,tent,gaussian} break after a comma. Set on the app before its
/// subcommands are added, which inherit it.
class WrappingFormatter : public CLI::Formatter {
 public:
  /// Lines of at most `width` columns (the names' column scales with it).
  explicit WrappingFormatter(std::size_t width);

  /// The whole help, with one blank line between sections (CLI11 puts two).
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override;
  /// One option: its name and value type, then its description.
  std::string make_option(const CLI::Option* opt, bool is_positional) const override;
  /// One subcommand in the app's list: its name, then its description.
  std::string make_subcommand(const CLI::App* sub) const override;
  /// The app's description, wrapped.
  std::string make_description(const CLI::App* app) const override;
  /// The usage line, wrapped with its continuation indented.
  std::string make_usage(const CLI::App* app, std::string name) const override;
  /// The footer, wrapped.
  std::string make_footer(const CLI::App* app) const override;

 private:
  // "  NAME  description", wrapped: the description in the column after the names.
  std::string entry(const std::string& name, const std::string& description) const;

  std::size_t m_width;
};

}  // namespace raylab::cli
