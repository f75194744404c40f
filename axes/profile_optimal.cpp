// axes/profile_optimal.cpp: profiles where the manual prescribes nothing (docs/axes-profile.md,
// "Profile rule", "Synchronised and moving targets"):
//  - ProfileRule::time_optimal: the fastest single-peak profile (jerk::fastest_move);
//  - a prescribed duration: the single-peak profile with a lowered level (jerk::move_of_duration),
//    a turn with a lowered level, the stretched two-peak change, else a rest on the way;
//  - time-synchronised axes: every axis gets the longest single-axis duration;
//  - a target moving with constant velocity: the earliest meeting time, found by growing the
//    time geometrically until the single-peak family can meet p1 + v1 T in time, then
//    bisecting between the last time it could not and the first it could.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "axes/profile.hpp"
#include "axes/profile_builder.hpp"
#include "axes/profile_classify.hpp"
#include "core/tolerance.hpp"
#include "jerk/trusted.hpp"

namespace ncsim::axes {

namespace detail {

void append_move(ProfileBuilder& b, const jerk::Move& m) noexcept {
  b.set_level(m.v_level);
  b.add(m.cross, m.sign);
  b.add(m.first, m.sign);
  b.add(0.0, m.t_cruise);
  b.mark_brake();
  b.add(m.second, m.sign);
}

namespace {

void append_two_peak(ProfileBuilder& b, const jerk::TwoPeak& tp) noexcept {
  b.set_level(std::abs(tp.v_end));
  for (std::size_t i = 0; i < 4; ++i) {
    if (i == 1) b.mark_brake();
    b.add(tp.sign * tp.jerk[i], tp.duration[i], tp.sign * tp.a_end[i]);
  }
}

void append_dip_crossing(ProfileBuilder& b, const jerk::DipCrossing& dc) noexcept {
  b.set_level(std::abs(dc.rest.v_end));
  b.add(dc.sign * dc.jerk, dc.dip, dc.sign * dc.a_dip);
  b.mark_brake();  // as the two-peak change: the change after the dip
  b.add(dc.cross, dc.sign);
  b.add(dc.rest, dc.sign);
  b.add(0.0, dc.t_cruise);
}

// Level of the fastest rest-to-rest move under the real A+ and A-: the highest vm <= V with
// d(vm) = ramp(vm, A+) + ramp(vm, A-) <= D, split by which limits the ramps reach:
//  - neither (vm J <= min(A)^2):   D = 2 vm^1.5 / sqrt(J)          -> vm = cbrt(D^2 J / 4);
//  - both (vm J >= max(A)^2):      D = k vm^2 + m vm, k = (1/A+ + 1/A-)/2, m = (A+ + A-)/(2J);
//  - only the smaller A = a_s:     D = vm^2/(2 a_s) + vm a_s/(2J) + vm^1.5/sqrt(J), in u = sqrt(vm)
//    a convex increasing quartic: Newton from an upper bound descends onto the root.
double level_neither(double d, double j) noexcept {
  return std::cbrt(0.25 * d * d * j);
}

double level_both(double d, const Dynamics& dyn) noexcept {
  const double k = 0.5 * (1.0 / dyn.a_max + 1.0 / dyn.d_max);
  const double m = 0.5 * (dyn.a_max + dyn.d_max) / dyn.j_max;
  return 2.0 * d / (m + std::sqrt(m * m + 4.0 * k * d));
}

double level_smaller(double d, double a_s, double j, double u_hi) noexcept {
  const double c4 = 0.5 / a_s;
  const double c3 = 1.0 / std::sqrt(j);
  const double c2 = 0.5 * a_s / j;
  double u = u_hi;
  for (int i = 0; i < 100; ++i) {
    const double u2 = u * u;
    const double f = u2 * (u2 * c4 + u * c3 + c2) - d;
    if (!(f > 0.0)) break;
    const double slope = u * (4.0 * c4 * u2 + 3.0 * c3 * u + 2.0 * c2);
    const double next = u - f / slope;
    if (!(next < u)) break;
    u = next;
  }
  return u * u;
}

// The level where V is not reached (both_ramps(V) > d).
double rest_to_rest_level_below(double d, const Dynamics& dyn) noexcept {
  const double j = dyn.j_max;
  const auto both_ramps = [&](double v) {
    return ramp_distance(v, dyn.a_max, j) + ramp_distance(v, dyn.d_max, j);
  };
  const double a_s = std::min(dyn.a_max, dyn.d_max);
  const double a_l = std::max(dyn.a_max, dyn.d_max);
  const double v_s = a_s * a_s / j;  // level at which the smaller limit is just reached
  const double v_l = a_l * a_l / j;
  if (d <= both_ramps(v_s)) return level_neither(d, j);
  if (d >= both_ramps(v_l)) return level_both(d, dyn);
  return level_smaller(d, a_s, j, std::sqrt(v_l));
}

double rest_to_rest_level(double d, const Dynamics& dyn) noexcept {
  const double j = dyn.j_max;
  if (ramp_distance(dyn.v_max, dyn.a_max, j) + ramp_distance(dyn.v_max, dyn.d_max, j) <= d)
    return dyn.v_max;
  return rest_to_rest_level_below(d, dyn);
}

// A rest ramp to v under a_lim, j: ramp_distance and rest_ramp_time (the same expressions, their
// common square root or quotient sum evaluated once).
struct RestRamp {
  double dist = 0.0;  // [mm]
  double time = 0.0;  // [s]
};

RestRamp rest_ramp(double v, double a_lim, double j) noexcept {
  if (v * j <= a_lim * a_lim) {
    const double r = std::sqrt(v / j);
    return RestRamp{v * r, 2.0 * r};
  }
  const double s = v / a_lim + a_lim / j;
  return RestRamp{0.5 * v * s, s};
}

// Case rest to rest: closed form by limits reached (no iteration over ramps).
void append_rest_to_rest_fastest(ProfileBuilder& b, double p_target, const Dynamics& dyn) noexcept {
  const double d = p_target - b.state().p;
  if (d == 0.0) return;
  const double s = d > 0.0 ? 1.0 : -1.0;
  const double dist = std::abs(d);
  const double vm = std::min(dyn.v_max, rest_to_rest_level(dist, dyn));
  const double j = dyn.j_max;
  const double d_cruise = dist - ramp_distance(vm, dyn.a_max, j) - ramp_distance(vm, dyn.d_max, j);
  const double t_cruise = d_cruise > kResidue * dist ? d_cruise / vm : 0.0;
  b.set_level(vm);
  b.add(velocity_ramp(0.0, 0.0, vm, dyn.a_max, dyn.d_max, j), s);
  b.add(0.0, t_cruise);
  b.mark_brake();
  b.add(velocity_ramp(vm, 0.0, 0.0, dyn.a_max, dyn.d_max, j), s);
}

}  // namespace

double rest_to_rest_fastest_time(double dist, const Dynamics& dyn) noexcept {
  // The durations append_rest_to_rest_fastest plans (without a profile).
  if (!(dist > 0.0)) return 0.0;
  const double j = dyn.j_max;
  // The ramps' times in closed form, without building them (issue 11, session 25: the
  // stop-then-go bound, half the plans); where V is reached, the ramps of the level's first
  // test are the plan's (issue 36: two square roots or four divisions fewer).
  double vm = dyn.v_max;
  RestRamp up = rest_ramp(vm, dyn.a_max, j);
  RestRamp down = rest_ramp(vm, dyn.d_max, j);
  if (!(up.dist + down.dist <= dist)) {
    vm = std::min(dyn.v_max, rest_to_rest_level_below(dist, dyn));
    up = rest_ramp(vm, dyn.a_max, j);
    down = rest_ramp(vm, dyn.d_max, j);
  }
  const double d_cruise = dist - up.dist - down.dist;
  const double t_cruise = d_cruise > 0.0 ? d_cruise / vm : 0.0;
  return up.time + t_cruise + down.time;
}

bool plan_fastest(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                  Profile& out, bool& direct, StopPoint& stop) noexcept {
  direct = false;
  const MotionState end{target.p, target.v, 0.0};
  if (start.v == 0.0 && start.a == 0.0 && target.v == 0.0) {
    ProfileBuilder b(out, start);
    append_rest_to_rest_fastest(b, target.p, dyn);
    b.finish(&end);
    direct = true;
    return true;
  }
  // (The inputs are plan_position's, checked there: the kernel's searches without their own
  // check, jerk/trusted.hpp.)
  // The candidates are compared by their phase times; a candidate is built when it is the
  // fastest so far (the two-peak change and the turn are rarely both faster than the single
  // peak), and each candidate's object is made only where it is evaluated: a Reversal is zeroed
  // in 60 instructions, more than its test costs in most plans (issue 11, session 25).
  // Candidate 1: one single-peak move (reversing without a stop where the target lies behind).
  double t_best = std::numeric_limits<double>::infinity();
  bool found = false;
  {
    jerk::Move m;
    if (jerk::detail::fastest_move_trusted(start, target.p, target.v, dyn, m) == jerk::Status::ok) {
      found = true;
      t_best = m.time();
      ProfileBuilder b(out, start);
      append_move(b, m);
      b.finish(&end);
      // Toward the target without moving away: a stop first cannot be faster.
      direct = m.sign * start.v >= 0.0 && m.sign * (target.p - start.p) >= 0.0;
    }
  }
  // Candidate 2: the two-peak change (the acceleration dips toward 0 without reaching it),
  // for targets between the direct ramp and releasing the start acceleration first.
  // (Skipped where its shape does not apply, then where its lower bound shows it cannot be
  // faster: profile_classify.)
  if (jerk::detail::two_peak_applies(start, target.p, target.v, dyn) &&
      two_peak_bound(start, target, dyn, t_best) < t_best) {
    jerk::TwoPeak tp;
    if (jerk::detail::two_peak_move_trusted(start, target.p, target.v, dyn, tp) ==
            jerk::Status::ok &&
        tp.time() < t_best) {
      found = true;
      t_best = tp.time();
      ProfileBuilder b(out, start);
      append_two_peak(b, tp);
      b.finish(&end);
    }
  }
  // Candidate 3: turn round once on the way to an arrival velocity (the target too close to
  // arrive at v1 without a detour, or v1 against the direction of travel).
  if (!direct && target.v != 0.0) {
    jerk::Reversal rev;
    if (jerk::detail::reversal_move_trusted(start, target.p, target.v, dyn, rev) ==
            jerk::Status::ok &&
        rev.time() < t_best) {
      found = true;
      t_best = rev.time();
      ProfileBuilder b(out, start);
      append_move(b, rev.out);
      append_move(b, rev.back);
      b.finish(&end);
    }
  }
  // Candidate 3b: brake through v = 0 with a free peak (ease the braking to a dip, then the
  // crossing): a braking start moving against the arrival velocity, straight to it (issue 11,
  // session 31; jerk/dip_cross.cpp). Skipped where its shape does not apply (no member
  // evaluated) and where its fastest member is not faster than the best found.
  if (target.v != 0.0 && jerk::detail::dip_crossing_applies(start, target.v, dyn)) {
    jerk::DipCrossing dc;
    if (jerk::detail::dip_crossing_move_trusted(start, target.p, target.v, dyn, t_best, dc) ==
            jerk::Status::ok &&
        dc.time() < t_best) {
      found = true;
      t_best = dc.time();
      ProfileBuilder b(out, start);
      append_dip_crossing(b, dc);
      b.finish(&end);
    }
  }
  // Candidate 4 (starts moving away): stop with A-, then the fastest move from rest; a
  // reversing ramp can only use min(A+, A-) across v = 0, so the stop can be faster.
  if (direct || (start.v == 0.0 && start.a == 0.0)) return found;
  // Skipped where its lower bound shows it cannot be faster (profile_classify);
  // infinite where its go part cannot reach an arrival velocity (issue 11, session 26).
  const double t_found = found ? out.duration() : std::numeric_limits<double>::infinity();
  if (stop_then_go_bound(start, target, dyn, &stop) >= t_found) return found;
  Profile alt;
  ProfileBuilder b(alt, start);
  append_stop(b, dyn);
  if (target.v == 0.0) {
    // From rest to rest the fastest move is the closed form (no level search).
    append_rest_to_rest_fastest(b, target.p, dyn);
  } else {
    const MotionState rest{b.state().p, 0.0, 0.0};
    jerk::Move m;
    if (jerk::detail::fastest_move_trusted(rest, target.p, target.v, dyn, m) != jerk::Status::ok)
      return found;
    append_move(b, m);
  }
  b.finish(&end);
  if (!found || alt.duration() < out.duration()) out = alt;
  return true;
}

}  // namespace detail

namespace {

bool finite(const MotionState& s) noexcept {
  return std::isfinite(s.p) && std::isfinite(s.v) && std::isfinite(s.a);
}

// The stretched two-peak change (docs/axes-profile.md, "Prescribed durations", item 5; session
// 30): in the frame toward the target (v0 >= 0, v1 >= 0), with sigma the sign of v1 - v0 and
// alpha the acceleration times sigma, jerk +J from alpha0 to a first peak x1, -J down to a dip
// z >= 0, +J to a second peak x2, -J to 0. The velocity change fixes
//   x2^2 = J |v1 - v0| + alpha0^2 / 2 + z^2 - x1^2,   T = (2 x1 + 2 x2 - alpha0 - 2 z) / J.
// z = x1 or x2 = z is the single triangle (the fastest); on the branch x1 >= x2 (the first peak
// the higher: more distance) T falls from the symmetric x1 = x2 to the triangle's, so x1 is
// the root of T for a dip z, and z the root of the distance D (both by bisection; no holds:
// peaks within the limit). Used where no other family takes the duration.
class StretchedTwoPeak {
 public:
  /// The frame values of the change; false where the shape does not apply.
  bool set_up(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
              double duration) noexcept {
    const double dp = target.p - start.p;
    if (!(dp != 0.0)) return false;
    f_ = dp > 0.0 ? 1.0 : -1.0;
    v0_ = f_ * start.v;
    a0_ = f_ * start.a;
    v1_ = f_ * target.v;
    d_ = f_ * dp;
    j_ = dyn.j_max;
    duration_ = duration;
    if (v0_ < 0.0 || v1_ < 0.0 || v1_ == v0_) return false;
    sigma_ = v1_ > v0_ ? 1.0 : -1.0;
    const double lim = sigma_ > 0.0 ? dyn.a_max : dyn.d_max;
    alpha0_ = sigma_ * a0_;
    if (alpha0_ > lim) return false;
    // A start pushing against the change (alpha0 < 0) moves v away from v1 first: keep v in
    // [0, V] and the acceleration within the other limit.
    if (alpha0_ < 0.0) {
      const double v_turn = v0_ - sigma_ * alpha0_ * alpha0_ / (2.0 * j_);
      const double other = sigma_ > 0.0 ? dyn.d_max : dyn.a_max;
      if (v_turn < 0.0 || v_turn > dyn.v_max || -alpha0_ > other) return false;
    }
    w_ = j_ * std::abs(v1_ - v0_) + 0.5 * alpha0_ * alpha0_;
    x_tri_ = std::sqrt(w_);
    lim_ = lim;
    if (!(x_tri_ > std::max(alpha0_, 0.0)) || x_tri_ > lim) return false;
    return duration >= (2.0 * x_tri_ - alpha0_) / j_ * (1.0 - kRelTol);  // not below the triangle
  }

  /// The dip z from 0 (deepest) up to the shallowest still slow enough, by bisection on the
  /// distance (monotone along that curve: assumed, checked by the bracket); false where the
  /// time and the distance do not both meet to kRelTol.
  bool solve(jerk::TwoPeak& tp) const noexcept {
    if (!(t_eq(0.0) >= duration_)) return false;  // even the deepest dip is too fast
    double z_lo = 0.0;
    double z_hi = shallowest_dip();
    jerk::TwoPeak tp_lo;
    jerk::TwoPeak tp_hi;
    double g_lo = gap(z_lo, tp_lo);
    const double g_hi = gap(z_hi, tp_hi);
    if (!std::isfinite(g_lo) || !std::isfinite(g_hi) || (g_lo > 0.0) == (g_hi > 0.0)) return false;
    tp = tp_lo;
    for (int i = 0; i < 200 && z_hi - z_lo > kBisectWidth * z_hi; ++i) {
      const double mid = 0.5 * (z_lo + z_hi);
      jerk::TwoPeak t_mid;
      const double g_mid = gap(mid, t_mid);
      if (!std::isfinite(g_mid)) return false;
      ((g_mid > 0.0) == (g_lo > 0.0) ? z_lo : z_hi) = mid;
      if ((g_mid > 0.0) == (g_lo > 0.0)) g_lo = g_mid;
      tp = t_mid;
    }
    return std::abs(tp.time() - duration_) <= kRelTol * duration_ &&
           std::abs(distance(tp) - d_) <= kRelTol * std::max(d_, kSamePoint);
  }

 private:
  double x2_of(double x1, double z) const noexcept {
    return std::sqrt(std::max(0.0, w_ + z * z - x1 * x1));
  }
  double time_of(double x1, double z) const noexcept {
    return (2.0 * x1 + 2.0 * x2_of(x1, z) - alpha0_ - 2.0 * z) / j_;
  }
  jerk::TwoPeak shape(double x1, double z) const noexcept {
    const double x2 = x2_of(x1, z);
    jerk::TwoPeak tp;
    tp.jerk = {sigma_ * j_, -sigma_ * j_, sigma_ * j_, -sigma_ * j_};
    tp.duration = {(x1 - alpha0_) / j_, (x1 - z) / j_, (x2 - z) / j_, x2 / j_};
    tp.a_end = {sigma_ * x1, sigma_ * z, sigma_ * x2, 0.0};
    tp.v_end = v1_;
    tp.sign = f_;
    return tp;
  }
  double distance(const jerk::TwoPeak& tp) const noexcept {
    jerk::State st{0.0, v0_, a0_};
    for (std::size_t i = 0; i < 4; ++i) {
      st = jerk::advance(st, tp.jerk[i], tp.duration[i]);
      st.a = tp.a_end[i];
    }
    return st.p;
  }
  /// x1 on the branch [max(x_eq, alpha0), x_tri] with T(x1) = duration for the dip z; < 0:
  /// none.
  double x1_for(double z) const noexcept {
    const double x_eq = std::sqrt(0.5 * (w_ + z * z));
    double hi = x_tri_;
    double lo = std::max({x_eq, alpha0_, z});
    if (lo > lim_ || !(time_of(lo, z) >= duration_) || time_of(hi, z) > duration_) return -1.0;
    for (int i = 0; i < 200 && hi - lo > kBisectWidth * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (time_of(mid, z) >= duration_ ? lo : hi) = mid;
    }
    return lo;
  }
  /// The distance left over by the shape of dip z (NaN: no x1 takes the duration).
  double gap(double z, jerk::TwoPeak& tp) const noexcept {
    const double x1 = x1_for(z);
    if (x1 < 0.0) return std::numeric_limits<double>::quiet_NaN();
    tp = shape(x1, z);
    return distance(tp) - d_;
  }
  /// T at x1 = x_eq: it falls as the dip z grows.
  double t_eq(double z) const noexcept {
    return time_of(std::max({std::sqrt(0.5 * (w_ + z * z)), alpha0_, z}), z);
  }
  /// The shallowest dip still slow enough (bisection on [0, x_tri]).
  double shallowest_dip() const noexcept {
    double z_ok = 0.0;
    double z_no = x_tri_;
    for (int i = 0; i < 200 && z_no - z_ok > kBisectWidth * x_tri_; ++i) {
      const double mid = 0.5 * (z_ok + z_no);
      (t_eq(mid) >= duration_ ? z_ok : z_no) = mid;
    }
    return z_ok;
  }

  double f_ = 1.0, v0_ = 0.0, a0_ = 0.0, v1_ = 0.0, d_ = 0.0, j_ = 0.0, duration_ = 0.0;
  double sigma_ = 1.0, alpha0_ = 0.0, lim_ = 0.0, w_ = 0.0, x_tri_ = 0.0;
};

bool two_peak_from(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                   double duration, Profile& out) noexcept {
  StretchedTwoPeak change;
  jerk::TwoPeak tp;
  if (!change.set_up(start, target, dyn, duration) || !change.solve(tp)) return false;
  const MotionState end{target.p, target.v, 0.0};
  detail::ProfileBuilder b(out, start);
  detail::append_two_peak(b, tp);
  b.finish(&end);
  return true;
}

// The stretched two-peak change, first as it is, then after a first dip of the start's
// acceleration (jerk -sigma J from alpha0 down to u, a third parameter; u on kDips steps down
// to the other limit, the first that lets the change take the rest of the duration): the
// shape linear programs find between the level family's runs (docs/axes-profile.md (c)).
bool plan_two_peak_of_duration(const MotionState& start, const PositionTarget& target,
                               const Dynamics& dyn, double duration, Profile& out) noexcept {
  if (two_peak_from(start, target, dyn, duration, out)) return true;
  const double dp = target.p - start.p;
  if (!(dp != 0.0)) return false;
  const double f = dp > 0.0 ? 1.0 : -1.0;
  const double v0 = f * start.v;
  const double v1 = f * target.v;
  if (v0 < 0.0 || v1 < 0.0 || v1 == v0) return false;
  const double sigma = v1 > v0 ? 1.0 : -1.0;
  const double alpha0 = sigma * f * start.a;
  const double other = sigma > 0.0 ? dyn.d_max : dyn.a_max;
  const double j = dyn.j_max;
  // The velocity's extremum where the dip passes a = 0 stays in [0, V].
  const double v_ext = v0 + sigma * std::max(alpha0, 0.0) * alpha0 / (2.0 * j);
  if (v_ext < 0.0 || v_ext > dyn.v_max || !(alpha0 > -other)) return false;
  constexpr int kDips = 16;
  for (int k = 1; k <= kDips; ++k) {
    const double u = alpha0 - (alpha0 + other) * k / kDips;
    const double t0 = (alpha0 - u) / j;
    if (!(t0 < duration)) break;
    // The change after the dip takes durations between its triangle's and its symmetric
    // peaks' with the dip at 0 (closed form): skip a u whose range misses the duration.
    const double w_u = j * std::abs(v1 - v0) - 0.5 * alpha0 * alpha0 + u * u;
    if (!(w_u > 0.0)) continue;
    const double t_tri = (alpha0 - 2.0 * u + 2.0 * std::sqrt(w_u)) / j;
    const double t_sym = (alpha0 - 2.0 * u + 4.0 * std::sqrt(0.5 * w_u)) / j;
    if (duration < t_tri * (1.0 - kRelTol) || duration > t_sym * (1.0 + kRelTol)) continue;
    MotionState s1 = jerk::advance(start, -f * sigma * j, t0);
    s1.a = f * sigma * u;
    Profile tail;
    if (!two_peak_from(s1, target, dyn, duration - t0, tail)) continue;
    const MotionState end{target.p, target.v, 0.0};
    detail::ProfileBuilder b(out, start);
    b.add(-f * sigma * j, t0, f * sigma * u);
    b.add(tail);
    b.finish(&end);
    return true;
  }
  return false;
}

// The rest families (docs/axes-profile.md, "Prescribed durations", item 5): a profile that
// rests on the way, for durations no stretched family takes. A target at rest: the fastest
// profile, then a rest at the target (every duration from the fastest on). An arrival velocity:
// the fastest stop (none from a start at rest), a rest, then the fastest profile from there
// (every duration from stop + go on). False where the duration is shorter, or the phases would
// not fit into one Profile.
bool plan_with_rest(const MotionState& start, const PositionTarget& target, const Dynamics& dyn,
                    double duration, Profile& out) noexcept {
  const MotionState end{target.p, target.v, 0.0};
  Profile go;
  if (target.v == 0.0) {
    if (plan_position(start, target, dyn, go, ProfileRule::time_optimal) != Result::ok ||
        !(go.duration() <= duration) || go.phases().size() >= Profile::kMaxPhases) {
      return false;
    }
    detail::ProfileBuilder b(out, start);
    b.add(go);
    b.add(0.0, duration - go.duration());
    b.finish(&end);
    return true;
  }
  Profile stop = Profile::at_rest(start.p);
  if (start.v != 0.0 || start.a != 0.0) {
    if (plan_stop(start, dyn, stop) != Result::ok) return false;
  }
  const MotionState rest{stop.end_state().p, 0.0, 0.0};
  if (plan_position(rest, target, dyn, go, ProfileRule::time_optimal) != Result::ok) return false;
  const double t_rest = duration - stop.duration() - go.duration();
  if (!(t_rest >= 0.0) || stop.phases().size() + 1 + go.phases().size() > Profile::kMaxPhases) {
    return false;
  }
  detail::ProfileBuilder b(out, start);
  b.add(stop);
  b.add(0.0, t_rest);
  b.add(go);
  b.finish(&end);
  return true;
}

// Where the rest families' durations begin (infinite where they do not apply).
double rest_family_start(const MotionState& start, const PositionTarget& target,
                         const Dynamics& dyn) noexcept {
  Profile stop = Profile::at_rest(start.p);
  if (target.v != 0.0 && (start.v != 0.0 || start.a != 0.0) &&
      plan_stop(start, dyn, stop) != Result::ok) {
    return std::numeric_limits<double>::infinity();
  }
  const MotionState from = target.v == 0.0 ? start : MotionState{stop.end_state().p, 0.0, 0.0};
  Profile go;
  if (plan_position(from, target, dyn, go, ProfileRule::time_optimal) != Result::ok)
    return std::numeric_limits<double>::infinity();
  return (target.v == 0.0 ? 0.0 : stop.duration()) + go.duration();
}

// plan_position_of_duration; `late`: the rest families too (not for moving targets: a meeting
// that rests first is not built, docs/axes-profile.md).
Result position_of_duration(const MotionState& start, const PositionTarget& target,
                            const Dynamics& dyn, double duration, Profile& out,
                            bool late) noexcept {
  // The single-peak family (in the reversed frame for an overshoot to a target at rest), else a
  // turn on the way to an arrival velocity, each with its level lowered to the duration.
  const MotionState end{target.p, target.v, 0.0};
  jerk::Move m;
  const jerk::Status st = jerk::move_of_duration(start, target.p, target.v, duration, dyn, m);
  if (st == jerk::Status::invalid_input) return Result::error_invalid_input;
  if (st == jerk::Status::ok) {
    detail::ProfileBuilder b(out, start);
    detail::append_move(b, m);
    b.finish(&end);
    return Result::ok;
  }
  jerk::Reversal rev;
  if (target.v != 0.0 && jerk::reversal_of_duration(start, target.p, target.v, duration, dyn,
                                                    rev) == jerk::Status::ok) {
    detail::ProfileBuilder b(out, start);
    detail::append_move(b, rev.out);
    detail::append_move(b, rev.back);
    b.finish(&end);
    return Result::ok;
  }
  // A braking turn through v = 0 (jerk/dip_cross.cpp) with a cruise at the arrival velocity at
  // its end (issue 11, session 31).
  jerk::DipCrossing dc;
  if (target.v != 0.0 && jerk::dip_crossing_of_duration(start, target.p, target.v, duration, dyn,
                                                        dc) == jerk::Status::ok) {
    detail::ProfileBuilder b(out, start);
    detail::append_dip_crossing(b, dc);
    b.finish(&end);
    return Result::ok;
  }
  // The duration of the fastest profile itself (e.g. a two-peak change, which has no slower
  // variant in these families).
  if (plan_position(start, target, dyn, out, ProfileRule::time_optimal) == Result::ok &&
      std::abs(out.duration() - duration) <= kRelRounding * duration) {
    return Result::ok;
  }
  if (plan_two_peak_of_duration(start, target, dyn, duration, out)) return Result::ok;
  if (late && plan_with_rest(start, target, dyn, duration, out)) return Result::ok;
  return Result::error_not_synchronizable;
}

}  // namespace

Result plan_position_of_duration(const MotionState& start, const PositionTarget& target,
                                 const Dynamics& dyn, double duration, Profile& out) noexcept {
  return position_of_duration(start, target, dyn, duration, out, true);
}

Result plan_synchronized(std::span<const MotionState> starts,
                         std::span<const PositionTarget> targets,
                         std::span<const Dynamics> dynamics, ProfileRule rule, double min_duration,
                         std::span<Profile> out) noexcept {
  const std::size_t n = starts.size();
  if (targets.size() != n || dynamics.size() != n || out.size() != n ||
      !std::isfinite(min_duration)) {
    return Result::error_invalid_input;
  }
  double t_sync = std::max(min_duration, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Result r = plan_position(starts[i], targets[i], dynamics[i], out[i], rule);
    if (r != Result::ok) return r;
    t_sync = std::max(t_sync, out[i].duration());
  }
  // Every axis in exactly t_sync. An axis without a profile of that duration (a gap between
  // the longest single-peak profile and the fastest turn, docs/axes-profile.md) moves t_sync
  // to the start of its next feasible range, and every axis is planned again (Ruckig's
  // "blocked intervals"); each round moves t_sync onto the start of a range, so a few rounds
  // suffice (bounded: 2 n + 2).
  for (std::size_t round = 0; round <= 2 * n + 1; ++round) {
    double t_next = t_sync;
    for (std::size_t i = 0; i < n; ++i) {
      if (round == 0 && out[i].duration() == t_sync) continue;  // the slowest keeps its own
      const Result r =
          plan_position_of_duration(starts[i], targets[i], dynamics[i], t_sync, out[i]);
      if (r == Result::ok) continue;
      if (r != Result::error_not_synchronizable) return r;
      const double t_resume = next_feasible_duration(starts[i], targets[i], dynamics[i], t_sync);
      if (!(t_resume > t_sync)) return r;
      t_next = std::max(t_next, t_resume);
    }
    if (t_next == t_sync) return Result::ok;
    t_sync = t_next;
  }
  return Result::error_not_synchronizable;
}

double next_feasible_duration(const MotionState& start, const PositionTarget& target,
                              const Dynamics& dyn, double duration) noexcept {
  // The ranges of the families plan_position_of_duration stretches start at the single-peak
  // family's root bracketed from 0 and at the fastest turn.
  double next = std::numeric_limits<double>::infinity();
  const double t_rest = rest_family_start(start, target, dyn);
  if (t_rest > duration) next = t_rest;
  const double t_single = jerk::min_single_peak_time(start, target.p, target.v, dyn);
  if (t_single > duration) next = std::min(next, t_single);
  jerk::Reversal rev;
  if (target.v != 0.0 &&
      jerk::reversal_move(start, target.p, target.v, dyn, rev) == jerk::Status::ok) {
    if (rev.time() > duration) {
      next = std::min(next, rev.time());
    } else if (jerk::reversal_of_duration(start, target.p, target.v, duration, dyn, rev) !=
               jerk::Status::ok) {
      // A gap inside the turns: the levels below the hump of the turn's displacement
      // (jerk/reverse.cpp) start at a slower time, and every longer duration has a turn. Found
      // by doubling a step from the duration until a turn of that duration exists, then
      // bisection of that one boundary.
      const auto turns = [&](double t) {
        return jerk::reversal_of_duration(start, target.p, target.v, t, dyn, rev) ==
               jerk::Status::ok;
      };
      double t_no = duration;
      double step = duration * 0x1p-20;
      double t_yes = -1.0;
      for (int k = 0; k < 80; ++k, step *= 2.0) {
        if (turns(duration + step)) {
          t_yes = duration + step;
          break;
        }
        t_no = duration + step;
      }
      for (int i = 0; t_yes > 0.0 && i < 200 && t_yes - t_no > kBisectWidth * t_yes; ++i) {
        const double mid = 0.5 * (t_no + t_yes);
        (turns(mid) ? t_yes : t_no) = mid;
      }
      if (t_yes > 0.0) next = std::min(next, t_yes);
    }
  }
  return std::isfinite(next) ? next : -1.0;
}

Result plan_moving_target(const MotionState& start, double p1, double v1, const Dynamics& dyn,
                          Profile& out, double& t_meet) noexcept {
  return plan_moving_target(start, p1, v1, v1, dyn, out, t_meet);
}

Result plan_moving_target(const MotionState& start, double p1, double v1, double v_arrive,
                          const Dynamics& dyn, Profile& out, double& t_meet) noexcept {
  if (!valid(dyn) || !finite(start) || !std::isfinite(p1) || !std::isfinite(v1) ||
      !std::isfinite(v_arrive) || std::abs(v_arrive) > dyn.v_max) {
    return Result::error_invalid_input;
  }
  // reach(T): the fastest profile reaches p1 + v1 T with velocity v_arrive within T. Necessary
  // for a meeting at T; where the fastest takes exactly T (the boundary the search converges
  // to) it is the meeting itself.
  Profile probe;
  const auto target_at = [&](double t) { return PositionTarget{p1 + v1 * t, v_arrive}; };
  const auto reach = [&](double t) {
    return plan_position(start, target_at(t), dyn, probe, ProfileRule::time_optimal) ==
               Result::ok &&
           probe.duration() <= t;
  };
  // meet(T): a profile of exactly T meets the target (into `out`). A moving start can have
  // durations between its fastest and its slower families that no profile takes (a gap), so
  // reach(T) does not imply meet(T).
  const auto meet = [&](double t) {
    if (!reach(t)) return false;
    if (position_of_duration(start, target_at(t), dyn, t, out, false) == Result::ok) return true;
    if (std::abs(probe.duration() - t) <= kRelTol * std::max(t, kSameTime)) {
      out = probe;  // at the boundary of reach: the fastest profile takes T
      return true;
    }
    return false;
  };

  // The earliest T with pred(T): grow T geometrically from t_start, then bisect to rounding
  // between the last T without and the first with. Decision: a window shorter than the
  // doubling step can be missed (docs/axes-profile.md).
  const auto earliest = [&](double t_start, double t_step, auto pred, double& t_found) {
    double t_lo = t_start;
    double step = t_step;
    double t_hi = t_start + step;
    for (int k = 0; !pred(t_hi); ++k) {
      if (k > 100) return false;  // the target runs away
      t_lo = t_hi;
      step *= 2.0;
      t_hi = t_start + step;
    }
    for (int i = 0; i < 200 && t_hi - t_lo > kBisectWidth * t_hi; ++i) {
      const double mid = 0.5 * (t_lo + t_hi);
      (pred(mid) ? t_hi : t_lo) = mid;
    }
    t_found = t_hi;
    return true;
  };
  // From well below the static target's time, so an approaching target is met early.
  const bool static_ok =
      plan_position(start, target_at(0.0), dyn, probe, ProfileRule::time_optimal) == Result::ok;
  const double t_scale = static_ok && probe.duration() > 0.0 ? probe.duration() : 1.0;
  double t_found = 0.0;
  if (!meet(0.0)) {
    // The boundary of reach first: there the fastest profile takes T (met exactly); past a gap,
    // the earliest T from there on at which a profile of exactly T exists.
    if (!earliest(0.0, t_scale * 0x1p-20, reach, t_found)) return Result::error_not_synchronizable;
    if (!meet(t_found)) {
      if (!earliest(t_found, t_found * 0x1p-20, meet, t_found)) {
        return Result::error_not_synchronizable;
      }
      // meet is not monotone: the bisection can end inside a window of meetings; walk back
      // (doubling steps) to the window's start and bisect there.
      double step = t_found * 0x1p-20;
      double t_ok = t_found;
      for (int k = 0; k < 60 && t_ok - step > 0.0 && meet(t_ok - step); ++k) {
        t_ok -= step;
        step *= 2.0;
      }
      double t_no = std::max(0.0, t_ok - step);
      for (int i = 0; i < 200 && t_ok - t_no > kBisectWidth * t_ok; ++i) {
        const double mid = 0.5 * (t_no + t_ok);
        (meet(mid) ? t_ok : t_no) = mid;
      }
      if (!meet(t_ok)) return Result::error_not_synchronizable;
    }
  }
  t_meet = out.duration();  // T to rounding; the profile's own end is the meeting
  return Result::ok;
}

}  // namespace ncsim::axes
