#pragma once
// jerk/crossing: crossing_ramp (jerk.hpp) split into the part that depends on the start only
// and the part that depends on the end velocity, so a level search that evaluates many end
// velocities from one start computes the start's part once (docs/axes-profile.md, "Speed").
//
// Purpose: the time-optimal change through v = 0 of crossing_ramp. Its acceleration at v = 0 is
//     a_z = min(A-, A+, sqrt(2 J v1), sqrt(a0^2 + 2 J |v0|)),
// so for every v1 with sqrt(2 J v1) >= a_fix = min(A-, A+, sqrt(a0^2 + 2 J |v0|)) the crossing
// phases (and the distance they cover) are the same: computed once in CrossingStart.
// Inputs: frame start (v0 [mm/s], a0 [mm/s^2]), end velocity v1 [mm/s], Limits.
// Outputs: the same Crossing and Ramp as crossing_ramp, bit for bit (the same expressions in
// the same order; only where they are evaluated differs), and the crossing's distance [mm].
// Invariants: crossing_from(crossing_start(v0, a0, lim), v1, ..) == crossing_ramp(v0, a0, v1, ..).
// Internal to jerk/ (not part of jerk.hpp). Nothing allocates or throws.

#include <algorithm>
#include <cmath>

#include "jerk/jerk.hpp"

namespace ncsim::jerk::detail {

/// The start's part of a crossing (independent of the end velocity).
struct CrossingStart {
  bool possible = false;       ///< the start moves backward (or reverses) and a0 <= A-
  double v0 = 0.0;             ///< frame start velocity [mm/s]
  double a0 = 0.0;             ///< frame start acceleration [mm/s^2]
  double v_zero = 0.0;         ///< release velocity v0 + a0 |a0| / (2J) [mm/s]
  double a_z_min = 0.0;        ///< lowest acceleration at v = 0 the start allows [mm/s^2]
  double a_fix = 0.0;          ///< min(A-, A+, sqrt(a0^2 + 2 J |v0|)) [mm/s^2]
  bool fixed_ok = false;       ///< `fixed` holds the crossing for a_z = a_fix
  Crossing fixed;              ///< the crossing phases for a_z = a_fix
  double fixed_dist = 0.0;     ///< distance covered by `fixed` from (v0, a0) [mm]
  double fixed_release = 0.0;  ///< release velocity of (0, a_fix): a_fix^2 / (2J) [mm/s]
};

/// Crossing phases from (v0, a0) that reach v = 0 with acceleration a_z (crossing_ramp's body).
inline Crossing crossing_phases(double v0, double a0, double a_z, const Limits& lim) noexcept {
  const double j = lim.j_max;
  const double c = lim.d_max;
  const double gain = -v0;
  double a_p = std::sqrt(0.5 * (2.0 * j * gain + a0 * a0 + a_z * a_z));
  double t_hold = 0.0;
  if (a_p > c) {
    a_p = c;
    const double dv_ramps = (2.0 * c * c - a0 * a0 - a_z * a_z) / (2.0 * j);
    const double dv_hold = gain - dv_ramps;
    if (dv_hold > kResidue * (gain + std::abs(dv_ramps))) t_hold = dv_hold / c;
  }
  a_p = std::max({a_p, a0, a_z});
  const double up = a_p - a0;
  const double down = a_p - a_z;
  Crossing cross;
  cross.jerk = {j, 0.0, -j};
  cross.duration = {up > kResidue * a_p ? up / j : 0.0, t_hold,
                    down > kResidue * a_p ? down / j : 0.0};
  cross.a_peak = a_p;
  cross.a_zero = a_z;
  return cross;
}

/// Distance [mm] of the crossing phases from (v0, a0) (integrated phase by phase).
inline double crossing_distance(double v0, double a0, const Crossing& cross) noexcept {
  State st{0.0, v0, a0};
  for (std::size_t i = 0; i < 3; ++i)
    st = advance(st, cross.jerk[i], cross.duration[i]);
  return st.p;
}

/// The start's part of crossing_ramp(v0, a0, ., lim) written into `cs` (default-constructed or
/// from an earlier call: every member the answer depends on is set); `prepare_fixed`: also the
/// crossing for a_z = a_fix (worth it where several end velocities follow). In place, so a
/// frame holding it is not zero-filled and copied a second time (issue 11, session 25).
/// `v_zero`: the start's release velocity v0 + a0 |a0| / (2J), where the caller has it.
inline void crossing_start_into(CrossingStart& cs, double v0, double a0, double v_zero,
                                const Limits& lim, bool prepare_fixed) noexcept {
  const double j = lim.j_max;
  cs.v0 = v0;
  cs.a0 = a0;
  cs.v_zero = v_zero;
  const double c = lim.d_max;
  const double gain = -v0;
  // A start that neither moves backward nor reverses, or one beyond A- while slowing (it
  // forces its own ramp), has no crossing.
  cs.possible = (v0 < 0.0 || v_zero < 0.0) && !(a0 > c);
  cs.fixed_ok = false;
  if (!cs.possible) return;
  cs.a_z_min = a0 > 0.0 ? std::sqrt(std::max(0.0, a0 * a0 - 2.0 * j * gain)) : 0.0;
  cs.a_fix = std::min({c, lim.a_max, std::sqrt(a0 * a0 + 2.0 * j * gain)});
  cs.fixed_ok = prepare_fixed && !(cs.a_z_min > cs.a_fix);
  if (cs.fixed_ok) {
    cs.fixed = crossing_phases(v0, a0, cs.a_fix, lim);
    cs.fixed_dist = crossing_distance(v0, a0, cs.fixed);
    cs.fixed_release = 0.0 + cs.a_fix * std::abs(cs.a_fix) / (2.0 * j);
  }
}

/// The same as a value.
inline CrossingStart crossing_start(double v0, double a0, const Limits& lim,
                                    bool prepare_fixed) noexcept {
  CrossingStart cs;
  crossing_start_into(cs, v0, a0, v0 + a0 * std::abs(a0) / (2.0 * lim.j_max), lim, prepare_fixed);
  return cs;
}

/// crossing_ramp from a prepared start; `cross_dist` (when given) receives the crossing's
/// distance [mm].
inline bool crossing_from(const CrossingStart& cs, double v1, const Limits& lim, Crossing& cross,
                          Ramp& rest, double* cross_dist) noexcept {
  if (!(v1 > 0.0) || !cs.possible) return false;
  const double j = lim.j_max;
  const double a_v1 = std::sqrt(2.0 * j * v1);  // releasing it from v = 0 gains exactly v1
  const double a_z = std::min(cs.a_fix, a_v1);
  if (cs.a_z_min > a_z) return false;  // the start reaches v = 0 too fast (or overshoots v1)
  const bool fixed = cs.fixed_ok && a_z == cs.a_fix;
  if (fixed) {
    cross = cs.fixed;
    if (cross_dist != nullptr) *cross_dist = cs.fixed_dist;
  } else {
    cross = crossing_phases(cs.v0, cs.a0, a_z, lim);
    if (cross_dist != nullptr) *cross_dist = crossing_distance(cs.v0, cs.a0, cross);
  }
  if (a_z == a_v1) {
    // Only the release of a_z: built directly, since velocity_ramp would see v1 == v_zero to
    // rounding and answer a spurious pulse of sqrt(rounding) size (docs/axes-profile.md,
    // "Numerics").
    rest = Ramp{};
    rest.jerk = {j, 0.0, -j};
    rest.duration = {0.0, 0.0, a_z / j};
    rest.a_peak = a_z;
    rest.v_end = v1;
    return true;
  }
  // The rest ramp from (0, a_z): velocity_ramp's release velocity 0 + a_z |a_z| / (2J), for
  // a_z = a_fix prepared once with the start (issue 36: a division per level).
  const double v_zero = fixed ? cs.fixed_release : 0.0 + a_z * std::abs(a_z) / (2.0 * j);
  rest = velocity_ramp_released(0.0, a_z, v_zero, v1, lim.a_max, lim.d_max, j);
  return true;
}

}  // namespace ncsim::jerk::detail
