// Prescribed durations from any start (plan_position_of_duration: the single-peak family in
// either frame, a turn on the way to an arrival velocity), time-synchronised axes across a
// gap in an axis's feasible durations, and moving targets that need a turn
// (docs/axes-profile.md, "Prescribed durations, synchronised axes, moving targets").

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "axes/profile.hpp"
#include "jerk/jerk.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;
using ncsim::axes::Result;

using ncsim::test::log_uniform;

// Path limits on a grid: |v| <= V, A+ where the acceleration speeds the motion up, A- where it
// slows it down (beyond them only what the start forces), |j| = J in every jerk phase.
void check_path_limits(const Profile& p, const Dynamics& d, const MotionState& start) {
  for (int k = 0; k <= 200; ++k) {
    const auto sp = p.at(p.duration() * k / 200.0);
    REQUIRE(std::abs(sp.v) <= std::max(d.v_max, std::abs(start.v)) * (1.0 + 1e-9));
    const double cap = (sp.v * sp.a > 0.0 ? d.a_max : d.d_max) * (1.0 + 1e-9) + 1e-9;
    REQUIRE(std::abs(sp.a) <= std::max(cap, std::abs(start.a) * (1.0 + 1e-9)));
  }
  for (const auto& ph : p.phases())
    REQUIRE((ph.j == 0.0 || std::abs(std::abs(ph.j) - d.j_max) <= 1e-12 * d.j_max));
}

void check_exact(const Profile& p, const PositionTarget& target, double duration) {
  REQUIRE(std::abs(p.duration() - duration) <= 1e-9 * duration);
  const auto end = p.at(p.duration());
  REQUIRE(end.p == target.p);
  REQUIRE(end.v == target.v);
  REQUIRE(end.a == 0.0);
}

}  // namespace

TEST_CASE("a duration of a lower interval of levels is met, not NC5015") {
  // The feasible levels of the single-peak family form two intervals here (jerk's
  // stretch_scan, jerk/move_duration_test.cpp): 0.049766 s lies in the lower one, around
  // v1 = 1.074 mm/s. Before: error_not_synchronizable (NC5015).
  const Dynamics d{0x1.1d4dc12cfe2c2p+1, 0x1.9018ea2a1e8d2p+4, 0x1.88cd4f356d4efp+12,
                   0x1.c12deebe7f7a5p+6};
  const MotionState start{0.0, 0x1.1e9014d68625dp+0, -0x1.0bef59a708025p+0};
  const PositionTarget target{0x1.bd61c67b785eap-5, 0x1.1306a06c69872p+0};
  const double duration = 0x1.97ae32a3972cbp-5;
  Profile p;
  REQUIRE(ncsim::axes::plan_position_of_duration(start, target, d, duration, p) == Result::ok);
  check_exact(p, target, duration);
  check_path_limits(p, d, start);
}

TEST_CASE("a prescribed duration overshoots a target at rest the start cannot stop before") {
  // 1000 mm/s toward a target 1 mm away, to be met at rest after 10 s (was NC5015).
  const Dynamics d{1000.0, 1000.0, 1000.0, 1e4};
  const MotionState start{0.0, 1000.0, 0.0};
  const PositionTarget target{1.0, 0.0};
  Profile p;
  REQUIRE(ncsim::axes::plan_position_of_duration(start, target, d, 10.0, p) == Result::ok);
  check_exact(p, target, 10.0);
  check_path_limits(p, d, start);
  double p_max = 0.0;
  for (double t = 0.0; t < 10.0; t += 1e-3)
    p_max = std::max(p_max, p.at(t).p);
  CHECK(p_max > 500.0);  // the stop alone takes 1.1 s and 600 mm
}

TEST_CASE("a prescribed duration from a start moving away turns without stopping") {
  // Moving away at 500 mm/s from the target: the fastest turns through
  // v = 0; 1.5x and 3x its duration lower the return level.
  const Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  const MotionState start{0.0, -500.0, 0.0};
  for (const PositionTarget target :
       {PositionTarget{100.0, 0.0}, PositionTarget{100.0, 300.0}, PositionTarget{-20.0, 300.0}}) {
    Profile fastest;
    REQUIRE(ncsim::axes::plan_position(start, target, d, fastest, ProfileRule::time_optimal) ==
            Result::ok);
    for (const double k : {1.0, 1.5, 3.0}) {
      INFO("p1=", target.p, " v1=", target.v, " k=", k);
      Profile p;
      REQUIRE(ncsim::axes::plan_position_of_duration(start, target, d, k * fastest.duration(), p) ==
              Result::ok);
      check_exact(p, target, k * fastest.duration());
      check_path_limits(p, d, start);
    }
  }
}

TEST_CASE(
    "prescribed durations from random starts: exact, within the limits, NC5015 only in a gap") {
  // Starts v0 in [-V, V] (a0 inside the path limits), targets either side, arrival velocities
  // of either sign; durations 1..3x the fastest. NC5015 only where the duration lies in a gap
  // (beyond a range of the single-peak family, below the next range or the fastest turn), and
  // next_feasible_duration then names a duration that is feasible.
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int solved = 0;
  int gaps = 0;
  const int cases = 4000;
  for (int n = 0; n < cases; ++n) {
    const Dynamics d{log_uniform(rng, 1.0, 1e4), log_uniform(rng, 10.0, 1e5),
                     log_uniform(rng, 10.0, 1e5), log_uniform(rng, 1e2, 1e7)};
    const double v0 = d.v_max * (2.0 * unit(rng) - 1.0);
    const double s0 = v0 >= 0.0 ? 1.0 : -1.0;
    const double a0 = unit(rng) < 0.5
                          ? 0.0
                          : -s0 * std::min(d.d_max, std::sqrt(2.0 * d.j_max * std::abs(v0))) *
                                unit(rng);  // slowing, its release keeps the direction
    const double dist = (unit(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 1e-4, 1e4);
    const double v1 = unit(rng) < 0.4 ? 0.0 : d.v_max * (2.0 * unit(rng) - 1.0);
    const MotionState start{0.0, v0, a0};
    const PositionTarget target{dist, v1};
    Profile fastest;
    REQUIRE(ncsim::axes::plan_position(start, target, d, fastest, ProfileRule::time_optimal) ==
            Result::ok);
    const double duration = fastest.duration() * (1.0 + 2.0 * unit(rng));
    INFO("v0=", v0, " a0=", a0, " p1=", dist, " v1=", v1, " T=", duration, " V=", d.v_max,
         " A+=", d.a_max, " A-=", d.d_max, " J=", d.j_max);
    Profile p;
    const Result r = ncsim::axes::plan_position_of_duration(start, target, d, duration, p);
    if (r == Result::error_not_synchronizable) {
      const double t_resume = ncsim::axes::next_feasible_duration(start, target, d, duration);
      REQUIRE(t_resume > duration);
      REQUIRE(ncsim::axes::plan_position_of_duration(start, target, d, t_resume, p) == Result::ok);
      check_exact(p, target, t_resume);
      check_path_limits(p, d, start);
      ++gaps;
      continue;
    }
    REQUIRE(r == Result::ok);
    check_exact(p, target, duration);
    check_path_limits(p, d, start);
    ++solved;
  }
  MESSAGE("solved ", solved, ", in a gap ", gaps);
  CHECK(solved > cases * 9 / 10);  // 3971 exact, 29 in a gap
}

TEST_CASE("synchronised axes skip a duration in an axis's gap: all meet at its fastest turn") {
  // X at 800 mm/s, 40 mm behind its target to be met at 800 mm/s: the cruise takes 0.05 s, a
  // dip below 800 at most ~0.6 % longer, and every slower profile turns round (0.8 s). Y needs
  // 0.3 s: no X profile takes 0.3 s, so both take X's fastest turn.
  const Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  const std::array<MotionState, 2> starts{MotionState{0.0, 800.0, 0.0}, MotionState{}};
  const std::array<PositionTarget, 2> targets{PositionTarget{40.0, 800.0},
                                              PositionTarget{150.0, 0.0}};
  const std::array<Dynamics, 2> dyn{d, d};
  std::array<Profile, 2> out;
  Profile y;
  REQUIRE(ncsim::axes::plan_position(starts[1], targets[1], d, y) == Result::ok);
  REQUIRE(y.duration() > 0.1);
  CHECK(ncsim::axes::plan_position_of_duration(starts[0], targets[0], d, y.duration(), out[0]) ==
        Result::error_not_synchronizable);
  REQUIRE(ncsim::axes::plan_synchronized(starts, targets, dyn, ProfileRule::manual, 0.0, out) ==
          Result::ok);
  const double t_turn = ncsim::axes::next_feasible_duration(starts[0], targets[0], d, y.duration());
  CHECK(t_turn == doctest::Approx(0.8).epsilon(1e-9));
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(out[i].duration() == doctest::Approx(t_turn).epsilon(1e-12));
    check_exact(out[i], targets[i], out[i].duration());
    check_path_limits(out[i], d, starts[i]);
  }
}

TEST_CASE("a moving target just ahead and faster is met by turning or dipping, not NC5015") {
  // X at 18.188 mm moving at 223 mm/s, the target 38.8 mm behind at 328.111 mm/s (the conveyor
  // catch-up case of tracking/catch_up_test.cpp, NC5015 before).
  const Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  const MotionState start{18.188, 223.002, 0.0};
  Profile p;
  double t_meet = 0.0;
  REQUIRE(ncsim::axes::plan_moving_target(start, -20.609, 328.111, d, p, t_meet) == Result::ok);
  const auto end = p.at(t_meet);
  CHECK(end.p == doctest::Approx(-20.609 + 328.111 * t_meet).epsilon(1e-12));
  CHECK(end.v == 328.111);
  CHECK(end.a == 0.0);
  check_path_limits(p, d, start);
}
