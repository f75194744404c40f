#pragma once
// interp/trace: the stable one-line text form of commands, and the `ncsim trace` driver.
//
// Inputs: Commands (and the machine for axis names). Outputs: one line per command:
// `<line>: <KIND> <fields>`; numbers fixed with 4 decimals, locale-independent
// (core::decimals_text); axis values as NAME=value for the machine's path axes in machine order; a
// motion ends with its frame and start point. Also check_semantics(): the semantic check behind
// `ncsim check` (interprets the whole program to its end; stops at the first error, at the first
// repeat of an endless program with note NC4904, or after kCheckMaxCommands with warning NC4902).

#include <array>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "interp/command.hpp"
#include "interp/interpreter.hpp"
#include "machines/machine.hpp"

namespace ncsim::interp {

/// One trace line. A motion ends with ` frame=<frame> start <axes>`: the frame its start, end
/// and arc centre are in, and its start point.
std::string to_trace_line(const Command& command, const machines::Machine& machine);

struct TraceOptions {
  Options interp;                       ///< V.E. values (--ve NAME=value), limits
  std::uint64_t max_commands = 100000;  ///< --max-commands; 0: no limit
};

/// Writes the command stream of `file` to `out`, one line per command, answering each Barrier
/// from the decode-only state. Returns 0 when the program ran to its end, 1 on a program
/// error (added to `diags`). A trace cut at max_commands while the program goes on ends with
/// the line `# truncated after N commands (--max-commands)` and note NC4905 in `diags`; it
/// still returns 0 (nothing is wrong with the program; the marker says the record is partial).
int write_trace(const core::SourceFile& file, const machines::Machine& machine,
                const TraceOptions& options, std::ostream& out, core::DiagnosticList& diags);

/// Smallest and largest coordinates an arc motion reaches on its two plane axes
/// ({axis_1, axis_2} each), in the motion's frame: its end points and every quadrant point
/// the arc passes.
std::pair<std::array<double, 2>, std::array<double, 2>> arc_extent(const Motion& motion);

/// The software-limit errors NC4601 of one command, where decode time can decide them: a
/// motion's or spline point's programmed target in the MCS without kinematics, and the extent
/// of such an arc. `check` reports every one; `time` / `run` refuse the block at its line with
/// the first, before it moves (program::ProgramSource), so both apply one rule (issue 34 item 22).
void add_soft_limit_errors(const Command& c, const machines::Machine& machine,
                           const std::string& file, core::DiagnosticList& out);

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
/// With `program_check`, that check is fed by the interpreter's parse of the program (one parse for
/// both; `ncsim check`): the interpreter stops at the first syntax or structure error found
/// (the semantic findings of such a program are not reported), then the rest of the file is
/// parsed for `program_check`, whose finish() the caller calls.
core::DiagnosticList check_semantics(const core::SourceFile& file, const machines::Machine& machine,
                                     const Options& options,
                                     grammar::ProgramCheck* program_check = nullptr);

}  // namespace ncsim::interp
