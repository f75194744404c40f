// plan_moving_target over seeded random cases against an independent reference (issue 11: "a
// target moving with constant velocity met in p, v, a at the earliest time").
//
// The reference, written here apart from the kernel: a start (v0 >= 0, a = 0) meets the target
// p1 + v1 t (p1 > 0, v1 >= 0) at time T when p1 + v1 T lies between the least and the largest
// distance coverable in exactly T ending at (v1, a = 0) without reversing:
//  - largest s_max(T): the peak level vm >= max(v0, v1), textbook S-ramps v0 -> vm -> v1
//    (A+ speeding up, A- slowing down, 002_* 2.1) and a cruise at vm; the distance
//    vm T - (vm - v0) t1 / 2 - (vm - v1) t2 / 2 is concave in vm (x t(x) is convex), so a
//    golden-section search over the levels whose ramps fit in T finds it;
//  - least s_min(T): the dip vm <= min(v0, v1), convex in vm, the same way.
// Once met, the axis can ride along at v1, so feasibility is monotone in T: s_max(T) - v1 T
// grows (its slope is the peak level minus v1) and s_min(T) - v1 T falls; the earliest meeting
// is found by doubling and bisection on T. It is the earliest of every profile where going
// faster decides (catch-up: no profile covers more than s_max), or where the dip does not
// reach v = 0 (a reversal would first have to stop); where the dip reaches v = 0 a reversal
// (v < 0) could meet earlier, and the reference bounds the meeting from above only.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "axes/profile.hpp"
#include "axes/profile_limits_check.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::Profile;
using ncsim::axes::Result;
using ncsim::test::log_uniform;
using Real = long double;

// Textbook S-ramp from a = 0 to a = 0 over the velocity change dv >= 0 with limit a, jerk j.
Real ramp_time(Real dv, Real a, Real j) {
  return dv * j <= a * a ? 2 * std::sqrt(dv / j) : dv / a + a / j;
}

struct MeetRef {
  Real v0, v1, p1, vmax, ap, am, j;

  // Ramps v0 -> vm -> v1 (v >= 0: A+ speeding up, A- slowing down) and their time.
  Real ramps(Real vm, Real& t1, Real& t2) const {
    t1 = ramp_time(std::fabs(vm - v0), vm > v0 ? ap : am, j);
    t2 = ramp_time(std::fabs(vm - v1), vm > v1 ? am : ap, j);
    return t1 + t2;
  }
  // Distance in exactly T through level vm (its ramps must fit: t1 + t2 <= T).
  Real dist(Real vm, Real T) const {
    Real t1 = 0;
    Real t2 = 0;
    ramps(vm, t1, t2);
    return (v0 + vm) / 2 * t1 + (vm + v1) / 2 * t2 + vm * (T - t1 - t2);
  }
  Real t_direct() const { return ramp_time(std::fabs(v1 - v0), v1 > v0 ? ap : am, j); }

  // The level in [lo, hi] (ramp time monotone there, rising toward `far`) whose ramps take T.
  Real level_edge(Real near, Real far, Real T) const {
    Real t1 = 0;
    Real t2 = 0;
    if (ramps(far, t1, t2) <= T) return far;
    Real a = near;
    Real b = far;
    for (int i = 0; i < 100; ++i) {
      const Real m = (a + b) / 2;
      (ramps(m, t1, t2) <= T ? a : b) = m;
    }
    return a;
  }
  // Golden-section extreme of dist over [a, b]: sign +1 max (concave), -1 min (convex).
  Real extreme(Real a, Real b, Real T, Real sign, Real& at) const {
    const Real g = (std::sqrt(Real(5)) - 1) / 2;
    for (int i = 0; i < 100; ++i) {
      const Real x1 = b - g * (b - a);
      const Real x2 = a + g * (b - a);
      if (sign * dist(x1, T) < sign * dist(x2, T)) {
        a = x1;
      } else {
        b = x2;
      }
    }
    at = (a + b) / 2;
    return dist(at, T);
  }
  Real s_max(Real T, Real& vm) const {
    const Real lo = std::max(v0, v1);
    return extreme(lo, level_edge(lo, vmax, T), T, 1, vm);
  }
  Real s_min(Real T, Real& vm) const {
    const Real hi = std::min(v0, v1);
    return extreme(level_edge(hi, 0, T), hi, T, -1, vm);
  }
  bool feasible(Real T) const {
    if (T < t_direct()) return false;
    Real vm = 0;
    const Real x = p1 + v1 * T;
    return s_min(T, vm) <= x && x <= s_max(T, vm);
  }
};

}  // namespace

TEST_CASE("a moving target is met at the independent reference's earliest time (3000 cases)") {
  std::mt19937_64 rng(2026112530);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  int exact = 0;     // the reference is the earliest of every profile: checked both ways
  int reversal = 0;  // the dip reaches v = 0: the reference bounds from above only
  int no_ref = 0;    // v1 = 0 and a target the start overshoots: needs a reversal
  int early = 0;     // earlier than the reference within the kernel's distance tolerance
  for (int n = 0; n < 3000; ++n) {
    const Dynamics d{log_uniform(rng, 1.0, 1e4), log_uniform(rng, 10.0, 1e5),
                     log_uniform(rng, 10.0, 1e5), log_uniform(rng, 1e2, 1e7)};
    const double v0 = d.v_max * unit(rng);
    const double v1 = unit(rng) < 0.2 ? 0.0 : 0.8 * d.v_max * unit(rng);
    const double scale = d.v_max * d.v_max / std::min(d.a_max, d.d_max);
    // Half over issue 11's absolute distances, half relative to the braking scale.
    const double p1 =
        n % 2 == 0 ? log_uniform(rng, 1e-4, 1e4) : scale * log_uniform(rng, 1e-4, 1e1);
    const MeetRef ref{v0, v1, p1, d.v_max, d.a_max, d.d_max, d.j_max};
    Real lo = 0;
    Real hi = std::max(ref.t_direct(), Real(1e-9));
    int k = 0;
    while (!ref.feasible(hi) && ++k < 80) {
      lo = hi;
      hi *= 2;
    }
    if (k >= 80) {
      ++no_ref;
      continue;
    }
    for (int i = 0; i < 120; ++i) {
      const Real mid = (lo + hi) / 2;
      (ref.feasible(mid) ? hi : lo) = mid;
    }
    const double t_ref = static_cast<double>(hi);
    // Which side decides, and how finely the reference resolves T: the distances' rounding
    // (1e-15 of the way) over the slope of the deciding side.
    Real vm_max = 0;
    Real vm_min = 0;
    const Real x = p1 + v1 * hi;
    const Real gap_max = ref.s_max(hi, vm_max) - x;
    const Real gap_min = x - ref.s_min(hi, vm_min);
    const bool catch_up = gap_max <= gap_min;
    const Real slope = catch_up ? vm_max - v1 : v1 - vm_min;
    const Real resolution = 1e-15L * (std::fabs(x) + v0 * hi) / std::max(slope, Real(1e-300));
    const bool earliest = catch_up || vm_min > 1e-9L * d.v_max;

    Profile p;
    double t_meet = 0.0;
    INFO("case ", n, " v0=", v0, " p1=", p1, " v1=", v1, " V=", d.v_max, " A+=", d.a_max,
         " A-=", d.d_max, " J=", d.j_max, " t_ref=", t_ref,
         std::string(catch_up ? " catch-up" : " dip"),
         " vm=", static_cast<double>(catch_up ? vm_max : vm_min),
         " resolution=", static_cast<double>(resolution / hi));
    REQUIRE(ncsim::axes::plan_moving_target(MotionState{0.0, v0, 0.0}, p1, v1, d, p, t_meet) ==
            Result::ok);
    INFO("t_meet=", t_meet, " rel=", t_meet / t_ref - 1.0);
    REQUIRE(p.duration() == t_meet);
    const auto end = p.at(t_meet);
    REQUIRE(end.p == doctest::Approx(p1 + v1 * t_meet).epsilon(1e-12));
    REQUIRE(end.v == v1);
    REQUIRE(end.a == 0.0);
    const std::string bad = ncsim::test::profile_limit_violation(p, d, MotionState{0.0, v0, 0.0});
    REQUIRE_MESSAGE(bad.empty(), bad);
    ++checked;
    if (resolution > 1e-10L * hi) continue;  // the reference cannot resolve 1e-9 here
    // Never later than the reference's meeting (its profiles are valid profiles).
    CHECK(t_meet <= t_ref * (1.0 + 1e-9));
    if (earliest) {
      // Not earlier either, but for the kernel's distance tolerance: a stretched level may
      // cover up to 1e-9 of D more than D (jerk/move.cpp stretch_from, "range not connected"),
      // and the profile's end is set on the target (docs/axes-profile.md, "Weak points"). Such
      // a meeting lies up to ~2e-9 early; it is held to that: the distance the reference needs
      // at t_meet exceeds the target's position there by at most 1e-9 of it.
      if (t_meet < t_ref * (1.0 - 1e-9)) {
        Real vm = 0;
        const Real x_meet = p1 + v1 * static_cast<Real>(t_meet);
        const Real need =
            catch_up ? x_meet - ref.s_max(t_meet, vm) : ref.s_min(t_meet, vm) - x_meet;
        INFO("distance short of the reference at t_meet: ", static_cast<double>(need / x_meet));
        CHECK(need <= 1.000001e-9L * x_meet);
        ++early;
      }
      ++exact;
    } else {
      ++reversal;
    }
  }
  MESSAGE("checked ", checked, ", earliest both ways ", exact,
          " (early by the 1e-9 distance "
          "tolerance ",
          early, "), bounded above (dip to 0) ", reversal, ", no reference ", no_ref);
  CHECK(exact > 2000);
}

TEST_CASE("from random moving starts a moving target is met exactly in p, v and a (3000 cases)") {
  // Starts with acceleration, either direction, inside the limits (draw_move), targets moving
  // either way: no reference here (see above), only the meeting itself and the limits. The
  // 4096 benchmark requests (bench/axes_bench.cpp) had one such start whose "meeting" ended
  // 7.5 mm off the target (case below).
  std::mt19937_64 rng(2026112531);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int met = 0;
  for (int n = 0; n < 3000; ++n) {
    const ncsim::test::MoveDraw m = ncsim::test::draw_move(rng, ncsim::test::Arrival::half);
    const double v1 = 0.8 * m.lim.v_max * (2.0 * unit(rng) - 1.0);
    Profile p;
    double t_meet = 0.0;
    INFO("case ", n, " v0=", m.start.v, " a0=", m.start.a, " p1=", m.p1 - m.start.p, " v1=", v1,
         " V=", m.lim.v_max, " A+=", m.lim.a_max, " A-=", m.lim.d_max, " J=", m.lim.j_max);
    const Result r = ncsim::axes::plan_moving_target(m.start, m.p1, v1, m.lim, p, t_meet);
    REQUIRE(r == Result::ok);
    INFO("t_meet=", t_meet);
    REQUIRE(p.duration() == t_meet);
    const auto end = p.at(t_meet);
    // To the rounding of the meeting time: the profile's duration may differ from the time the
    // target was taken at by ~1e-12 of it (plan_position_of_duration's acceptance).
    const double miss = end.p - (m.p1 + v1 * t_meet);
    INFO("miss=", miss);
    const double way = std::abs(m.p1 - m.start.p) + std::abs(v1) * t_meet + std::abs(m.p1);
    REQUIRE(std::abs(miss) <= 1.001e-12 * std::abs(v1) * t_meet + 1e-14 * way);
    REQUIRE(end.v == v1);
    REQUIRE(end.a == 0.0);
    const std::string bad = ncsim::test::profile_limit_violation(p, m.lim, m.start);
    REQUIRE_MESSAGE(bad.empty(), bad);
    ++met;
  }
  CHECK(met == 3000);
}

TEST_CASE("benchmark request 578: the moving target is met, not missed by 7.5 mm") {
  // bench/axes_bench.cpp BM_PlanMovingTarget, request 578: the target 238.8 mm behind moving
  // at +1030.6 mm/s. jerk::move_of_duration answered a probe duration with a move of another
  // duration, and the plan "met" at 0.49017 s at 273.88 mm while the target was at 266.39 mm.
  // Since move_of_duration refuses such moves (jerk/move_test.cpp) the meeting is at 0.49747 s.
  const MotionState start{0.0, 0x1.14d75fa69f691p+6, 0x1.a4a4ba05902fap+5};
  const double p1 = -0x1.dd9c014a83d06p+7;
  const double v1 = 0x1.01a8f4b9b3b68p+10;
  const Dynamics d{0x1.ad6eed3580daep+11, 0x1.01cbce97e1b9p+11, 0x1.0b42ed64a451fp+14,
                   0x1.fc7421d394f1cp+16};
  Profile p;
  double t_meet = 0.0;
  REQUIRE(ncsim::axes::plan_moving_target(start, p1, v1, d, p, t_meet) == Result::ok);
  CHECK(t_meet == doctest::Approx(0.49746724573).epsilon(1e-9));
  CHECK(std::abs(p.at(t_meet).p - (p1 + v1 * t_meet)) <= 1.001e-12 * v1 * t_meet + 1e-14 * 1000.0);
  CHECK(p.at(t_meet).v == v1);
  const std::string bad = ncsim::test::profile_limit_violation(p, d, start);
  CHECK_MESSAGE(bad.empty(), bad);
}
