#pragma once
// axes/profile_duration_bound: an independent proof that a prescribed duration is physically
// infeasible (test support only; docs/axes-profile.md, "Prescribed durations", gaps).
//
// Purpose: decide, apart from the planner's families, whether a duration T from a start to
// (p1, v1, a = 0) lies in a physical gap (Ruckig's "blocked intervals"). Only the frame
// toward the target with v0 >= 0 and v1 >= 0 is decided (else: undecided).
// Method: the jerk limit is dropped (a relaxation: every jerk-limited profile is one of the
// relaxed ones, so a bound on the relaxed profiles holds for the real ones), the velocity
// limit too. With path limits (A- while slowing, A+ while speeding up):
//  - class A, v >= 0 throughout: p is monotone and d(v^2)/dp lies in [-2 A-, 2 A+], so
//    v(p)^2 >= v0^2 - 2 A- p and v(p)^2 >= v1^2 - 2 A+ (D - p); T = integral dp / v is at most
//    that of the lower envelope, (v0 - w) / A- + (v1 - w) / A+ with w^2 (1/(2A-) + 1/(2A+)) =
//    v0^2/(2A-) + v1^2/(2A+) - D (unbounded when that is <= 0: the axis can rest on the way;
//    none when w > min(v0, v1): v1 is out of reach within D without going back);
//  - class B, v < 0 somewhere: reaching v = 0 first takes >= v0 / A- over >= v0^2 / (2 A-);
//    after the last v = 0 the rise to v1 takes >= v1 / A+ over >= v1^2 / (2 A+); in between
//    the axis goes back by >= B = v0^2/(2A-) + v1^2/(2A+) - D from rest to rest, which takes
//    >= sqrt(2 B (1/A+ + 1/A-)) (speeding backward at A+, slowing at A-).
// T above class A's bound and below class B's is infeasible. Loose by the jerk: a duration
// between the bounds is proven a gap, one outside them is not proven feasible.

#include <algorithm>
#include <cmath>

#include "axes/profile.hpp"

namespace ncsim::test {

/// The relaxed bounds of a start and target in the frame toward the target.
struct DurationBounds {
  bool decided = false;  ///< frame with v0 >= 0, v1 >= 0, D > 0 (else the bounds are unset)
  double t_no_reverse_max = 0.0;  ///< class A: longest duration without moving backward [s]
  double t_reverse_min = 0.0;     ///< class B: shortest duration moving backward somewhere [s]
};

inline DurationBounds duration_bounds(const axes::MotionState& start,
                                      const axes::PositionTarget& target, const axes::Dynamics& d) {
  DurationBounds b;
  const double dp = target.p - start.p;
  if (dp == 0.0) return b;
  const double f = dp > 0.0 ? 1.0 : -1.0;
  const double v0 = f * start.v;
  const double v1 = f * target.v;
  const double dist = f * dp;
  if (v0 < 0.0 || v1 < 0.0) return b;
  b.decided = true;
  const double ap = d.a_max;
  const double am = d.d_max;
  const double excess = v0 * v0 / (2.0 * am) + v1 * v1 / (2.0 * ap) - dist;
  if (excess <= 0.0) {
    b.t_no_reverse_max = INFINITY;
  } else {
    const double w = std::sqrt(excess / (0.5 / am + 0.5 / ap));
    // w above v0 or v1: the branches cross outside [0, D], no such profile at all.
    b.t_no_reverse_max = w > std::min(v0, v1) ? 0.0 : (v0 - w) / am + (v1 - w) / ap;
  }
  const double back = std::max(0.0, excess);
  b.t_reverse_min = v0 / am + std::sqrt(2.0 * back * (1.0 / ap + 1.0 / am)) + v1 / ap;
  return b;
}

/// True when the relaxed bounds prove that no profile of duration t exists (a physical gap).
inline bool proven_gap(const DurationBounds& b, double t) {
  return b.decided && t > b.t_no_reverse_max && t < b.t_reverse_min;
}

}  // namespace ncsim::test
