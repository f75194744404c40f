#pragma once
// axes/profile_limits_check: the one limit check of the PTP tests (test support only).
//
// Purpose: issue 11's proof demand "never exceeding V/A/J beyond what the start state forces",
// checked the same way in every test that plans profiles: the profile is sampled at every
// phase boundary, inside every phase (quarters, the velocity extreme where a = 0, every
// crossing of v = 0) and on a uniform grid over its duration, and each sample is checked
// against V, the path limits of 002_* 2.1 (A+ while the acceleration speeds the motion up, A-
// while it slows it down, whatever the sign of v) and J.
// Inputs: the profile, the Dynamics it was planned with, the start state the test gave.
// Output: an empty string when every sample holds, else the first violation (time, value,
// limit), for INFO / REQUIRE in the test.
// The start's forced part (the only exception, made explicit): a start outside the limits
// (|v0| > V, |a0| beyond its path limit, a release of a0 at full jerk ending beyond V, or a
// braking whose release crosses v = 0 with |a| beyond A+) may exceed the limits only until
// the profile's first sample inside, and only by what the start forces: |v| up to
// max(|v0|, |release velocity|), the acceleration's excess over its path limit up to the
// start's own excess or its release's excess at v = 0. From the first sample inside on (which
// is t = 0 for every start inside), the limits hold strictly. Written apart from the kernel:
// nothing here calls the planner's classification (outside_limits, recover).
// Rounding at v = 0: a double velocity near 0 carries ~1e-16 of the way's velocities, so where
// v crosses 0 is known only to dt = dv / |a| and the acceleration there only to J dv / |a|
// (seen: J / A+ = 6e4, 6.7e-9 of A+ beyond it at the crossing). With dv = 4e-15 of the
// velocity scale, a crossing may exceed min(A+, A-) by J dv / |a|, and a sample whose |v| is
// within dv of 0 (its sign not known) is held to the larger of A+ and A-.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "axes/profile.hpp"
#include "core/tolerance.hpp"

namespace ncsim::test {

namespace limits_detail {

// Release velocity of (v, a) at full jerk J (a taken to 0).
inline double release(double v, double a, double j) {
  return v + a * std::abs(a) / (2.0 * j);
}

// Path limit of the acceleration at (v, a): A+ where it speeds the motion up (or starts it
// from v = 0), A- where it slows it down (002_* 2.1).
inline double path_cap(double v, double a, const axes::Dynamics& d) {
  return (v == 0.0 || v * a > 0.0) ? d.a_max : d.d_max;
}

// |a| when the release of a braking (v, a) crosses v = 0; 0 when it does not cross.
inline double crossing_acc(double v, double a, double j) {
  if (!(v * a < 0.0)) return 0.0;
  const double c2 = a * a - 2.0 * j * std::abs(v);
  return c2 > 0.0 ? std::sqrt(c2) : 0.0;
}

// True when (v, a) lies inside the limits, its forced release included (relative tol).
inline bool inside(double v, double a, const axes::Dynamics& d, double tol) {
  if (std::abs(v) > d.v_max * (1.0 + tol)) return false;
  if (std::abs(a) > path_cap(v, a, d) * (1.0 + tol)) return false;
  if (std::abs(release(v, a, d.j_max)) > d.v_max * (1.0 + tol)) return false;
  return crossing_acc(v, a, d.j_max) <= d.a_max * (1.0 + tol);
}

}  // namespace limits_detail

/// First violation of V, the path limits A+/A- or J along `p` (planned from `start` under
/// `d`), beyond what the start forces; empty when none. `tol`: relative tolerance of every
/// limit; `grid`: uniform samples over the duration in addition to the phase samples.
inline std::string profile_limit_violation(const axes::Profile& p, const axes::Dynamics& d,
                                           const axes::MotionState& start, double tol = kRelTol,
                                           int grid = 256) {
  using namespace limits_detail;
  const double j = d.j_max;
  // The start's forced excesses (zero for a start inside).
  const double v_forced = std::max(std::abs(start.v), std::abs(release(start.v, start.a, j)));
  const double v_bound = std::max(d.v_max, v_forced) * (1.0 + tol);
  const double a_excess = std::max({0.0, std::abs(start.a) - path_cap(start.v, start.a, d),
                                    crossing_acc(start.v, start.a, j) - d.a_max});
  const double dv = 4e-15 * std::max(d.v_max, v_forced);  // velocity rounding near v = 0
  std::ostringstream why;
  why.precision(17);
  for (const auto& ph : p.phases()) {
    if (!(std::abs(ph.j) <= j * (1.0 + tol))) {
      why << "phase at t=" << ph.t_start << ": |jerk| " << std::abs(ph.j) << " > J " << j;
      return why.str();
    }
  }
  // Sample times: phase boundaries, quarters, a = 0 and v = 0 inside each phase, the grid.
  struct Sample {
    double t;
    bool crossing;  // a v = 0 crossing: both path limits apply
  };
  std::vector<Sample> ts;
  ts.reserve(p.phases().size() * 8 + static_cast<std::size_t>(grid) + 2);
  for (const auto& ph : p.phases()) {
    for (const double f : {0.0, 0.25, 0.5, 0.75, 1.0})
      ts.push_back({ph.t_start + f * ph.duration, false});
    if (ph.j != 0.0) {
      const double tz = -ph.a / ph.j;
      if (tz > 0.0 && tz < ph.duration) ts.push_back({ph.t_start + tz, false});
      const double disc = ph.a * ph.a - 2.0 * ph.j * ph.v;
      if (disc >= 0.0) {
        const double sq = std::sqrt(disc);
        for (const double r : {(-ph.a - sq) / ph.j, (-ph.a + sq) / ph.j})
          if (r > 0.0 && r < ph.duration) ts.push_back({ph.t_start + r, true});
      }
    } else if (ph.a != 0.0) {
      const double r = -ph.v / ph.a;
      if (r > 0.0 && r < ph.duration) ts.push_back({ph.t_start + r, true});
    }
  }
  for (int k = 0; k <= grid; ++k)
    ts.push_back({p.duration() * k / grid, false});
  std::sort(ts.begin(), ts.end(), [](const Sample& x, const Sample& y) { return x.t < y.t; });
  bool in = inside(start.v, start.a, d, tol);
  for (const Sample& s : ts) {
    const axes::Setpoint sp = p.at(s.t);
    if (!(std::abs(sp.j) <= j * (1.0 + tol))) {
      why << "t=" << s.t << ": |j| " << std::abs(sp.j) << " > J " << j;
      return why.str();
    }
    double cap = path_cap(sp.v, sp.a, d);
    if (std::abs(sp.v) <= dv) cap = std::max(d.a_max, d.d_max);  // the sign of v not known
    // At a crossing of v = 0 the motion slows (A-) before and speeds up (A+) after it.
    if (s.crossing && sp.a != 0.0)
      cap = std::min(d.a_max, d.d_max) + j * dv / std::abs(sp.a) / (1.0 + tol);
    if (!in) in = inside(sp.v, sp.a, d, tol);
    const double v_lim = in ? d.v_max * (1.0 + tol) : v_bound;
    const double a_lim = (cap + (in ? 0.0 : a_excess)) * (1.0 + tol);
    if (!(std::abs(sp.v) <= v_lim)) {
      why << "t=" << s.t << (in ? "" : " (forced part)") << ": |v| " << std::abs(sp.v) << " > "
          << v_lim << " (V " << d.v_max << ")";
      return why.str();
    }
    if (!(std::abs(sp.a) <= a_lim)) {
      why << "t=" << s.t << (in ? "" : " (forced part)") << (s.crossing ? " (v = 0)" : "")
          << ": |a| " << std::abs(sp.a) << " > " << a_lim << " at v " << sp.v << " (A+ " << d.a_max
          << ", A- " << d.d_max << ")";
      return why.str();
    }
  }
  return {};
}

}  // namespace ncsim::test
