#pragma once
// interp/trace: the stable one-line text form of commands, and the `ncsim trace` driver.
//
// Inputs: Commands (and the machine for axis names). Outputs: one line per command:
// `<line>: <KIND> <fields>`; numbers fixed with 4 decimals, locale-independent (std::to_chars);
// axis values as NAME=value for the machine's path axes in machine order.
// Also check_semantics(): the semantic check behind `ncsim check` (interprets the whole
// program to its end; stops at the first error, at the first repeat of an endless program
// with note NC4904, or after kCheckMaxCommands with warning NC4902).

#include <cstdint>
#include <ostream>
#include <string>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "interp/command.hpp"
#include "interp/interpreter.hpp"
#include "machines/machine.hpp"

namespace ncsim::interp {

std::string to_trace_line(const Command& command, const machines::Machine& machine);

struct TraceOptions {
  Options interp;                       ///< V.E. values (--ve NAME=value), limits
  std::uint64_t max_commands = 100000;  ///< --max-commands; 0: no limit
};

/// Writes the command stream of `file` to `out`, one line per command. Returns 0 when the
/// program ran to its end (or to max_commands), 1 on a program error (added to `diags`).
int write_trace(const core::SourceFile& file, const machines::Machine& machine,
                const TraceOptions& options, std::ostream& out, core::DiagnosticList& diags);

/// Commands a golden trace holds at most (endless programs are cut there).
inline constexpr std::uint64_t kGoldenCommands = 400;

/// Commands check_semantics interprets at most: kCheckMaxCommands, or kCheckCommandsPerLine
/// per line of the program if that is more (a long straight program is checked to its end).
/// A program that neither ends nor returns to an earlier state (Interpreter::endless_from)
/// within them gets warning NC4902.
inline constexpr std::uint64_t kCheckMaxCommands = 50'000'000;
inline constexpr std::uint64_t kCheckCommandsPerLine = 4;

/// Semantic check: interprets the program without motion and reports its errors (axes the
/// program names, kinematic ids, conveyor rules, arcs, ...). Syntax errors are left to
/// grammar::check_program: the check stops silently at the first block with a syntax error.
core::DiagnosticList check_semantics(const core::SourceFile& file, const machines::Machine& machine,
                                     const Options& options);

}  // namespace ncsim::interp
