// planner/lookahead: window, backward and forward passes, segment profiles (see the header).

#include "planner/lookahead.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace ncsim::planner {

namespace {

/// Distance of the two ramps v_entry -> level -> v_exit.
double ramps_distance(double v_entry, double level, double v_exit, double a, double d, double j) {
  const jerk::Ramp up = jerk::velocity_ramp(v_entry, 0.0, level, a, d, j);
  const jerk::Ramp down = jerk::velocity_ramp(level, 0.0, v_exit, a, d, j);
  return jerk::distance(v_entry, 0.0, up) + jerk::distance(level, 0.0, down);
}

/// Duration of a ramp between two velocities dv >= 0 apart with a = 0 at both ends (the
/// kernel's velocity_ramp from a0 = 0): jerk phases alone up to dv = a^2 / j (peak acceleration
/// sqrt(dv j)), else with a hold at a.
double ramp_time(double dv, double a, double j) {
  return dv * j <= a * a ? 2.0 * std::sqrt(dv / j) : dv / a + a / j;
}

/// ramps_distance() in closed form: a ramp with a = 0 at both ends is symmetric, so it covers
/// its mean velocity times its duration. Equal to ramps_distance() up to rounding (and the
/// kernel's snapping of rounding residues); used only to guess where the level lies.
double ramps_distance_model(double v_entry, double level, double v_exit, double a, double d,
                            double j) {
  return 0.5 * (v_entry + level) * ramp_time(level - v_entry, a, j) +
         0.5 * (level + v_exit) * ramp_time(level - v_exit, d, j);
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

std::size_t window_size(LookAheadKind kind, std::optional<std::size_t> custom,
                        std::size_t custom_max) {
  switch (kind) {
    case LookAheadKind::low:
      return 30;
    case LookAheadKind::standard:
      return 120;
    case LookAheadKind::high:
      return 190;
    case LookAheadKind::custom:
      break;
  }
  if (!custom || *custom < 10 || *custom > custom_max)
    throw std::invalid_argument("P-CHAN-00650 FCT_LOOK_AHEAD_CUSTOM: window " +
                                (custom ? std::to_string(*custom) : std::string("(none)")) +
                                " outside [10, " + std::to_string(custom_max) + "] (P-CHAN-00653)");
  return *custom;
}

jerk::Move profile(const PlannedSegment& planned) noexcept {
  const double length = planned.segment.path.length();
  const double cap = planned.segment.limits.v_max;
  const double a = planned.a_max;
  const double d = planned.d_max;
  const double j = planned.j_max;
  const double v0 = planned.v_entry;
  const double v1 = planned.v_exit;
  // Highest level in [max(v0, v1), cap] whose two ramps fit the length (monotone in level).
  const double lo = std::max(v0, v1);
  const double hi = std::max(cap, lo);
  double level = hi;
  const double g_hi = ramps_distance(v0, hi, v1, a, d, j) - length;
  if (g_hi > 0.0)
    level = level_search(
        lo, hi, g_hi, [&](double x) { return ramps_distance(v0, x, v1, a, d, j); },
        [&](double x) { return ramps_distance_model(v0, x, v1, a, d, j); }, length);
  jerk::Move move;
  move.sign = 1.0;
  move.v_level = level;
  move.first = jerk::velocity_ramp(v0, 0.0, level, a, d, j);
  move.second = jerk::velocity_ramp(level, 0.0, v1, a, d, j);
  const double rest =
      length - jerk::distance(v0, 0.0, move.first) - jerk::distance(level, 0.0, move.second);
  move.t_cruise = level > 0.0 ? std::max(0.0, rest) / level : 0.0;
  return move;
}

PathState profile_at(const jerk::Move& move, double v_entry, double t) noexcept {
  t = std::clamp(t, 0.0, move.time());
  jerk::State st{0.0, v_entry, 0.0};
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
  if (ramp(move.first, out)) return out;
  if (t <= move.t_cruise) return PathState{st.p + st.v * t, st.v, 0.0, 0.0};
  st.p += st.v * move.t_cruise;
  t -= move.t_cruise;
  if (ramp(move.second, out)) return out;
  return PathState{st.p, st.v, 0.0, 0.0};
}

LookAhead::LookAhead(std::size_t capacity, double t_cycle) : t_cycle_(t_cycle) {
  if (capacity < 1)
    throw std::invalid_argument("planner: look-ahead window of " + std::to_string(capacity) +
                                " segments (P-CHAN-00650)");
  if (!(t_cycle > 0.0) || !std::isfinite(t_cycle))
    throw std::invalid_argument("planner: interpolation cycle must be > 0, got " +
                                std::to_string(t_cycle));
  slots_.resize(capacity);
}

void LookAhead::push(PreparedSegment segment) {
  if (full()) throw std::logic_error("planner: push into a full look-ahead window");
  Slot& slot = at(count_);
  const PathLimits& lim = segment.limits;
  slot.length = segment.path.length();
  slot.cap = lim.v_max;
  slot.joint_cap = std::min(segment.v_end, lim.v_max);
  slot.a = lim.a_max;
  slot.d = lim.d_max;
  slot.j = std::isfinite(lim.j_max) ? lim.j_max : std::max(lim.a_max, lim.d_max) / t_cycle_;
  slot.segment = std::move(segment);
  ++count_;
  backward_from_end();
}

void LookAhead::backward_from_end() {
  // The new last segment ends at the window end: a possible stop.
  std::size_t k = count_ - 1;
  Slot* s = &at(k);
  s->exit_cap = 0.0;
  s->entry_cap = std::min(s->cap, jerk::entry_velocity_for_exit(0.0, s->length, s->d, s->j));
  while (k > 0) {
    const double entry_next = s->entry_cap;
    --k;
    s = &at(k);
    const double exit = std::min(s->joint_cap, entry_next);
    if (exit <= s->exit_cap) break;  // caps only grow; an unchanged one ends the pass
    s->exit_cap = exit;
    // An exit at the cap leaves the entry at the cap: a speed-up from v never ends below v
    // (jerk::reachable_velocity adds a term >= 0 to it), so the kernel is not asked.
    s->entry_cap =
        exit >= s->cap
            ? s->cap
            : std::min(s->cap, jerk::entry_velocity_for_exit(exit, s->length, s->d, s->j));
  }
}

double LookAhead::feasible_exit(double v_entry, double v_upper, const Slot& s) const noexcept {
  // Speeding up (or cruising) to v_upper <= reach always fits.
  if (v_upper >= v_entry) return v_upper;
  auto fits = [&](double v_exit) {
    const jerk::Ramp down = jerk::velocity_ramp(v_entry, 0.0, v_exit, s.a, s.d, s.j);
    // The kernel's inverse functions agree with its ramps to rounding, not exactly.
    return jerk::distance(v_entry, 0.0, down) <= s.length * (1.0 + 1e-12) + 1e-15;
  };
  if (fits(v_upper)) return v_upper;
  // The entry cap of this segment shrank after its entry was committed (the distance of a
  // jerk-limited slow-down with a = 0 at both ends is not monotone in the exit velocity:
  // docs/planner.md "Look-ahead"). Slowing further fits: the slow-downs that fit are [0, v_lo].
  double lo = 0.0;
  double hi = v_upper;
  for (int iter = 0; iter < 60; ++iter) {
    const double mid = 0.5 * (lo + hi);
    if (fits(mid))
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

double LookAhead::start_at(double v) noexcept {  // --- sync-feed
  v_committed_ = std::clamp(v, 0.0, front_entry_cap());
  return v_committed_;
}

PlannedSegment LookAhead::pop() {
  if (empty()) throw std::logic_error("planner: pop from an empty look-ahead window");
  Slot& s = at(0);
  PlannedSegment out;
  out.v_entry = v_committed_;
  const double reach = jerk::reachable_velocity(v_committed_, 0.0, s.length, s.a, s.j);
  out.v_exit = feasible_exit(v_committed_, std::min({s.exit_cap, reach, s.cap}), s);
  out.a_max = s.a;
  out.d_max = s.d;
  out.j_max = s.j;
  out.segment = std::move(s.segment);
  v_committed_ = out.v_exit;
  head_ = (head_ + 1) % slots_.size();
  --count_;
  return out;
}

}  // namespace ncsim::planner
