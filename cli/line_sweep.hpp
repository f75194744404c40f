#pragma once
// cli/line_sweep: `ncsim line sweep LINE.toml --belt-velocity LO:HI` (issue 37 step 4;
// docs/lines.md "ncsim line sweep").
//
// Purpose: the highest belt velocity at which a production line runs clean: every workpiece
// that arrived taken (none missed, none left on the belt), no channel ending in an error, and
// every channel's audit clean (`line time --audit`); and the binding constraint named: at the
// lowest failing velocity, the workpieces missed (how many, the first), each failing channel's
// error id and text, each channel's first audit violation (axis, quantity, value > limit).
// Inputs: the line file, --belt-velocity LO:HI [mm/s], --tolerance, --grid, --jobs, --conv-vel
// follow|keep, --cycle-us, --max-time.
// Belt velocity (as `ncsim sweep`'s, cli/line_world): the line's encoder belt has its velocity
// and profile scaled so that it runs at the candidate at t = 0; a belt a channel drives
// (spindle) gets every MC_MoveVelocity Velocity > 0 replaced by the candidate. --conv-vel follow
// (default): every channel's #SYNC IN CONV_VEL is the candidate; keep: the programs'.
// Method: cli/sweep_search, the search of `ncsim sweep` (one bisection for both): each
// candidate is a whole line run (runner::LineRun) with its own belt, in parallel; the same
// output on any machine.
// Outputs (stdout): one line per candidate with its verdict; the result, the line's figures
// there (workpieces taken, per minute, each channel's utilisation), the binding constraint.
// Exit 0 when a velocity of [LO, HI] runs clean, 1 when none does, 2 usage (NC9120, NC9121,
// NC9122 no belt to sweep, NC9123 an encoder belt standing at t = 0).

#include <iosfwd>

#include "cli/line_command.hpp"

namespace CLI {
class App;
}

namespace ncsim::cli {

/// `ncsim line sweep`.
int run_line_sweep(const LineOptions& options, std::ostream& out, std::ostream& err);

/// The sweep's options of the `line` subcommand (--belt-velocity, --conv-vel, --tolerance,
/// --grid, --jobs).
void add_line_sweep_options(CLI::App& cmd, LineOptions& options);

}  // namespace ncsim::cli
