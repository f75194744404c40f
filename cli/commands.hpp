#pragma once
// cli/commands: the subcommands of `ncsim`, callable with explicit streams so that they are
// testable without a process. Exit statuses: 0 ok, 1 program errors, 2 usage or configuration.

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/source_file.hpp"
#include "machines/machine.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::interp {
struct Options;
}

namespace ncsim::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitProgramErrors = 1;
inline constexpr int kExitUsage = 2;

/// What every program-reading subcommand takes.
struct ProgramOptions {
  std::filesystem::path program;                     ///< NC program file
  std::optional<std::filesystem::path> machine_dir;  ///< --machine
  std::optional<std::filesystem::path> scenario;     ///< --scenario
  std::vector<std::string> external;                 ///< --ve NAME=value (V.E. variables)
  std::vector<std::filesystem::path> cycle_dirs;     ///< --cycles DIR (cycle files, in order)
  std::string missing_cycles = "error";              ///< --missing-cycles error|skip
  /// --max-time S (time, run, report): the run stops at S seconds of machine time like a
  /// scenario's `[stop] time` (the earlier of both); for programs that run endlessly
  std::optional<double> max_time;
};

/// The interpreter options `--cycles` and `--missing-cycles` give (interp::Options).
void apply_cycle_options(const ProgramOptions& options, interp::Options& interp);

struct TraceOptions {
  ProgramOptions program;
  std::uint64_t max_commands = 100000;  ///< --max-commands; 0: no limit
};

struct CheckOptions {
  ProgramOptions program;
  bool syntax_only = false;  ///< --syntax-only: grammar and structure, no machine, no interpreter
};

/// The machine folder a program runs on (design.md §5): --machine, else the bundled machine
/// named in the program folder's `machine` file, else the default bundled machine; nothing
/// (reported on `err`) when that file names none.
std::optional<std::filesystem::path> machine_folder(const ProgramOptions& options,
                                                    std::ostream& err);

/// The scenario file a program runs under (docs/scenario.md): --scenario, else the program
/// folder's `scenario.toml` (the current folder's for `-`) when it exists, else none.
std::optional<std::filesystem::path> scenario_file(const ProgramOptions& options);

/// Loads and validates the scenario of `options` (scenario_file) against `program`'s lines and
/// `machine`'s axis names. No scenario: nullopt. A missing --scenario file or any error in it:
/// every diagnostic printed on `err` (with its source line) and the exit status kExitUsage.
std::variant<std::optional<scenario::Scenario>, int> load_scenario_for(
    const ProgramOptions& options, const core::SourceFile& program,
    const machines::Machine& machine, std::ostream& err);

/// `ncsim check`: syntax, structure and semantics; every diagnostic to `err`, a one-line
/// verdict to `out`.
/// The end of every command: standard output flushed; when it could not be written (a closed
/// pipe, a full disk) and the command has not reported that itself, a message on `err` and
/// kExitUsage instead of `status` (README: an output that cannot be written exits 2).
int finish_stdout(int status, std::ostream& err);

int run_check(const CheckOptions& options, std::ostream& out, std::ostream& err);

/// `ncsim trace`: the interpreter's command stream to `out`, one command per line.
int run_trace(const TraceOptions& options, std::ostream& out, std::ostream& err);

}  // namespace ncsim::cli
