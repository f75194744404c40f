// Start states beyond the limits and velocity profiles from moving states
// (decision "limits first", docs/axes-profile.md).

#include <doctest/doctest.h>

#include <cmath>

#include "axes/profile.hpp"

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::Result;

TEST_CASE("a start above V brakes to V first, then reaches the target") {
  const Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  Profile p;
  REQUIRE(ncsim::axes::plan_position(MotionState{0.0, 1500.0, 0.0}, PositionTarget{3000.0, 0.0}, d,
                                     p) == Result::ok);
  CHECK(p.at(0.5).v == doctest::Approx(1000.0));
  for (double t = 0.0; t < p.duration(); t += 1e-3)
    CHECK(p.at(t).v <= 1500.0 + 1e-9);
  CHECK(p.at(p.duration()).p == 3000.0);
}

TEST_CASE("a start with acceleration beyond A+ first takes it back to A+ with J") {
  const Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  Profile p;
  REQUIRE(ncsim::axes::plan_position(MotionState{0.0, 100.0, 8000.0}, PositionTarget{2000.0, 0.0},
                                     d, p) == Result::ok);
  CHECK(p.phases()[0].j == -50000.0);
  CHECK(p.phases()[0].duration == doctest::Approx(3000.0 / 50000.0));
  CHECK(p.at(p.duration()).p == 2000.0);
}

TEST_CASE("a start moving away from the target stops and returns") {
  const Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  Profile p;
  REQUIRE(ncsim::axes::plan_position(MotionState{0.0, -500.0, 0.0}, PositionTarget{100.0, 0.0}, d,
                                     p) == Result::ok);
  double p_min = 0.0;
  for (double t = 0.0; t < p.duration(); t += 1e-3)
    p_min = std::min(p_min, p.at(t).p);
  CHECK(p_min < -10.0);
  CHECK(p.at(p.duration()).p == 100.0);
}

TEST_CASE("a velocity profile from a moving state reaches the target velocity with a = 0") {
  const Dynamics d{0.0, 2000.0, 3000.0, 750000.0};
  Profile p;
  REQUIRE(ncsim::axes::plan_velocity(MotionState{5.0, 100.0, 500.0}, 300.0, d, p) == Result::ok);
  const auto end = p.at(p.duration());
  CHECK(end.v == 300.0);
  CHECK(end.a == 0.0);
  CHECK(p.at(p.duration() + 1.0).p == doctest::Approx(end.p + 300.0));
  for (double t = 0.0; t < p.duration(); t += 1e-4)
    CHECK(p.at(t).a <= 2000.0 + 1e-9);
}

TEST_CASE("a stop from a moving state ends at rest") {
  const Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  Profile p;
  REQUIRE(ncsim::axes::plan_stop(MotionState{0.0, -800.0, -1000.0}, d, p) == Result::ok);
  CHECK(p.at(p.duration()).v == 0.0);
  CHECK(p.at(p.duration()).p < 0.0);
  CHECK(ncsim::axes::plan_stop(MotionState{0.0, NAN, 0.0}, d, p) == Result::error_invalid_input);
}
