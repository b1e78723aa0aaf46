#pragma once
/// \file
/// Messages for command lines that do not parse, which point at the fix: the nearest valid
/// command or option ("did you mean ...?") and the help of the command that was meant.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace raylab::cli {

/// The message for `error`, raised while `app` parsed `args` (the arguments after the program
/// name): "unknown command 'rendr'; did you mean 'render'?" for a misspelled subcommand,
/// "unknown option '--sppp'; did you mean '--spp'?" for a misspelled option of the subcommand,
/// else CLI11's own words; then the line that names the help to read (`raylab render --help`
/// when the error is in a subcommand). Lines end with a newline; the first starts "raylab: ".
std::string explain_parse_error(const CLI::App& app, const CLI::ParseError& error,
                                const std::vector<std::string>& args);

/// The message of a usage error found after parsing (a raylab::UsageError's `message`), with
/// the line naming the help of the command that was run, as explain_parse_error ends.
std::string usage_error_message(const CLI::App& app, const std::string& message);

/// `args` with `help` and `help CMD` turned into `--help` and `CMD --help`, so that `raylab help
/// render` prints exactly `raylab render --help`; `help NAME` of an unknown NAME becomes `NAME`,
/// which the parser refuses like any unknown command. Other arguments are returned unchanged.
std::vector<std::string> expand_help_command(const CLI::App& app, std::vector<std::string> args);

/// The message of an unknown subcommand `name` of `app`, with the nearest one when it is close.
std::string unknown_command_message(const CLI::App& app, const std::string& name);

}  // namespace raylab::cli
