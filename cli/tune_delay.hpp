#pragma once
// cli/tune_delay: `ncsim tune-delay PROG.nc` (issue 14 "Finding the line's limits"; seed 004
// l.1601-1605, l.737-747; docs/conveyor.md "Tuning the delay time offline").
//
// Purpose: propose the delay time P-AXIS-00626 (conv_sync.delay_time) that zeroes the static
// part (the mean) of synchro_lag, as the manual tells the commissioning engineer to do by hand
// ("synchro_lag > 0 -> delay_time set too high").
// Inputs: the program, machine and scenario as `time` takes them (the scenario must move the
// belt and bring workpieces: the manual's synchro_lag programs, programs/synchro_lag_*),
// --cycle-us.
// Method: run 1 with the machine's delay time d0: the mean synchro_lag m and the mean master
// velocity along PCS0 X v (v_master_comp) over the synchronised cycles (phase tracking). The
// delay-time compensation adds v x delay_time to the frame (docs/conveyor.md F-5), so the
// lag moves by v per second of delay time: d1 = d0 - m / v, rounded to 1 us (the list's unit).
// Run 2 with d1 shows the static part left (the check). Both runs are the same deterministic
// simulation apart from P-AXIS-00626.
// Outputs (stdout): both runs' mean, minimum, maximum synchro_lag, the proposal in us, and for
// reference the scenario's dead time plus the position filter's delay ((n - 1) T / 2); with
// --contour also each run's contour error on the real workpiece (ContourStats; the accuracy
// benchmark bench/line_accuracy.sh reads these lines).
// Exit 0; 1 when a run fails or never synchronises (NC9125); 2 for usage errors (NC9126).
// Invariants: deterministic.

#include <cstdint>
#include <iosfwd>
#include <optional>

#include "cli/commands.hpp"

namespace CLI {
class App;
}

namespace ncsim::cli {

/// NC9125: tune-delay: the program never ran synchronised with a moving belt (no synchro_lag).
inline constexpr const char* kTuneNoLagId = "NC9125";
/// NC9126: tune-delay: the machine has no conveyor axis with conveyor tracking.
inline constexpr const char* kTuneNoConveyorId = "NC9126";

struct TuneDelayOptions {
  ProgramOptions program;
  std::optional<std::uint64_t> cycle_us;
  bool contour = false;  ///< --contour: also the contour error on the real workpiece
};

/// The statistics of synchro_lag over the synchronised cycles of one run.
struct LagStats {
  std::uint64_t cycles = 0;  ///< synchronised cycles with a moving belt
  double mean = 0.0;         ///< [mm] the static part
  double min = 0.0;          ///< [mm]
  double max = 0.0;          ///< [mm]
  double rms = 0.0;          ///< [mm]
  double v_mean = 0.0;       ///< [mm/s] mean v_master_comp over the same cycles
};

/// The contour error on the real workpiece over the synchronised feed cycles (G01/G02/G03 with
/// the path moving): the actual X/Y/Z mapped into the true workpiece frame (real belt travel since
/// the real front edge, tracking/synchro_lag.hpp real_travel) minus the commanded PCS1 point; the
/// contour error is its part normal to the path's direction, the position error all of it.
struct ContourStats {
  std::uint64_t cycles = 0;
  double contour_rms = 0.0;   ///< [mm]
  double contour_max = 0.0;   ///< [mm]
  double position_rms = 0.0;  ///< [mm]
  double position_max = 0.0;  ///< [mm]
};

/// `ncsim tune-delay`.
int run_tune_delay(const TuneDelayOptions& options, std::ostream& out, std::ostream& err);

class TuneDelayCommand {
 public:
  explicit TuneDelayCommand(CLI::App& app);
  /// The exit status when `tune-delay` was parsed; nullopt otherwise.
  std::optional<int> dispatch(std::ostream& out, std::ostream& err) const;

 private:
  TuneDelayOptions options_;
  CLI::App* cmd_ = nullptr;
};

}  // namespace ncsim::cli
