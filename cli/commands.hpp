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
#include "runner/locate.hpp"
#include "runner/spec.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitProgramErrors = 1;
inline constexpr int kExitUsage = 2;

/// What every program-reading subcommand takes (runner/spec.hpp).
using ProgramOptions = runner::ProgramSpec;

// Where the machine and the scenario are, the scenario loaded (runner/locate.hpp).
using runner::apply_cycle_options;
using runner::machine_folder;
using runner::scenario_file;

struct TraceOptions {
  ProgramOptions program;
  std::uint64_t max_commands = 100000;  ///< --max-commands; 0: no limit
};

struct CheckOptions {
  ProgramOptions program;
  bool syntax_only = false;  ///< --syntax-only: grammar and structure, no machine, no interpreter
};

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
