#include "parse_errors.h"

#include <algorithm>
#include <cctype>

#include "raylab/core/suggest.h"

namespace raylab::cli {
namespace {

// A usage error's two lines: what is wrong, then the help that shows how to say it.
std::string with_help_hint(const std::string& message, const std::string& help) {
  return "raylab: " + message + "\nRun '" + help + "' for usage.\n";
}

// A word on the command line that names an option, not a value such as -1 or '-' (stdout).
bool looks_like_option(const std::string& arg) {
  if (arg.size() < 2 || arg[0] != '-') return false;
  if (arg[1] == '-') return arg.size() > 2;
  return std::isalpha(static_cast<unsigned char>(arg[1])) != 0;
}

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  return names;
}

// Every spelling of every option of `cmd`, with its dashes: --spp, -o, --output, ...
std::vector<std::string> option_names(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : cmd.get_options()) {
    for (const std::string& n : opt->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : opt->get_snames()) names.push_back("-" + n);
  }
  return names;
}

// The first option in `args` from `first` on that `cmd` does not have, without any "=value".
std::optional<std::string> first_unknown_option(const CLI::App& cmd, const std::vector<std::string>& args,
                                                std::size_t first) {
  const std::vector<std::string> known = option_names(cmd);
  for (std::size_t i = first; i < args.size(); ++i) {
    if (args[i] == "--") break;  // what follows is positional
    if (!looks_like_option(args[i])) continue;
    std::string name = args[i].substr(0, args[i].find('='));
    if (name.size() > 2 && name[1] != '-') name = name.substr(0, 2);  // -o4: -o with value 4
    if (std::find(known.begin(), known.end(), name) == known.end()) return name;
  }
  return std::nullopt;
}

std::string unknown_option_message(const CLI::App& cmd, const std::string& name) {
  std::string message = "unknown option '" + name + "'";
  // Compared without dashes, so that the tolerance is counted on the word itself.
  auto strip = [](const std::string& n) { return n.substr(n.find_first_not_of('-')); };
  std::vector<std::string> bare;
  for (const std::string& n : option_names(cmd)) bare.push_back(strip(n));
  if (const auto near = closest_name(strip(name), bare)) {
    const auto i = std::find(bare.begin(), bare.end(), *near) - bare.begin();
    message += "; did you mean '" + option_names(cmd)[static_cast<std::size_t>(i)] + "'?";
  }
  return message;
}

// The position of the subcommand in `args`: the first word that is not an option.
std::optional<std::size_t> command_position(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (!looks_like_option(args[i])) return i;
  }
  return std::nullopt;
}

}  // namespace

std::string unknown_command_message(const CLI::App& app, const std::string& name) {
  std::string message = "unknown command '" + name + "'";
  if (const auto near = closest_name(name, subcommand_names(app))) message += "; did you mean '" + *near + "'?";
  return message;
}

std::string explain_parse_error(const CLI::App& app, const CLI::ParseError& error,
                                const std::vector<std::string>& args) {
  std::string message = error.what();
  std::string help = "raylab --help";
  const std::optional<std::size_t> at = command_position(args);
  const CLI::App* cmd = nullptr;
  if (at) {
    const std::vector<std::string> names = subcommand_names(app);
    if (std::find(names.begin(), names.end(), args[*at]) == names.end()) {
      message = unknown_command_message(app, args[*at]);
    } else {
      cmd = app.get_subcommand(args[*at]);
      help = "raylab " + args[*at] + " --help";
    }
  }
  if (!at) {
    std::string names;
    for (const std::string& n : subcommand_names(app)) names += (names.empty() ? "" : ", ") + n;
    message = "no command given (" + names + ")";
  }
  if (!at || cmd != nullptr) {
    const CLI::App& scope = cmd != nullptr ? *cmd : app;
    if (const auto unknown = first_unknown_option(scope, args, at ? *at + 1 : 0)) {
      message = unknown_option_message(scope, *unknown);
    }
  }
  return with_help_hint(message, help);
}

std::string usage_error_message(const CLI::App& app, const std::string& message) {
  const std::vector<CLI::App*> ran = app.get_subcommands();
  return with_help_hint(message, ran.empty() ? "raylab --help" : "raylab " + ran.front()->get_name() + " --help");
}

std::vector<std::string> expand_help_command(const CLI::App& app, std::vector<std::string> args) {
  if (args.empty() || args[0] != "help") return args;
  if (args.size() == 1) return {"--help"};
  const std::vector<std::string> names = subcommand_names(app);
  // An unknown name is left alone, for the parser to refuse as any unknown command.
  if (std::find(names.begin(), names.end(), args[1]) == names.end()) return {args[1]};
  return {args[1], "--help"};
}

}  // namespace raylab::cli
