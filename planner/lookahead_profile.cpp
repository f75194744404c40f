// planner/lookahead_profile: the jerk-limited velocity profile of a planned segment and its
// closed-form evaluation (profile(), profile_at(); see planner/lookahead.hpp).

#include <algorithm>
#include <cmath>

#include "planner/lookahead.hpp"
#include "planner/lookahead_ramps.hpp"

namespace ncsim::planner {

using ramps::as_state_ramp;
using ramps::ramps_distance_model;
using ramps::released_velocity;

namespace {

/// Distance of the two ramps (v_entry, a_entry) -> level -> v_exit.
double ramps_distance(double v_entry, double a_entry, double level, double v_exit, double a,
                      double d, double j) {
  const jerk::Ramp up = jerk::velocity_ramp(v_entry, a_entry, level, a, d, j);
  const jerk::Ramp down = jerk::velocity_ramp(level, 0.0, v_exit, a, d, j);
  return jerk::distance(v_entry, a_entry, up) + jerk::distance(level, 0.0, down);
}

/// The phases of `r` after the time t (the acceleration there is a_at): a carried brake's
/// rest, followed exactly as it was planned (solving the change again from the cut state can
/// differ: the pulse's peak is a square root of the velocity change, so a rounding residue of
/// it becomes a pulse of its own).
jerk::Ramp ramp_after(jerk::Ramp r, double t, double a_at) noexcept {
  for (std::size_t i = 0; i < 3; ++i) {
    const double cut = std::min(t, r.duration[i]);
    r.duration[i] -= cut;
    t -= cut;
    if (i == 2 && cut > 0.0) r.a_peak = a_at;  // phases 0, 1 emptied: they end at a_at
  }
  return r;
}

/// ramps_distance() from a carried (v0, a0 > 0), as a guess: the first ramp is the rest of a
/// ramp begun at a = 0 at v0 - a0^2 / 2j a0 / j earlier (exact when its peak is at least a0).
double carried_ramps_distance_model(double v0, double a0, double level, double v_exit, double a,
                                    double d, double j) {
  const double t = a0 / j;
  const double v_start = v0 - 0.5 * a0 * t;
  const double before = v_start * t + j * t * t * t / 6.0;
  return ramps_distance_model(v_start, level, v_exit, a, d, j) - before;
}

/// Weight of the stale end of the bracket when the same end moved twice in a row
/// (Anderson-Bjorck: 1 - g_new / g_replaced; Illinois' 1/2 where that is not in (0, 1)).
double stale_weight(double g_new, double g_replaced) noexcept {
  const double m = 1.0 - g_new / g_replaced;
  return m > 0.0 ? m : 0.5;
}

/// A sign-changing bracket of a rising g: g(fit) <= 0 < g(miss), both evaluated.
struct Bracket {
  double fit, miss;
  double g_fit, g_miss;
};

/// Narrows `b` by a bracketed secant (Anderson-Bjorck) until miss - fit <= width (at most 40
/// evaluations of g).
template <class G>
void narrow(Bracket& b, const G& g, double width) {
  int side = 0;  // which end moved last: -1 fit, +1 miss
  for (int iter = 0; iter < 40 && b.miss - b.fit > width; ++iter) {
    double x = (b.fit * b.g_miss - b.miss * b.g_fit) / (b.g_miss - b.g_fit);
    if (!(x > b.fit && x < b.miss)) x = 0.5 * (b.fit + b.miss);
    const double gx = g(x);
    if (gx <= 0.0) {
      if (side == -1) b.g_miss *= stale_weight(gx, b.g_fit);
      b.fit = x;
      b.g_fit = gx;
      side = -1;
    } else {
      if (side == 1) b.g_fit *= stale_weight(gx, b.g_miss);
      b.miss = x;
      b.g_miss = gx;
      side = 1;
    }
  }
}

/// The level the bisection "keep lo while distance(mid) <= length" on [lo, hi] would return,
/// to the last bit, with a handful of distance evaluations (docs/planner.md "Profile level").
/// distance(hi) > length on entry; distance() rises with the level; `model` is a cheap
/// closed form of distance() (equal up to rounding).
/// First the model's root, found by a bracketed secant on the model alone, is bracketed by two
/// evaluations of distance() a fifth of the bisection's final width apart; where that fails
/// (the model does not bracket, or its root is off) a bracketed secant on distance() narrows
/// [fit, miss] to a quarter of that width. Then the bisection is replayed on its own midpoints:
/// a midpoint at or below `fit` fits and one at or above `miss` does not (monotonicity), so
/// only midpoints inside the narrow bracket are evaluated.
/// `g_hi` = distance(hi) - length > 0.
template <class Distance, class Model>
double level_search(double lo, double hi, double g_hi, const Distance& distance, const Model& model,
                    double length) {
  // g < 0 exactly when distance < length: a difference of doubles has the exact sign.
  const auto g = [&](double x) { return distance(x) - length; };
  const double width = 0.25e-12 * std::max(1.0, hi);
  Bracket b{lo, hi, 0.0, g_hi};
  bool fit_known = false;  // b.fit evaluated (else it is lo, not evaluated yet)
  const auto gm = [&](double x) { return model(x) - length; };
  Bracket m{lo, hi, gm(lo), gm(hi)};
  if (m.g_fit <= 0.0 && m.g_miss > 0.0) {
    narrow(m, gm, 0.01 * width);
    const double x = 0.5 * (m.fit + m.miss);
    const double x1 = std::max(lo, x - 0.4 * width);
    const double x2 = x + 0.4 * width;
    const double g1 = g(x1);
    if (g1 <= 0.0) {
      b.fit = x1;
      b.g_fit = g1;
      fit_known = true;
      if (x2 < hi) {
        const double g2 = g(x2);
        (g2 <= 0.0 ? b.fit : b.miss) = x2;
        (g2 <= 0.0 ? b.g_fit : b.g_miss) = g2;
      }
    } else if (x1 == lo) {
      return lo;  // nothing fits (below)
    } else {
      b.miss = x1;
      b.g_miss = g1;
    }
  }
  if (!fit_known) {
    b.g_fit = g(lo);
    // Nothing fits: every midpoint of the bisection misses, so it ends at lo.
    if (b.g_fit > 0.0) return lo;
  }
  narrow(b, g, width);
  // The bisection of the reference (profile() before the secant, same loop bounds).
  for (int iter = 0; iter < 100 && hi - lo > 1e-12 * std::max(1.0, hi); ++iter) {
    const double mid = 0.5 * (lo + hi);
    bool fits = false;
    if (mid <= b.fit) {
      fits = true;
    } else if (mid < b.miss) {
      fits = g(mid) <= 0.0;
      (fits ? b.fit : b.miss) = mid;
    }
    if (fits)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

}  // namespace

SegmentProfile profile(const PlannedSegment& planned) noexcept {
  const double length = planned.segment.path.length();
  const double cap = planned.segment.limits.v_max;
  const bool carried = planned.shape != ProfileShape::plain;
  const double a = carried ? planned.ramp_a : planned.a_max;
  const double d = carried ? planned.ramp_d : planned.d_max;
  const double j = carried ? planned.ramp_j : planned.j_max;
  const double v0 = planned.v_entry;
  const double a0 = planned.a_entry;
  const double v1 = planned.v_exit;
  SegmentProfile out;
  out.v0 = v0;
  out.a0 = a0;
  if (planned.shape == ProfileShape::brake_end) {  // the rest of a carried brake, then cruise
    const jerk::Ramp brake = jerk::velocity_ramp(planned.level, 0.0, planned.v_toward, a, d, j);
    out.first = ramp_after(brake, planned.t_cut, a0);
    out.t_first = out.first.time();
    if (planned.v_toward > 0.0)
      out.t_cruise = std::max(0.0, length - jerk::distance(v0, a0, out.first)) / planned.v_toward;
    out.second.v_end = planned.v_toward;  // no second ramp: the velocity stays
    out.v_level = v0;
    return out;
  }
  if (planned.shape == ProfileShape::brake_through) {  // a carried brake between two cuts
    const jerk::Ramp brake = jerk::velocity_ramp(planned.level, 0.0, planned.v_toward, a, d, j);
    out.first = ramp_after(brake, planned.t_cut, a0);
    out.t_first = std::clamp(planned.t_brake - planned.t_cut, 0.0, out.first.time());
    out.v_level = v0;
    return out;
  }
  if (planned.shape == ProfileShape::carry_up) {
    out.first = jerk::velocity_ramp(v0, a0, planned.v_toward, a, a, j);  // as LookAhead::pop
    out.t_first = std::clamp(planned.t_cut, 0.0, out.first.time());
    out.v_level = v1;
    return out;
  }
  if (planned.shape == ProfileShape::carry_down) {  // level, cruise, a brake cut at the end
    out.v_level = planned.level;
    out.first = jerk::velocity_ramp(v0, a0, planned.level, a, d, j);
    out.t_first = out.first.time();
    out.second = jerk::velocity_ramp(planned.level, 0.0, planned.v_brake, a, d, j);
    out.t_second = std::clamp(planned.t_brake, 0.0, out.second.time());
    const double e = jerk::state_at(planned.level, 0.0, as_state_ramp(out.second), out.t_second).p;
    const double rest = length - jerk::distance(v0, a0, out.first) - e;
    out.t_cruise = planned.level > 0.0 ? std::max(0.0, rest) / planned.level : 0.0;
    return out;
  }
  return plain_profile(length, cap, v0, a0, v1, a, d, j);
}

SegmentProfile plain_profile(double length, double cap, double v0, double a0, double v1, double a,
                             double d, double j) noexcept {
  SegmentProfile out;
  out.v0 = v0;
  out.a0 = a0;
  // Highest level in [max(v0, v1), cap] whose two ramps fit the length (monotone in level);
  // from a0 > 0 no level below the release's velocity is reached.
  const double lo = std::max(released_velocity(v0, a0, j), v1);
  const double hi = std::max(cap, lo);
  double level = hi;
  const double g_hi = ramps_distance(v0, a0, hi, v1, a, d, j) - length;
  const auto dist = [&](double x) { return ramps_distance(v0, a0, x, v1, a, d, j); };
  if (g_hi > 0.0) {
    if (a0 == 0.0)
      level = level_search(
          lo, hi, g_hi, dist, [&](double x) { return ramps_distance_model(v0, x, v1, a, d, j); },
          length);
    else  // the closed form from the virtual start at a = 0 the first ramp passes through
      level = level_search(
          lo, hi, g_hi, dist,
          [&](double x) { return carried_ramps_distance_model(v0, a0, x, v1, a, d, j); }, length);
  }
  out.v_level = level;
  out.first = jerk::velocity_ramp(v0, a0, level, a, d, j);
  out.t_first = out.first.time();
  out.second = jerk::velocity_ramp(level, 0.0, v1, a, d, j);
  out.t_second = out.second.time();
  const double rest =
      length - jerk::distance(v0, a0, out.first) - jerk::distance(level, 0.0, out.second);
  out.t_cruise = level > 0.0 ? std::max(0.0, rest) / level : 0.0;
  return out;
}

PathState profile_at(const SegmentProfile& profile, double t) noexcept {
  t = std::clamp(t, 0.0, profile.time());
  jerk::State st{0.0, profile.v0, profile.a0};
  // One ramp: phases with their jerk; boundary values snapped to the ramp's exact ones.
  auto ramp = [&](const jerk::Ramp& r, PathState& out) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (t <= r.duration[i]) {
        const jerk::State at = jerk::advance(st, r.jerk[i], t);
        out = PathState{at.p, at.v, at.a, r.jerk[i]};
        return true;
      }
      st = jerk::advance(st, r.jerk[i], r.duration[i]);
      st.a = i < 2 ? r.a_peak : 0.0;
      t -= r.duration[i];
    }
    st.v = r.v_end;
    return false;
  };
  PathState out;
  if (ramp(profile.first, out)) return out;
  if (t <= profile.t_cruise) return PathState{st.p + st.v * t, st.v, 0.0, 0.0};
  st.p += st.v * profile.t_cruise;
  t -= profile.t_cruise;
  if (ramp(profile.second, out)) return out;
  return PathState{st.p, st.v, 0.0, 0.0};
}

}  // namespace ncsim::planner
