#pragma once
// cli/sweep_command: `ncsim sweep PROG.nc --belt-velocity LO:HI` (issue 14 "Finding the line's
// limits"; docs/conveyor.md "The line's limits offline").
//
// Purpose: the highest belt velocity at which a conveyor program runs through: no program or
// run-time error (an abort, 50653, 50587, a workspace exit NC9052/NC9053, a soft limit, a lag or
// any dynamic error of the axes) and no audit violation (`time --audit`'s check on the axes'
// setpoints). The manual says the highest velocity "is determined by testing" on the machine;
// this tests it offline.
// Inputs: the program, machine and scenario as `time` takes them; --belt-velocity LO:HI [mm/s],
// --tolerance [mm/s] (default 1), --grid K candidates per round (default 3), --jobs N threads
// (default: the cores, at most K), --cycle-us.
// Belt velocity: a belt the program drives (spindle mode) gets every MC_MoveVelocity with a
// Velocity > 0 replaced by the candidate; an encoder belt has the scenario's velocity and
// profile scaled so that its velocity at t = 0 is the candidate (fluctuation and noise kept
// relative). --conv-vel follow (default): every #SYNC IN's CONV_VEL is the candidate too
// (interp::Options::conv_vel), so the sweep finds how fast the line runs with the program set
// for that belt; --conv-vel keep: the program's CONV_VEL stays, so 50653 bites at
// 1.1 x CONV_VEL (seed 004 l.514) and the sweep finds how far the belt may run above the
// program's declaration.
// Method: cli/sweep_search (shared with `ncsim line sweep`): round 0 runs LO and HI; then each
// round runs K candidates evenly inside the interval [highest passing, lowest failing] at once
// (one thread each, at most --jobs at a time) until the interval is <= the tolerance; the same
// output on any machine.
// Outputs (stdout): one line per candidate with its verdict; the result with the margin to the
// conveyor workspace's conveying face (the smallest distance of the commanded TCP to it while
// synchronised) at the result. Exit 0 when a velocity in [LO, HI] runs, 1 when none does, 2
// for usage errors (NC9120..NC9124).
// Invariants: deterministic; every candidate is a separate run with its own world.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "cli/sweep_search.hpp"

namespace CLI {
class App;
}

namespace ncsim::cli {

/// NC9122: the machine has no conveyor axis or its channel no conveyor tracking: nothing to sweep.
inline constexpr const char* kSweepNoConveyorId = "NC9122";
/// NC9123: an encoder belt whose scenario velocity at t = 0 is 0: nothing to scale.
inline constexpr const char* kSweepEncoderZeroId = "NC9123";

struct SweepOptions {
  ProgramOptions program;
  std::string belt_velocity;        ///< "LO:HI" [mm/s]
  std::string conv_vel = "follow";  ///< "follow": CONV_VEL := the candidate; "keep": the program's
  double tolerance = 1.0;           ///< [mm/s] the result's resolution
  unsigned grid = 3;                ///< candidates per round
  unsigned jobs = 0;                ///< threads (0: the cores)
  std::optional<std::uint64_t> cycle_us;
};

/// `ncsim sweep`.
int run_sweep(const SweepOptions& options, std::ostream& out, std::ostream& err);

class SweepCommand {
 public:
  explicit SweepCommand(CLI::App& app);
  /// The exit status when `sweep` was parsed; nullopt otherwise.
  std::optional<int> dispatch(std::ostream& out, std::ostream& err) const;

 private:
  SweepOptions options_;
  CLI::App* cmd_ = nullptr;
};

}  // namespace ncsim::cli
