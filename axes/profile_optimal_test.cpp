// ProfileRule::time_optimal, prescribed durations, synchronised axes and moving targets
// (docs/axes-profile.md, "Profile rule"). The minimum time of rest-to-rest moves with A+ != A-
// is checked against an independent reference below: a bisection on the duration whose
// feasibility check maximises the distance coverable in that time over the cruise level.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "axes/profile.hpp"
#include "axes/profile_limits_check.hpp"
#include "axes/profile_outside.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;
using ncsim::axes::Result;

using ncsim::test::log_uniform;

// Reference, written apart from the kernel: S-ramp from rest to v (time, mean velocity v/2).
double ref_ramp_time(double v, double a, double j) {
  return v * j <= a * a ? 2.0 * std::sqrt(v / j) : v / a + a / j;
}

// Largest distance from rest to rest within time t: maximise over the level by a scan and a
// golden-section refinement (the distance is unimodal in the level).
double ref_max_distance(double t, const Dynamics& d) {
  const auto dist = [&](double v) {
    const double ta = ref_ramp_time(v, d.a_max, d.j_max);
    const double td = ref_ramp_time(v, d.d_max, d.j_max);
    if (ta + td > t) return -1.0;
    return 0.5 * v * (ta + td) + v * (t - ta - td);
  };
  double best_v = 0.0;
  double best = 0.0;
  constexpr int kScan = 64;
  for (int i = 1; i <= kScan; ++i) {
    const double v = d.v_max * i / kScan;
    if (dist(v) > best) {
      best = dist(v);
      best_v = v;
    }
  }
  double lo = std::max(0.0, best_v - d.v_max / kScan);
  double hi = std::min(d.v_max, best_v + d.v_max / kScan);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 200; ++i) {
    const double x1 = hi - g * (hi - lo);
    const double x2 = lo + g * (hi - lo);
    if (dist(x1) < dist(x2)) {
      lo = x1;
    } else {
      hi = x2;
    }
  }
  return std::max(best, dist(0.5 * (lo + hi)));
}

double ref_min_time(double distance, const Dynamics& d) {
  double lo = 0.0;
  double hi = 1.0;
  while (ref_max_distance(hi, d) < distance)
    hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ref_max_distance(mid, d) >= distance ? hi : lo) = mid;
  }
  return hi;
}

// Largest distance within time t from (v0 >= 0, a = 0) ending at (v1 >= 0, a = 0), over the
// level vm: ramps with a = 0 at both ends have the mean velocity of their ends; A+ when
// speeding up, A- when slowing down.
double ref_max_distance_from(double v0, double v1, double t, const Dynamics& d) {
  const auto dist = [&](double vm) {
    const double t1 = ref_ramp_time(std::abs(vm - v0), vm > v0 ? d.a_max : d.d_max, d.j_max);
    const double t2 = ref_ramp_time(std::abs(vm - v1), vm > v1 ? d.d_max : d.a_max, d.j_max);
    if (t1 + t2 > t) return -1e300;
    return 0.5 * (v0 + vm) * t1 + 0.5 * (vm + v1) * t2 + vm * (t - t1 - t2);
  };
  constexpr int kScan = 256;
  double best_v = 0.0;
  double best = dist(0.0);
  for (int i = 1; i <= kScan; ++i) {
    const double v = d.v_max * i / kScan;
    if (dist(v) > best) {
      best = dist(v);
      best_v = v;
    }
  }
  double lo = std::max(0.0, best_v - d.v_max / kScan);
  double hi = std::min(d.v_max, best_v + d.v_max / kScan);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 200; ++i) {
    const double x1 = hi - g * (hi - lo);
    const double x2 = lo + g * (hi - lo);
    if (dist(x1) < dist(x2)) {
      lo = x1;
    } else {
      hi = x2;
    }
  }
  return std::max(best, dist(0.5 * (lo + hi)));
}

Dynamics random_dynamics(std::mt19937_64& rng) {
  Dynamics d;
  d.v_max = log_uniform(rng, 1.0, 1e4);
  d.a_max = log_uniform(rng, 10.0, 1e5);
  d.d_max = log_uniform(rng, 10.0, 1e5);
  d.j_max = log_uniform(rng, 1e2, 1e7);
  return d;
}

// V, A+/A-, J along the profile beyond what the start forces (axes/profile_limits_check.hpp).
void check_limits(const Profile& p, const Dynamics& d, const MotionState& start) {
  const std::string bad = ncsim::test::profile_limit_violation(p, d, start);
  REQUIRE_MESSAGE(bad.empty(), bad);
}

}  // namespace

TEST_CASE("time-optimal rest-to-rest with A+ != A- matches the independent reference to 1e-9") {
  std::mt19937_64 rng(20261122);
  for (int n = 0; n < 2000; ++n) {
    const Dynamics d = random_dynamics(rng);
    const double dist = log_uniform(rng, 1e-4, 1e4);
    Profile p;
    REQUIRE(ncsim::axes::plan_position(MotionState{}, PositionTarget{dist, 0.0}, d, p,
                                       ProfileRule::time_optimal) == Result::ok);
    const double t_ref = ref_min_time(dist, d);
    INFO("D=", dist, " V=", d.v_max, " A+=", d.a_max, " A-=", d.d_max, " J=", d.j_max,
         " t=", p.duration(), " t_ref=", t_ref);
    REQUIRE(p.duration() <= t_ref * (1.0 + 1e-9));
    const auto end = p.at(p.duration());
    REQUIRE(end.p == dist);
    REQUIRE(end.v == 0.0);
    REQUIRE(end.a == 0.0);
    check_limits(p, d, MotionState{});
  }
}

TEST_CASE("time-optimal from moving starts (a = 0) toward the target matches the reference") {
  // Starts at velocity v0 >= 0 with a = 0, the target ahead beyond the stop point, arrival at
  // v1 >= 0: the reference bisects the duration on "the largest distance coverable in T
  // reaches D" (ref_max_distance_from, written apart from the kernel).
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int n = 0; n < 2000; ++n) {
    const Dynamics d = random_dynamics(rng);
    const double v0 = d.v_max * unit(rng);
    const double v1 = unit(rng) < 0.5 ? 0.0 : d.v_max * unit(rng);
    const double dist = log_uniform(rng, 1e-4, 1e4);
    // Skip targets the start cannot reach without overshooting (the level 0 covers more).
    const double t0 = ref_ramp_time(v0, d.d_max, d.j_max);
    const double t1 = ref_ramp_time(v1, d.a_max, d.j_max);
    if (0.5 * v0 * t0 + 0.5 * v1 * t1 > dist) continue;
    Profile p;
    REQUIRE(ncsim::axes::plan_position(MotionState{0.0, v0, 0.0}, PositionTarget{dist, v1}, d, p,
                                       ProfileRule::time_optimal) == Result::ok);
    double lo = 0.0;
    double hi = p.duration() * 2.0 + 1e-9;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (ref_max_distance_from(v0, v1, mid, d) >= dist ? hi : lo) = mid;
    }
    INFO("v0=", v0, " v1=", v1, " D=", dist, " V=", d.v_max, " A+=", d.a_max, " A-=", d.d_max,
         " J=", d.j_max, " t=", p.duration(), " t_ref=", hi);
    REQUIRE(p.duration() <= hi * (1.0 + 1e-9));
    const auto end = p.at(p.duration());
    REQUIRE(end.p == dist);
    REQUIRE(end.v == v1);
    REQUIRE(end.a == 0.0);
    check_limits(p, d, MotionState{0.0, v0, 0.0});
    ++checked;
  }
  CHECK(checked > 600);
}

TEST_CASE("the manual rule (default) keeps Dynamik 1.2; time-optimal is faster when V is cut") {
  // Dynamik 1.2 reaches V: both rules give 0.95 s.
  const Dynamics d12{2000.0, 5000.0, 10000.0, 50000.0};
  Profile manual;
  Profile fast;
  REQUIRE(ncsim::axes::plan_position(MotionState{}, PositionTarget{1000.0, 0.0}, d12, manual) ==
          Result::ok);
  REQUIRE(ncsim::axes::plan_position(MotionState{}, PositionTarget{1000.0, 0.0}, d12, fast,
                                     ProfileRule::time_optimal) == Result::ok);
  CHECK(manual.duration() == doctest::Approx(0.95));
  CHECK(fast.duration() == doctest::Approx(0.95));
  // V unreachable with A+ != A-: the manual's symmetric min(A+, A-) costs time.
  const Dynamics cut{5000.0, 5000.0, 20000.0, 50000.0};
  REQUIRE(ncsim::axes::plan_position(MotionState{}, PositionTarget{500.0, 0.0}, cut, manual) ==
          Result::ok);
  REQUIRE(ncsim::axes::plan_position(MotionState{}, PositionTarget{500.0, 0.0}, cut, fast,
                                     ProfileRule::time_optimal) == Result::ok);
  CHECK(fast.duration() < manual.duration());
}

TEST_CASE("time-optimal reverses without stopping where the manual stops and returns (002 2.3)") {
  const Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  const MotionState start{0.0, 800.0, 0.0};  // moving away from the target at -100
  Profile manual;
  Profile fast;
  REQUIRE(ncsim::axes::plan_position(start, PositionTarget{-100.0, 0.0}, d, manual) == Result::ok);
  REQUIRE(ncsim::axes::plan_position(start, PositionTarget{-100.0, 0.0}, d, fast,
                                     ProfileRule::time_optimal) == Result::ok);
  CHECK(fast.duration() < manual.duration());
  CHECK(fast.at(fast.duration()).p == -100.0);
  check_limits(fast, d, start);
}

TEST_CASE("time-optimal from random moving states: never slower than the manual, limits, exact") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < 20000; ++n) {
    const Dynamics d = random_dynamics(rng);
    const double dist = (unit(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 1e-4, 1e4);
    // 10 % of the starts lie beyond the limits (|v0| up to 1.5 V, |a0| up to 1.5 A).
    const double beyond = unit(rng) < 0.1 ? 1.5 : 1.0;
    MotionState start{0.0, beyond * d.v_max * (2.0 * unit(rng) - 1.0), 0.0};
    if (unit(rng) < 0.3) {
      start.a = beyond * std::min(d.a_max, d.d_max) * (2.0 * unit(rng) - 1.0);
      if (beyond == 1.0) start.a *= 0.5;
    }
    const double v_end = unit(rng) < 0.25 ? (dist > 0 ? 1.0 : -1.0) * d.v_max * unit(rng) : 0.0;
    Profile manual;
    Profile fast;
    INFO("v0=", start.v, " a0=", start.a, " D=", dist, " v1=", v_end, " V=", d.v_max,
         " A+=", d.a_max, " A-=", d.d_max, " J=", d.j_max);
    REQUIRE(ncsim::axes::plan_position(start, PositionTarget{dist, v_end}, d, manual) ==
            Result::ok);
    REQUIRE(ncsim::axes::plan_position(start, PositionTarget{dist, v_end}, d, fast,
                                       ProfileRule::time_optimal) == Result::ok);
    // A start outside the limits (or forced beyond V by its release) is first
    // brought inside as fast as possible, which can cost total time (profile_outside_test.cpp).
    if (!ncsim::axes::detail::outside_limits(start, d)) {
      REQUIRE(fast.duration() <= manual.duration() * (1.0 + 1e-9));
    }
    const auto end = fast.at(fast.duration());
    REQUIRE(end.p == dist);
    REQUIRE(end.v == v_end);
    REQUIRE(end.a == 0.0);
    // Beyond the limits only by what the start forces (the helper's explicit exception).
    check_limits(fast, d, start);
  }
}

TEST_CASE("synchronised axes all take the slowest axis's duration and end on their targets") {
  const std::array<MotionState, 3> starts{MotionState{}, MotionState{0.0, 50.0, 0.0},
                                          MotionState{10.0, 0.0, 0.0}};
  const std::array<PositionTarget, 3> targets{
      PositionTarget{1000.0, 0.0}, PositionTarget{100.0, 0.0}, PositionTarget{-5.0, 0.0}};
  const std::array<Dynamics, 3> dyn{Dynamics{2000.0, 5000.0, 5000.0, 50000.0},
                                    Dynamics{500.0, 2000.0, 3000.0, 20000.0},
                                    Dynamics{300.0, 1000.0, 1000.0, 1e4}};
  std::array<Profile, 3> out;
  REQUIRE(ncsim::axes::plan_synchronized(starts, targets, dyn, ProfileRule::manual, 0.0, out) ==
          Result::ok);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(out[i].duration() == doctest::Approx(1.0).epsilon(1e-12));  // Dynamik 1.1 is slowest
    CHECK(out[i].at(out[i].duration()).p == targets[i].p);
    check_limits(out[i], dyn[i], starts[i]);
  }
  // INDP TIME=: a longer prescribed duration stretches every axis.
  REQUIRE(ncsim::axes::plan_synchronized(starts, targets, dyn, ProfileRule::manual, 2.5, out) ==
          Result::ok);
  for (std::size_t i = 0; i < 3; ++i)
    CHECK(out[i].duration() == doctest::Approx(2.5).epsilon(1e-12));
}

TEST_CASE("a moving target is met in position, velocity and acceleration at the earliest time") {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int met = 0;
  for (int n = 0; n < 2000; ++n) {
    Dynamics d = random_dynamics(rng);
    const double v1 = d.v_max * 0.8 * (2.0 * unit(rng) - 1.0);
    const double p1 = (unit(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 1e-3, 1e3);
    const MotionState start{0.0, d.v_max * (2.0 * unit(rng) - 1.0) * 0.5, 0.0};
    Profile p;
    double t_meet = 0.0;
    const Result r = ncsim::axes::plan_moving_target(start, p1, v1, d, p, t_meet);
    INFO("v0=", start.v, " p1=", p1, " v1=", v1, " V=", d.v_max, " A+=", d.a_max, " A-=", d.d_max,
         " J=", d.j_max);
    if (r == Result::error_not_synchronizable) continue;
    REQUIRE(r == Result::ok);
    ++met;
    const auto end = p.at(t_meet);
    REQUIRE(p.duration() == t_meet);
    REQUIRE(end.p == doctest::Approx(p1 + v1 * t_meet).epsilon(1e-9));
    REQUIRE(end.v == v1);
    REQUIRE(end.a == 0.0);
    check_limits(p, d, start);
    // Earliest: 1e-5 sooner no profile takes exactly that time to the target's position there
    // (the fastest is slower, or that duration lies in a gap of the start's durations). (Was
    // 1 %: before jerk's stretch_scan, near the start of a stretchable range
    // plan_position_of_duration failed sporadically and the search stopped up to ~0.2 % late:
    // case 1553, v0 = 0.26, V = 1.19, late at 1e-3; docs/axes-profile.md "Weak points".)
    const double t_early = t_meet * (1.0 - 1e-5);
    if (t_early > 0.0) {
      Profile q;
      const PositionTarget early{p1 + v1 * t_early, v1};
      const Result rq = ncsim::axes::plan_position(start, early, d, q, ProfileRule::time_optimal);
      if (rq == Result::ok && q.duration() <= t_early) {
        REQUIRE(ncsim::axes::plan_position_of_duration(start, early, d, t_early, q) ==
                Result::error_not_synchronizable);
      }
    }
  }
  CHECK(met == 2000);  // 1835 before turns and overshoots of a prescribed duration were built
}

TEST_CASE("time-optimal from a start moving away switches from A- to A+ at v = 0 (hand-computed)") {
  // V = 2000, A+ = 4000, A- = 1000, J = 1e4, start v = -1000 (away from the target at 3000).
  // Through v = 0 (jerk/move_test.cpp): 1.8625 s over 343.4375 mm (-549.583 before v = 0,
  // +893.021 after); braking 2000 -> 0 with A-: 2.1 s over 2100 mm; cruise 556.5625 mm at V:
  // 0.27828125 s. Total 4.24078125 s (one ramp under min(A+, A-), or stop then go, is slower).
  const Dynamics d{2000.0, 4000.0, 1000.0, 1e4};
  const MotionState start{0.0, -1000.0, 0.0};
  Profile p;
  REQUIRE(ncsim::axes::plan_position(start, PositionTarget{3000.0, 0.0}, d, p,
                                     ProfileRule::time_optimal) == Result::ok);
  CHECK(p.duration() == doctest::Approx(4.24078125).epsilon(1e-12));
  CHECK(p.at(p.duration()).p == 3000.0);
  // At v = 0 (t = 1.05 s) the acceleration is A- = 1000 and climbs to A+ after it.
  CHECK(p.at(1.05).v == doctest::Approx(0.0).epsilon(1e-9).scale(1000.0));
  CHECK(p.at(1.05).a == doctest::Approx(1000.0).epsilon(1e-12));
  CHECK(p.at(1.40).a == doctest::Approx(4000.0).epsilon(1e-12));
}

TEST_CASE("time-optimal from random starts moving away keeps the path limits A-/A+ and ends") {
  // Path limits (002_* 2.1): |a| <= A- while the acceleration slows the motion, <= A+ while it
  // speeds it up; checked on a fine grid of every profile (axes/profile_limits_check.hpp).
  std::mt19937_64 rng(808);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < 3000; ++n) {
    const Dynamics d = random_dynamics(rng);
    const double dist = log_uniform(rng, 1e-4, 1e4);
    const MotionState start{0.0, -d.v_max * unit(rng),
                            0.5 * std::min(d.a_max, d.d_max) * (2.0 * unit(rng) - 1.0)};
    const double v_end = unit(rng) < 0.3 ? d.v_max * unit(rng) : 0.0;
    Profile fast;
    Profile manual;
    INFO("v0=", start.v, " a0=", start.a, " D=", dist, " v1=", v_end, " V=", d.v_max,
         " A+=", d.a_max, " A-=", d.d_max, " J=", d.j_max);
    REQUIRE(ncsim::axes::plan_position(start, PositionTarget{dist, v_end}, d, fast,
                                       ProfileRule::time_optimal) == Result::ok);
    REQUIRE(ncsim::axes::plan_position(start, PositionTarget{dist, v_end}, d, manual) ==
            Result::ok);
    // As above, only starts inside the limits.
    if (!ncsim::axes::detail::outside_limits(start, d)) {
      REQUIRE(fast.duration() <= manual.duration() * (1.0 + 1e-9));
    }
    const auto end = fast.at(fast.duration());
    REQUIRE(end.p == dist);
    REQUIRE(end.v == v_end);
    REQUIRE(end.a == 0.0);
    check_limits(fast, d, start);
  }
}

namespace {

// Reference ramp (v0, a0) -> (vm, 0), written apart from the kernel from the textbook S-ramp
// between states at rest in acceleration (ref_ramp_time, mean velocity of its ends):
//  - the pulse continues the start's jerk (vm beyond v_zero against a0's sign, or a0 = 0):
//    release a0 first (time |a0|/J, to v_zero), then the S-ramp from v_zero to vm;
//  - else the start lies on the S-ramp from the virtual rest state v_b = v0 - a0|a0|/(2J)
//    (time-shifted by |a0|/J): the S-ramp from v_b minus its first |a0|/J seconds.
// Limit: A+ for a speeding-up pulse, A- for a slowing one (all velocities >= 0 here).
struct RefPiece {
  double t = 0.0;
  double s = 0.0;
};

RefPiece ref_ramp(double v0, double a0, double vm, const Dynamics& d) {
  const double j = d.j_max;
  const double v_zero = v0 + a0 * std::abs(a0) / (2.0 * j);
  const double up = vm >= v_zero ? 1.0 : -1.0;
  const double lim = up > 0.0 ? d.a_max : d.d_max;
  const auto s_ramp = [&](double va, double vb) {
    const double t = ref_ramp_time(std::abs(vb - va), lim, j);
    return RefPiece{t, 0.5 * (va + vb) * t};
  };
  const double tr = std::abs(a0) / j;
  if (up * a0 <= 0.0) {  // release, then the S-ramp from v_zero
    const RefPiece r = s_ramp(v_zero, vm);
    const double s_rel = v0 * tr + 0.5 * a0 * tr * tr + up * j * tr * tr * tr / 6.0;
    return RefPiece{tr + r.t, s_rel + r.s};
  }
  const double v_b = v0 - a0 * std::abs(a0) / (2.0 * j);  // virtual start at a = 0
  const RefPiece r = s_ramp(v_b, vm);
  const double s_head = v_b * tr + up * j * tr * tr * tr / 6.0;
  return RefPiece{r.t - tr, r.s - s_head};
}

// Largest distance within time t from (v0, a0) to (v1, 0) over the level vm (fine scan and
// golden-section refinement around the best point).
double ref_max_distance_state(double v0, double a0, double v1, double t, const Dynamics& d) {
  const auto dist = [&](double vm) {
    const RefPiece r1 = ref_ramp(v0, a0, vm, d);
    const RefPiece r2 = ref_ramp(vm, 0.0, v1, d);
    if (r1.t + r2.t > t) return -1e300;
    return r1.s + r2.s + vm * (t - r1.t - r2.t);
  };
  constexpr int kScan = 2048;
  double best_v = 0.0;
  double best = dist(0.0);
  for (int i = 1; i <= kScan; ++i) {
    const double v = d.v_max * i / kScan;
    if (dist(v) > best) {
      best = dist(v);
      best_v = v;
    }
  }
  double lo = std::max(0.0, best_v - d.v_max / kScan);
  double hi = std::min(d.v_max, best_v + d.v_max / kScan);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 200; ++i) {
    const double x1 = hi - g * (hi - lo);
    const double x2 = lo + g * (hi - lo);
    if (dist(x1) < dist(x2)) {
      lo = x1;
    } else {
      hi = x2;
    }
  }
  return std::max(best, dist(0.5 * (lo + hi)));
}

}  // namespace

TEST_CASE("time-optimal from moving starts with a != 0 toward the target matches the reference") {
  // Starts v0 >= 0 with a0 in the limits whose release keeps v >= 0 (v_zero >= 0), the target
  // ahead beyond the release-and-change distance (see below), arrival v1 >= 0: bisection on the
  // duration with the reference above (textbook S-ramps, time-shifted for the start acceleration).
  std::mt19937_64 rng(271828);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int n = 0; n < 1500; ++n) {
    const Dynamics d = random_dynamics(rng);
    const double v0 = d.v_max * unit(rng);
    const double a0 = (2.0 * unit(rng) - 1.0) * std::min(d.a_max, d.d_max);
    const double v_zero = v0 + a0 * std::abs(a0) / (2.0 * d.j_max);
    if (v_zero < 0.0 || v_zero > d.v_max) continue;
    const double v1 = unit(rng) < 0.5 ? 0.0 : d.v_max * unit(rng);
    const double dist = log_uniform(rng, 1e-4, 1e4);
    // The reference's feasibility ("the largest distance coverable in T reaches D") assumes a
    // shorter distance is coverable too, which holds where the level max(v_zero, v1) (release
    // the start acceleration, then change to v1) fits in D: every level between it and the
    // best one then fits with a cruise. Closer targets need two-peak profiles whose
    // acceleration does not return to 0 between the peaks (not built; docs/axes-profile.md).
    const double v_knee = std::max(v_zero, v1);
    const RefPiece knee1 = ref_ramp(v0, a0, v_knee, d);
    const RefPiece knee2 = ref_ramp(v_knee, 0.0, v1, d);
    if (knee1.s + knee2.s > dist) continue;
    Profile p;
    REQUIRE(ncsim::axes::plan_position(MotionState{0.0, v0, a0}, PositionTarget{dist, v1}, d, p,
                                       ProfileRule::time_optimal) == Result::ok);
    double lo = 0.0;
    double hi = p.duration() * 2.0 + 1e-9;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (ref_max_distance_state(v0, a0, v1, mid, d) >= dist ? hi : lo) = mid;
    }
    INFO("v0=", v0, " a0=", a0, " v1=", v1, " D=", dist, " V=", d.v_max, " A+=", d.a_max,
         " A-=", d.d_max, " J=", d.j_max, " t=", p.duration(), " t_ref=", hi);
    REQUIRE(p.duration() <= hi * (1.0 + 1e-9));
    const auto end = p.at(p.duration());
    REQUIRE(end.p == dist);
    REQUIRE(end.v == v1);
    REQUIRE(end.a == 0.0);
    check_limits(p, d, MotionState{0.0, v0, a0});
    ++checked;
  }
  CHECK(checked > 300);
}

TEST_CASE("the shared limit check flags every limit a profile exceeds, and only the start's part") {
  // axes/profile_limits_check.hpp must be able to fail: Dynamik 1.1 (V = 2000, A+ = A- = 5000,
  // J = 50000, 1000 mm) checked against limits just below its own.
  const Dynamics d{2000.0, 5000.0, 5000.0, 50000.0};
  Profile p;
  REQUIRE(ncsim::axes::plan_position(MotionState{}, PositionTarget{1000.0, 0.0}, d, p) ==
          Result::ok);
  CHECK(ncsim::test::profile_limit_violation(p, d, MotionState{}).empty());
  const auto flags = [&](Dynamics tighter, const char* what) {
    const std::string bad = ncsim::test::profile_limit_violation(p, tighter, MotionState{});
    INFO(what, ": ", bad);
    CHECK(bad.find(what) != std::string::npos);
  };
  flags(Dynamics{1999.0, 5000.0, 5000.0, 50000.0}, "|v|");
  flags(Dynamics{2000.0, 4999.0, 5000.0, 50000.0}, "|a|");  // speeding up: A+
  flags(Dynamics{2000.0, 5000.0, 4999.0, 50000.0}, "|a|");  // slowing down: A-
  flags(Dynamics{2000.0, 5000.0, 5000.0, 49999.0}, "J");
  // A start above V may exceed V only by what it forces: the same profile is fine from its
  // start at 2500 mm/s and flagged when the start is taken to be inside (1999 mm/s).
  const MotionState fast{0.0, 2500.0, 0.0};
  Profile q;
  REQUIRE(ncsim::axes::plan_position(fast, PositionTarget{3000.0, 0.0}, d, q) == Result::ok);
  CHECK(ncsim::test::profile_limit_violation(q, d, fast).empty());
  CHECK_FALSE(ncsim::test::profile_limit_violation(q, d, MotionState{0.0, 1999.0, 0.0}).empty());
}
