// jerk/reverse.cpp: moves that turn round once before arriving at a velocity v1 != 0 (see
// jerk.hpp, "ptp additions").
//
// With g = sign(v1): the first part (frame -g) changes the start to the level L > 0 in the
// direction -g (through v = 0 with the path limits where the start moves the other way),
// cruises there, and the second part (frame g) takes (-L, 0) through v = 0 to (v1, 0). The
// displacement toward g without cruise is s(L); the fastest turn is at the highest level whose
// displacement still reaches the target, s(L) >= g (p1 - p0), the rest cruised at L (a cruise
// at V when s(V) is still beyond the target).
// s(L) is not monotone: where the out frame's start already moves away faster than L (L below
// u_zero = u0 + b0 |b0| / (2J), the out start's velocity once its acceleration is released), the
// out part brakes to L and the back part brakes from L, and the two nearly cancel. Above u_zero
// s falls with L (both parts speed up into the detour: every term of its slope has one sign);
// on (0, u_zero) h(L) = D - s(L) rises from L = 0 (slope (|p_out| + p_back) / (2J)) and falls
// into the kink (L / |p_out| -> infinity as the out part vanishes): one hump (seen on a
// 4000-level grid in every one of 10,864 seeded draws with u_zero > 0). So the kink splits
// (0, V] into two pieces with one root each: [u_zero, V] when the kink is feasible, else
// (0, u_zero). The root is found by steps to the root of the local quadratic model with the
// closed-form slope and curvature of s(L) where they exist (Newton where only the slope does),
// else regula falsi (jerk/root.hpp, solve_with_curve). Session 22's search bracketed (0, V] whole
// and could land on the lower interval of feasible levels (up to 40 % slower;
// jerk/reverse_test.cpp).

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/tolerance.hpp"
#include "jerk/crossing.hpp"
#include "jerk/jerk.hpp"
#include "jerk/root.hpp"
#include "jerk/trusted.hpp"

namespace ncsim::jerk {

namespace {

// Frame change (v0, a0) -> (level > = 0, 0): through v = 0 with the path limits where the
// frame start moves backward, else one ramp (under min(A+, A-) when it crosses v = 0).
// `v_zero`: the start's release velocity v0 + a0 |a0| / (2J) (the callers have it: no division
// per level, issue 36). `cs`: the start's part of the crossing prepared once
// (jerk/crossing.hpp), else nullptr. Returns the distance the change covers in its frame [mm].
double ramp_to(double v0, double a0, double v_zero, double level, const Limits& lim,
               Crossing& cross, Ramp& ramp, const detail::CrossingStart* cs = nullptr) noexcept {
  cross = Crossing{};
  if ((v0 < 0.0 || a0 < 0.0) && level > 0.0) {
    double d_cross = 0.0;
    bool crossed = false;
    if (cs != nullptr) {
      crossed = detail::crossing_from(*cs, level, lim, cross, ramp, &d_cross);
    } else {
      detail::CrossingStart own;
      detail::crossing_start_into(own, v0, a0, v_zero, lim, false);
      crossed = detail::crossing_from(own, level, lim, cross, ramp, &d_cross);
    }
    if (crossed) return d_cross + distance(0.0, cross.a_zero, ramp);
  }
  cross = Crossing{};
  const double a_up =
      v0 < 0.0 ? (level > 0.0 ? std::min(lim.a_max, lim.d_max) : lim.d_max) : lim.a_max;
  ramp = detail::velocity_ramp_released(v0, a0, v_zero, level, a_up, lim.d_max, lim.j_max);
  return distance(v0, a0, ramp);
}

// The turn at `level` without cruise, into `r` (every member written: the searches evaluate
// many levels into one Reversal, not a new one built and copied each time); `reach` receives
// its displacement toward g [mm]: the back part's distance in its frame (g) less the out
// part's in its frame (-g), each the sum of its pieces' closed-form or per-phase distances
// (not the end state integrated through both).
// `cs_out`: crossing_start of the out part's start (-g v0, -g a0), prepared once per search.
void make_into(Reversal& r, const State& start, double g, double level, double v1,
               const Limits& lim, double& reach,
               const detail::CrossingStart* cs_out = nullptr) noexcept {
  r.out.sign = -g;
  r.out.t_cruise = 0.0;
  r.back.t_cruise = 0.0;
  const double u0 = -g * start.v;
  const double b0 = -g * start.a;
  const double u_zero =
      cs_out != nullptr ? cs_out->v_zero : u0 + b0 * std::abs(b0) / (2.0 * lim.j_max);
  const double d_out = ramp_to(u0, b0, u_zero, level, lim, r.out.cross, r.out.first, cs_out);
  r.out.v_level = level;
  r.out.second = Ramp{};
  r.out.second.v_end = level;
  r.back.sign = g;
  // The back part starts at (-level, 0): its release velocity -level + 0 |0| / (2J) is
  // -level + 0.0 to the bit.
  const double d_back = ramp_to(-level, 0.0, -level + 0.0, g * v1, lim, r.back.cross, r.back.first);
  r.back.v_level = g * v1;
  r.back.second = Ramp{};
  r.back.second.v_end = g * v1;
  reach = d_back - d_out;
}

// The slope and curvature of h(L) = D - s(L) [s] and [s^2/mm] (NaN where unknown). A
// piece from a fixed start ending at velocity vm with signed peak a_p covers a distance whose
// derivative in vm is T(a_p) = vm / a_p + |a_p| / (2J) (jerk/move.cpp, level_slope): the out
// part ends at L; the back part read backward in time ends at -L with the peak of its piece
// from -L (its crossing, else its one ramp). So h' = T(p_out) + T(p_back). Crossings are fixed
// unless their a_zero is sqrt(2 J L) (then they move with L: NaN). The curvature by the same
// rule as level_slope: a peak holding at its limit stays, one without a hold has
// p^2 = J |L - v_other| + const (dp/dL = J / (2|p|)), so dT/dL = 1/p + p' (sgn(p)/(2J) - L/p^2).
void reach_slope(const Reversal& r, double level, double j, double& slope, double& curve) noexcept {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  slope = curve = nan;
  const double a_level = (1.0 - kRelTol) * std::sqrt(2.0 * j * level);
  const double p_out = r.out.first.a_peak;
  if (p_out == 0.0 || (r.out.cross.time() > 0.0 && !(r.out.cross.a_zero < a_level))) return;
  double p_back = std::abs(r.back.first.a_peak);
  bool hold_back = r.back.first.duration[1] > 0.0;
  if (r.back.cross.time() > 0.0) {
    if (!(r.back.cross.a_zero < a_level)) return;
    p_back = r.back.cross.a_peak;
    hold_back = r.back.cross.duration[1] > 0.0;
  }
  if (!(p_back > 0.0)) return;
  const double a_out = std::abs(p_out);
  slope = level / p_out + a_out / (2.0 * j) + level / p_back + p_back / (2.0 * j);
  const double half = 0.5 / j;  // (-0.5) / j is -half to the bit: one division for both parts
  const auto curve_of = [&](double p, double ap, bool hold) {
    const double dp = hold ? 0.0 : j / (2.0 * ap);
    return 1.0 / p + dp * ((p > 0.0 ? half : -half) - level / (p * p));
  };
  curve =
      curve_of(p_out, a_out, r.out.first.duration[1] > 0.0) + curve_of(p_back, p_back, hold_back);
}

}  // namespace

Status reversal_move(const State& start, double p1, double v1, const Limits& lim,
                     Reversal& out) noexcept {
  if (!valid(lim) || !std::isfinite(start.p) || !std::isfinite(start.v) ||
      !std::isfinite(start.a) || !std::isfinite(p1) || !std::isfinite(v1) ||
      std::abs(v1) > lim.v_max) {
    return Status::invalid_input;
  }
  return detail::reversal_move_trusted(start, p1, v1, lim, out);
}

Status detail::reversal_move_trusted(const State& start, double p1, double v1, const Limits& lim,
                                     Reversal& out) noexcept {
  if (v1 == 0.0) return Status::not_supported;
  const double g = v1 > 0.0 ? 1.0 : -1.0;
  const double d = g * (p1 - start.p);
  // No detour needed, decided before any level is evaluated (issue 11, session 26): where the
  // out frame's start neither moves backward nor reverses (u0 >= 0, u_zero >= 0) the out part
  // keeps v >= 0 at every level (no crossing), so it covers >= 0; the back part's motion toward
  // g starts at v = 0 with a >= 0 and ends at (|v1|, 0) under A+, so its acceleration at each
  // velocity is at least the ramp 0 -> |v1|'s (the time-optimal ramp is the envelope) and it
  // covers at most ramp_distance(|v1|, A+). So h(L) >= d - ramp_distance(|v1|, A+) at every
  // level: with that above a rounding margin no level is feasible, and the search below would
  // find h > 0 at V, at the kink and at 0 (3 evaluations in 230 of the bench's 776 turns).
  const double u0 = -g * start.v;
  const double b0 = -g * start.a;
  const double u_zero = u0 + b0 * std::abs(b0) / (2.0 * lim.j_max);
  if (u0 >= 0.0 && u_zero >= 0.0) {
    const double up = ramp_distance(std::abs(v1), lim.a_max, lim.j_max);
    if (d - up > kRelTol * (std::abs(d) + up)) return Status::not_supported;
  }
  // h(L) = d - s(L); feasible (the turn still reaches the target) is h <= 0.
  // The turn and h of the last level evaluated are kept: the solver usually returns it. The
  // levels are evaluated into `out` itself (make_into writes every member), not into a local
  // Reversal zeroed and copied at the end (issue 11, session 28: 16 instructions per plan); where
  // no turn is found `out` holds the last level evaluated.
  Reversal& r = out;
  double last = -1.0;
  double h_last = 0.0;
  const detail::CrossingStart cs_out =
      detail::crossing_start(-g * start.v, -g * start.a, lim, true);
  const auto h = [&](double level, double& slope, double& curve) {
    double reach = 0.0;
    make_into(r, start, g, level, v1, lim, reach, &cs_out);
    last = level;
    reach_slope(r, level, lim.j_max, slope, curve);
    h_last = d - reach;
    return h_last;
  };
  // One sample of h: the level, h there and its slope and curvature (NaN where unknown).
  struct Sample {
    double level = 0.0;  // [mm/s]
    double h = 0.0;      // [mm]
    double slope = 0.0;  // [s]
    double curve = 0.0;  // [s^2/mm]
  };
  const auto sample = [&](double level) {
    Sample s{level, 0.0, 0.0, 0.0};
    s.h = h(level, s.slope, s.curve);
    return s;
  };
  const Sample top = sample(lim.v_max);
  double level = lim.v_max;
  if (top.h > 0.0) {
    // The bracket of the highest feasible level: h rises on [max(u_zero, 0), V] and has one
    // hump on (0, u_zero) (the file's note), so the piece above a feasible kink, else the
    // piece below it. `hi` is infeasible (h > 0); `lo`, once known, feasible (h <= 0).
    Sample hi = top;
    Sample lo;
    bool lo_known = false;
    bool step_in_tol = false;  // the step from V landed on the root (within tolerance)
    const double tol = kResidue * std::abs(d);
    if (u_zero > 0.0 && u_zero < lim.v_max) {
      // The root step from V before the kink (issue 11, session 26, as top_level's in
      // jerk/move.cpp): the kink has no slope, so the solver's first step in [u_zero, V] is this
      // step from V alone. Where it lands in (u_zero, V), on which h rises, a level in tolerance
      // is that piece's root, the highest feasible level, and the kink is not evaluated; a
      // feasible one bounds the root from below (and shows the kink feasible: h(u_zero) < h(x));
      // an infeasible one becomes the top of the bracket.
      if (top.slope > 0.0) {
        const double x = detail::curve_step(top.level, top.h, top.slope, top.curve, tol);
        if (x > u_zero && x < top.level) {
          const Sample step = sample(x);
          lo_known = step.h <= 0.0;
          step_in_tol = lo_known && step.h >= -tol;
          (lo_known ? lo : hi) = step;
        }
      }
      if (!lo_known) {
        const Sample kink = sample(u_zero);
        lo_known = kink.h <= 0.0;
        (lo_known ? lo : hi) = kink;
      }
    }
    if (!lo_known) {
      lo = sample(0.0);
      if (!(lo.h < 0.0)) return Status::not_supported;  // no detour needed (or none helps)
    }
    level = step_in_tol ? lo.level
                        : detail::solve_with_curve(lo.level, hi.level, lo.h, hi.h, lo.slope,
                                                   hi.slope, lo.curve, hi.curve, tol, h);
    if (!(level > 0.0)) return Status::not_supported;
    if (last != level) sample(level);
  }
  const double h_level = h_last;
  const double rest = -h_level;  // >= 0: covered by cruising backward at the level
  out.out.t_cruise = rest > kResidue * std::abs(d) ? rest / level : 0.0;
  return Status::ok;
}

}  // namespace ncsim::jerk

namespace ncsim::jerk {

namespace {

// The level search of reversal_of_duration: T(L) - duration of the reversal cruising back at
// level L, whether L is feasible (the ramps do not overshoot the way), and the reversal built
// at the last level evaluated.
class DurationSearch {
 public:
  DurationSearch(const State& start, double p1, double v1, double duration, const Limits& lim)
      : start_(start),
        v1_(v1),
        duration_(duration),
        lim_(lim),
        g_(v1 > 0.0 ? 1.0 : -1.0),
        d_(g_ * (p1 - start.p)),
        tol_rest_(kResidue * std::abs(d_)) {}

  /// T(level) - duration; infeasible levels count on the fast side (-duration).
  double operator()(double level, double& slope) noexcept {
    double reach = 0.0;
    make_into(r_, start_, g_, level, v1_, lim_, reach);
    slope = std::numeric_limits<double>::quiet_NaN();
    const double rest = reach - d_;
    feasible_ = !(rest < -tol_rest_);
    if (!feasible_) return -duration_;
    r_.out.t_cruise = rest > tol_rest_ ? rest / level : 0.0;
    return r_.time() - duration_;
  }
  double at(double level) noexcept {
    double slope = 0.0;
    return (*this)(level, slope);
  }
  bool feasible() const noexcept { return feasible_; }
  const Reversal& reversal() const noexcept { return r_; }

  /// The feasible end of the boundary between a feasible level `ok` and an infeasible `bad`.
  double boundary(double ok, double bad) noexcept {
    for (int i = 0; i < 200 && std::abs(ok - bad) > kMachineEpsilon * std::max(ok, bad); ++i) {
      const double mid = 0.5 * (ok + bad);
      at(mid);
      (feasible_ ? ok : bad) = mid;
    }
    return ok;
  }

  /// A root of T(L) = duration between a feasible level `fast` (T <= duration) and a feasible
  /// `slow` (T > duration), checked: false when it lands in a hole (`hole` receives it).
  bool solve(double fast, double t_fast, double slow, double t_slow, double& hole) noexcept {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // solve_with_slope wants g rising from x_neg to x_pos in value only (either order).
    const double level =
        detail::solve_with_slope(fast, slow, t_fast, t_slow, nan, nan, kResidue * duration_,
                                 [this](double x, double& slope) { return (*this)(x, slope); });
    const double t = at(level);
    hole = level;
    return feasible_ && std::abs(t) <= kRelRounding * duration_;
  }

  /// Halves `l_low` (a level, T at it in t_low) until T(l_low) > duration or the level reaches
  /// 0; with `fast` the last level still fast enough goes to l_hi / t_hi. Stops early at an
  /// infeasible level (a hole) when `stop_at_hole`: returns it, else -1.
  double halve(double& l_hi, double& t_hi, double& l_low, double& t_low,
               bool stop_at_hole) noexcept {
    for (int i = 0; i < 200; ++i) {
      l_low *= 0.5;
      t_low = at(l_low);
      if (stop_at_hole && !feasible_) return l_low;
      if (t_low > 0.0 || !(l_low > 0.0)) break;
      if (stop_at_hole) {
        l_hi = l_low;
        t_hi = t_low;
      }
    }
    return -1.0;
  }

 private:
  State start_;
  double v1_;
  double duration_;
  Limits lim_;
  double g_;         ///< the frame: the sign of the arrival velocity
  double d_;         ///< the way to the target in that frame [mm]
  double tol_rest_;  ///< a cruise shorter than this is rounding [mm]
  Reversal r_;
  bool feasible_ = false;  ///< of the last level evaluated
};

// The root within the lower interval (0, l_a] below a hole at `hole`, from a feasible 0
// (`low_known` false: not seen yet) or from a known too slow level l_low (true).
Status solve_below_hole(DurationSearch& search, double hole, bool low_known, double l_low,
                        double t_low, Reversal& out) noexcept {
  double l_hi = 0.0;
  double t_hi = 0.0;
  if (!low_known) {  // from a feasible 0, halved until too slow
    search.at(0.0);
    if (!search.feasible()) return Status::not_supported;
    const double l_a = search.boundary(0.0, hole);
    l_hi = l_a;
    t_hi = search.at(l_a);
    if (t_hi > 0.0) return Status::not_supported;  // the duration lies in the gap
    l_low = l_a;
    double unused_l = 0.0;
    double unused_t = 0.0;
    search.halve(unused_l, unused_t, l_low, t_low, false);
    if (!(t_low > 0.0)) return Status::not_supported;
  } else {
    const double l_a = search.boundary(l_low, hole);
    l_hi = l_a;
    t_hi = search.at(l_a);
    if (t_hi > 0.0) return Status::not_supported;  // the duration lies in the gap
  }
  double miss = 0.0;
  if (!search.solve(l_hi, t_hi, l_low, t_low, miss)) return Status::not_supported;
  out = search.reversal();
  return Status::ok;
}

}  // namespace

Status reversal_of_duration(const State& start, double p1, double v1, double duration,
                            const Limits& lim, Reversal& out) noexcept {
  if (!std::isfinite(duration) || duration < 0.0) return Status::invalid_input;
  Reversal fastest;
  const Status st = reversal_move(start, p1, v1, lim, fastest);
  if (st != Status::ok) return st;
  const double t_min = fastest.time();
  if (duration <= t_min) {
    if (duration < t_min * (1.0 - kRelRounding)) return Status::too_short;
    out = fastest;
    return Status::ok;
  }
  // The rest of the way is cruised backward at L, so T(L) = ramps(L) + rest(L) / L on the
  // feasible levels (rest >= 0), T(L_top) = t_min, unbounded as L -> 0 where the stop-and-go
  // alone overshoots the target (rest(0) > 0). The feasible levels below L_top are one interval
  // [L_b, L_top] down to the hump of h below the kink (reversal_move), and (0, L_a] below the
  // hump when the hump rises above 0 (a hole (L_a, L_b)); T is continuous on each. The level
  // is halved from L_top until it is too slow (a root of T(L) = duration lies between) or falls
  // into the hole; a root that lands in the hole shows one as well. With a hole: within
  // [L_b, L_top] when T(L_b) >= duration, else within (0, L_a] when T(L_a) <= duration, else
  // a gap (not_supported).
  DurationSearch search(start, p1, v1, duration, lim);
  double l_hi = fastest.out.v_level;  // the lowest feasible level seen that is fast enough
  double t_hi = t_min - duration;
  double l_low = l_hi;
  double t_low = 0.0;
  double hole = search.halve(l_hi, t_hi, l_low, t_low, true);
  bool low_known = false;  // l_low: a feasible level below the hole, too slow
  if (hole < 0.0) {
    if (!(t_low > 0.0)) return Status::not_supported;  // stop-and-go fills the way: no slower
    if (search.solve(l_hi, t_hi, l_low, t_low, hole)) {
      out = search.reversal();
      return Status::ok;
    }
    low_known = true;
  }
  // A hole (l_a, l_b) between l_hi and l_low.
  const double l_b = search.boundary(l_hi, hole);
  const double t_b = search.at(l_b);
  if (t_b > 0.0) {
    double miss = 0.0;
    if (!search.solve(l_hi, t_hi, l_b, t_b, miss)) return Status::not_supported;
    out = search.reversal();
    return Status::ok;
  }
  return solve_below_hole(search, hole, low_known, l_low, t_low, out);
}

}  // namespace ncsim::jerk
