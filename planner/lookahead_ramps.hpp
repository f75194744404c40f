#pragma once
// planner/lookahead_ramps: closed forms on jerk ramps shared by the look-ahead
// (lookahead.cpp) and the segment profiles (lookahead_profile.cpp); internal to planner/.
//
// Purpose: the release velocity of a carried acceleration, a Ramp as a StateRamp, and the
// time and distance of ramps with a = 0 at both ends in closed form (guesses for searches).
// Inputs: velocities [mm/s], accelerations [mm/s^2], jerks [mm/s^3] (j > 0).
// Outputs: the values named; pure functions.
// Invariants: the closed forms equal the kernel's (jerk/) distances up to rounding only: they
// guide searches, never decide a limit.

#include <cmath>

#include "jerk/jerk.hpp"

namespace ncsim::planner::ramps {

/// Velocity at which the acceleration a0 >= 0 is released with j (no lower level is reached
/// from (v0, a0) without the velocity passing it first).
inline double released_velocity(double v0, double a0, double j) noexcept {
  return a0 > 0.0 ? v0 + 0.5 * a0 * a0 / j : v0;
}

/// The same phases as a StateRamp (a_end = 0), for the kernel's cut functions.
inline jerk::StateRamp as_state_ramp(const jerk::Ramp& r) noexcept {
  return jerk::StateRamp{r.jerk, r.duration, r.a_peak, r.v_end, 0.0};
}

/// Duration of a ramp between two velocities dv >= 0 apart with a = 0 at both ends (the
/// kernel's velocity_ramp from a0 = 0): jerk phases alone up to dv = a^2 / j (peak acceleration
/// sqrt(dv j)), else with a hold at a.
inline double ramp_time(double dv, double a, double j) {
  return dv * j <= a * a ? 2.0 * std::sqrt(dv / j) : dv / a + a / j;
}

/// The distance of the two ramps v_entry -> level -> v_exit (a = 0 at each end) in closed form:
/// a ramp with a = 0 at both ends is symmetric, so it covers its mean velocity times its
/// duration. Equal to the kernel's distances up to rounding (and the kernel's snapping of
/// rounding residues); used only to guess where the level lies.
inline double ramps_distance_model(double v_entry, double level, double v_exit, double a, double d,
                                   double j) {
  return 0.5 * (v_entry + level) * ramp_time(level - v_entry, a, j) +
         0.5 * (level + v_exit) * ramp_time(level - v_exit, d, j);
}

}  // namespace ncsim::planner::ramps
