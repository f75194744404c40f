#pragma once
// conveyor/belt: the real conveyor belt, as it moves (docs/conveyor.md "The world").
//
// Purpose: the belt's travel, velocity and acceleration over time, with no sensor in between.
// Two sources: an encoder belt moved by the scenario (constant velocity, linear ramps, steps,
// stop and restart; closed form per piece) or a spindle belt the program drives with
// S1[MC_MoveVelocity ...] (a jerk-limited velocity change of jerk/, from the state the belt
// has when the command comes: 0 in a dynamic = the axis list's value). Either may fluctuate
// periodically: v = v_base (1 + A sin(2 pi f t)); a stopped belt stays stopped.
// Inputs: the profile or the commands; times in increasing order (advance()).
// Outputs: BeltState (mm, mm/s, mm/s^2) at the last advance().
// Invariants: deterministic; memory fixed after construction (the profile's pieces); the base
// motion is exact (closed form); the fluctuation's travel is integrated by Simpson's rule over
// each advance (4 sub-intervals: error below 1e-12 mm per 1 ms cycle at 1 Hz).

#include <cstddef>
#include <optional>
#include <vector>

#include "conveyor/port.hpp"
#include "jerk/jerk.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::conveyor {

/// Dynamics an MC_MoveVelocity runs with (after 0 = axis list value is resolved).
struct VelocityDynamics {
  double acceleration = 0.0;  ///< [mm/s^2] speeding up (magnitude), > 0
  double deceleration = 0.0;  ///< [mm/s^2] slowing down (magnitude), > 0
  double jerk = 0.0;          ///< [mm/s^3] both ways, > 0
};

class Belt {
 public:
  /// An encoder belt: velocity v0 [mm/s] from before t = 0, then `profile` (time order, not
  /// overlapping, as the scenario loader guarantees).
  static Belt encoder(double v0, const std::vector<scenario::BeltChange>& profile,
                      std::optional<scenario::BeltFluctuation> fluctuation);
  /// A spindle belt at rest at travel 0 until the first command.
  static Belt spindle(std::optional<scenario::BeltFluctuation> fluctuation);

  /// The base motion (no fluctuation) at t [s]; t never before the last call's (a cursor);
  /// t < 0 extrapolates the state at 0 backwards at constant velocity.
  BeltState base(double t) noexcept;

  /// Moves the belt to time t [s] (>= the last advance's) and returns its state.
  const BeltState& advance(double t) noexcept;
  /// The state at the last advance().
  const BeltState& state() const noexcept { return state_; }
  /// Time of the last advance() [s].
  double time() const noexcept { return t_; }

  /// Spindle belt: from the last advance() on, change the base velocity to v [mm/s] with
  /// `dynamics` (jerk-limited; a reversal uses the smaller of the two accelerations both ways).
  void command(double v, const VelocityDynamics& dynamics) noexcept;

 private:
  struct Piece {  // constant acceleration from t0 on: encoder profile
    double t0 = 0.0, p0 = 0.0, v0 = 0.0, a = 0.0;
  };
  Belt() = default;
  BeltState ramp_state(double t) const noexcept;

  bool encoder_ = true;
  std::vector<Piece> pieces_;
  std::size_t cursor_ = 0;
  // Spindle: the ramp commanded at t_cmd_ from the base state cmd_start_.
  double t_cmd_ = 0.0;
  jerk::State cmd_start_;
  jerk::Ramp ramp_;
  std::optional<scenario::BeltFluctuation> fluctuation_;
  double fluct_travel_ = 0.0;  // [mm] A * integral of v_base sin(w t) dt up to t_
  double t_ = 0.0;
  BeltState state_;
};

}  // namespace ncsim::conveyor
