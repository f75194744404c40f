#pragma once
// runner/texts: a run's results as the texts the commands print: the error that ended it
// (positioned, with the block echoed), warnings, the stop reason, where a block is, the axes'
// names and units. Pure functions of a Run's state; nothing is printed here.

#include <cstdint>
#include <string>
#include <vector>

#include "channel/channel.hpp"
#include "interp/interpreter.hpp"
#include "machines/machine.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::runner {

class Run;
struct Ending;

/// The text of a run's end when it failed: the run-time error (file:line:col, the time, the id)
/// or the program error that ended the source (with a subroutine file's syntax errors).
std::string failure_text(const Run& run);
/// The interpreter's warnings (a skipped cycle NC4307, a main program without M30 NC2019, ...)
/// and the channel's NC6210 warning, positioned.
std::string warnings_text(const Run& run);
/// A run that ended at the program's end with axes still moving: the NC6106 warning naming
/// them, "" when all stand (issue 34). Not after an error or a [stop].
std::string still_moving_text(const Run& run);
/// Why a run ended (docs/scenario.md "[stop]"): "error", the scenario's [stop] reason,
/// "endless" (`endless`: the source ended where the program repeats, docs/interp.md), or the
/// program end.
std::string stop_reason(bool failed, const channel::Channel& channel, bool endless);
/// The note of a run the program's endless repeat ended (Ending::endless_from), "" otherwise.
std::string endless_note(const Ending& end);
/// What set the stop condition: "scenario 'f.toml'", or "--max-time" for the one the option made.
std::string stop_source(const scenario::Scenario& s);
/// Where a block is: its line in the main program, `file:line` in a subroutine file.
std::string block_where(const interp::Interpreter& interp, std::uint16_t file, std::uint32_t line);
/// The interpolated axes' names, in the channel's order.
std::vector<std::string> axis_names(const machines::Machine& m);
/// The length unit of each interpolated axis: deg for a rotary axis, mm otherwise.
std::vector<std::string> axis_units(const machines::Machine& m);
/// The first line of `s` (without its '\n').
std::string first_line(const std::string& s);
/// The audit's first violation in one line (sweep, tune-delay), "" when it has none listed.
std::string first_violation(const Run& run);

}  // namespace ncsim::runner
