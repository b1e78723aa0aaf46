// raylab command line: parses arguments, runs one subcommand, maps errors to exit codes.

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "help_format.h"
#include "isa_option.h"
#include "parse_errors.h"
#include "raylab/core/error.h"
#include "raylab/core/heap_policy.h"
#include "raylab/core/isa.h"
#include "raylab/core/terminal.h"
#include "raylab/dist/launcher.h"
#include "raylab/version.h"

int main(int argc, char** argv) {
  // One render allocates and frees large buffers in turn: reusing them spares fresh pages.
  raylab::reuse_freed_memory();
  // A write past the file-size limit (ulimit -f) then fails with EFBIG, which the atomic writer
  // reports and cleans up after, instead of SIGXFSZ killing the process and leaving a temporary.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"raylab: a ray tracing engine and lab for efficiency and quality", "raylab"};
  // Before the subcommands are added: they inherit the formatter.
  app.formatter(std::make_shared<raylab::cli::WrappingFormatter>(
      static_cast<std::size_t>(raylab::terminal_columns(STDOUT_FILENO))));
  app.require_subcommand(1);
  std::string isa;
  app.add_option("--isa", isa,
                 "Instruction set of the kernels: baseline, avx2 or avx512 (default: the widest this CPU "
                 "has, or RAYLAB_ISA); a lower one is for comparisons");
  // After --isa, whose value CLI11 stores first, so that `raylab --isa avx2 --version` names it.
  app.set_version_flag("--version", [&isa] {
    const std::string head = std::string("raylab ") + raylab::version() + "\n";
    try {
      raylab::cli::choose_isa(isa);
    } catch (const raylab::UsageError& e) {
      return head + "kernels: none (" + e.what() + ")";
    }
    return head + raylab::isa_summary();
  });
  // `raylab bench --isa avx2 ...` reaches the option above too.
  app.fallthrough();
  const raylab::cli::CommandRunner run_render = raylab::cli::add_render_command(app);
  const raylab::cli::CommandRunner run_diff = raylab::cli::add_diff_command(app);
  const raylab::cli::CommandRunner run_info = raylab::cli::add_info_command(app);
  const raylab::cli::CommandRunner run_convert = raylab::cli::add_convert_command(app);
  const raylab::cli::CommandRunner run_compare = raylab::cli::add_compare_command(app);
  const raylab::cli::CommandRunner run_quality = raylab::cli::add_quality_command(app);
  const raylab::cli::CommandRunner run_bench = raylab::cli::add_bench_command(app);
  // Listed among the commands; `raylab help CMD` is read as `raylab CMD --help` before parsing.
  app.add_subcommand("help", "Print this help, or a command's (raylab help render)");
  const std::vector<std::string> args =
      raylab::cli::expand_help_command(app, std::vector<std::string>(argv + 1, argv + argc));
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    app.parse(reversed);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Under an MPI launcher every rank parses the same arguments: one message is enough.
    if (!raylab::dist::launched_by_mpi() || raylab::dist::launcher_rank() == 0) {
      std::fputs(raylab::cli::explain_parse_error(app, e, args).c_str(), stderr);
    }
    return raylab::cli::kExitUsageError;
  }
  try {
    raylab::cli::choose_isa(isa);
    if (app.got_subcommand("render")) return run_render();
    if (app.got_subcommand("diff")) return run_diff();
    if (app.got_subcommand("info")) return run_info();
    if (app.got_subcommand("convert")) return run_convert();
    if (app.got_subcommand("compare")) return run_compare();
    if (app.got_subcommand("quality")) return run_quality();
    if (app.got_subcommand("bench")) return run_bench();
  } catch (const raylab::UsageError& e) {
    if (!raylab::dist::launched_by_mpi() || raylab::dist::launcher_rank() == 0) {
      std::fputs(raylab::cli::usage_error_message(app, e.what()).c_str(), stderr);
    }
    return raylab::cli::kExitUsageError;
  } catch (const raylab::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return raylab::cli::kExitInputError;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "raylab: out of memory\n");
    return raylab::cli::kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab: internal error: %s\n", e.what());
    return raylab::cli::kExitInternalError;
  }
  return 2;
}
