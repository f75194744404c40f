// The `ncsim` command: the user-facing contract of design.md §5.
//
//   ncsim check PROG.nc|- [--machine DIR] [--scenario FILE] [--ve NAME=value] [--syntax-only]
//                                              exit 0 ok, 1 program errors, 2 usage
//   ncsim trace PROG.nc [--machine DIR] [--scenario FILE] [--ve NAME=value] [--max-commands N]
//   ncsim time|run|report ...           cli/run_commands.hpp (exit 3: --audit violations)
//   ncsim golden check [PROGRAM...] | bless PROGRAM...|--all   cli/golden_command.hpp
//   ncsim sweep PROG.nc --belt-velocity LO:HI    cli/sweep_command.hpp   (--- line)
//   ncsim tune-delay PROG.nc                     cli/tune_delay.hpp
//
// Diagnostics go to stderr as `file:line:col: error: text [id]` with the source line and a
// caret. The command never throws past main: every failure is a message and an exit status.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "cli/golden_command.hpp"
#include "cli/line_command.hpp"
#include "cli/run_commands.hpp"
#include "cli/study_command.hpp"
#include "cli/sweep_command.hpp"
#include "cli/tune_delay.hpp"
#include "core/output_file.hpp"

namespace {

using ncsim::cli::kExitUsage;

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncsim: a virtual CNC channel for ISG / TwinCAT 3 CNC programs"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "ncsim 0.1.0");

  // Options every program-reading subcommand shares.
  const auto add_program_options = [](CLI::App& cmd, ncsim::cli::ProgramOptions& options) {
    cmd.add_option("program", options.program, "NC program file (.nc); - reads standard input")
        ->required();
    cmd.add_option("--machine", options.machine_dir,
                   "Machine folder (parameter lists); default: the program folder's "
                   "'machine' file, else the bundled portal_3x");
    cmd.add_option("--scenario", options.scenario,
                   "Scenario TOML file (docs/scenario.md); default: the program folder's "
                   "scenario.toml; check and trace read its [ve] values");
    cmd.add_option("--ve", options.external,
                   "V.E. variable value, NAME=value (repeatable; each NAME once; wins over the "
                   "scenario's [ve] value)");
    ncsim::cli::add_cycle_options(cmd, options);
  };

  ncsim::cli::CheckOptions check;
  auto* check_cmd =
      app.add_subcommand("check",
                         "Syntax, structure and semantic check of an NC program; every error with "
                         "file:line:col");
  add_program_options(*check_cmd, check.program);
  check_cmd->add_flag("--syntax-only", check.syntax_only,
                      "Syntax and structure only: no machine, no interpreter");

  ncsim::cli::TraceOptions trace;
  auto* trace_cmd = app.add_subcommand(
      "trace", "Print the interpreter's command stream, one command per line with its source line");
  add_program_options(*trace_cmd, trace.program);
  trace_cmd
      ->add_option("--max-commands", trace.max_commands,
                   "Stop after this many commands (0: no limit; endless programs need one)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();

  ncsim::cli::RunCommands run_commands(app);             // binds its options: not const, not moved
  ncsim::cli::GoldenCommands golden_commands(app);       // likewise
  ncsim::cli::SweepCommand sweep_command(app);           // likewise
  ncsim::cli::TuneDelayCommand tune_delay_command(app);  // likewise
  ncsim::cli::LineCommand line_command(app);             // likewise
  ncsim::cli::StudyCommand study_command(app);           // likewise

  // A first word that is no option and no subcommand is named (CLI11 would only say that a
  // subcommand is required).
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    bool known = false;
    std::string names;
    for (const CLI::App* sub : app.get_subcommands({})) {
      known = known || sub->get_name() == word;
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "ncsim: error: unknown command '" << word << "' (commands: " << names
                << "; see ncsim --help)\n";
      return kExitUsage;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help/version on stdout, errors on stderr
    return code == 0 ? 0 : kExitUsage;
  }

  // A closed pipe is a write error (exit 2 with a message), not a silent death by SIGPIPE.
  ncsim::core::ignore_sigpipe();
  try {
    const auto dispatch = [&]() -> int {
      if (const auto status = run_commands.dispatch(std::cout, std::cerr)) return *status;
      if (const auto status = golden_commands.dispatch(std::cout, std::cerr)) return *status;
      if (const auto status = sweep_command.dispatch(std::cout, std::cerr)) return *status;
      if (const auto status = tune_delay_command.dispatch(std::cout, std::cerr)) return *status;
      if (const auto status = line_command.dispatch(std::cout, std::cerr)) return *status;
      if (const auto status = study_command.dispatch(std::cout, std::cerr)) return *status;
      if (trace_cmd->parsed()) return ncsim::cli::run_trace(trace, std::cout, std::cerr);
      return ncsim::cli::run_check(check, std::cout, std::cerr);
    };
    return ncsim::cli::finish_stdout(dispatch(), std::cerr);
  } catch (const std::bad_alloc&) {
    std::cerr << "ncsim: error: out of memory (the program or its diagnostics need more memory "
                 "than is available)\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "ncsim: error: " << e.what() << '\n';
    return kExitUsage;
  }
}
