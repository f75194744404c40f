// Online changes of seed 002_* 2.2 to 2.5 and the velocity motion, through SetpointGenerator.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "axes/profile_generator.hpp"

namespace {

using ncsim::axes::CompensationRequest;
using ncsim::axes::GeneratorConfig;
using ncsim::axes::MoveDirection;
using ncsim::axes::OverrideType;
using ncsim::axes::Result;
using ncsim::axes::SetpointGenerator;
using ncsim::axes::VelocityCommand;

constexpr double kCycle = 1e-3;  // [s]

GeneratorConfig config(OverrideType type = OverrideType::reduced_iterated) {
  GeneratorConfig c;
  c.dynamics = {2000.0, 5000.0, 5000.0, 50000.0};
  c.v_axis_max = 3000.0;
  c.override_type = type;
  return c;
}

// Steps until finished (or the cycle budget runs out); returns the number of cycles.
int run(SetpointGenerator& g, int max_cycles, double* v_peak = nullptr) {
  for (int i = 1; i <= max_cycles; ++i) {
    const Result r = g.step(kCycle);
    if (v_peak != nullptr) *v_peak = std::max(*v_peak, std::abs(g.setpoint().v));
    if (r == Result::finished) return i;
  }
  return -1;
}

void steps(SetpointGenerator& g, int n) {
  for (int i = 0; i < n; ++i)
    g.step(kCycle);
}

}  // namespace

TEST_CASE("a position start runs the 7-phase profile and finishes at rest on the target") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(1000.0) == Result::ok);
  const int cycles = run(g, 5000);
  CHECK(cycles == 1000);  // Dynamik 1.1: 1.0 s
  CHECK(g.setpoint().p == 1000.0);
  CHECK(g.setpoint().v == 0.0);
  CHECK_FALSE(g.moving());
}

TEST_CASE("configuration errors throw naming the parameter") {
  GeneratorConfig c = config();
  c.dynamics.a_max = -1.0;
  CHECK_THROWS_WITH_AS(SetpointGenerator{c}, doctest::Contains("a_max (A+)"),
                       std::invalid_argument);
}

TEST_CASE("a start above the axis velocity limit is rejected") {
  SetpointGenerator g(config());
  CHECK(g.start_position(1000.0, 5000.0) == Result::error_velocity_limit);
  CHECK_FALSE(g.moving());
}

TEST_CASE("a move shorter than one encoder increment does not start") {
  SetpointGenerator g(config());
  CHECK(g.start_position(0.00001) == Result::ignored_below_increment);
}

TEST_CASE("override 75 % lowers the cruise velocity with the same ramps, 100 % restores it") {
  // 002_* 2.2, figure "Overrideänderungen: Startoverride 100% -> 75% -> 100% (V = 2000.0 mm/s,
  // von 0.0 mm auf 5000.0 mm)" (seed text l.383): 2000 -> 1500 -> 2000 mm/s. The new level is
  // reached from above without undershoot and with a = 0 on arrival ("instantaner Override",
  // l.346: the new level as fast as the limits allow).
  SetpointGenerator g(config());
  REQUIRE(g.start_position(5000.0) == Result::ok);
  steps(g, 1000);
  CHECK(g.setpoint().v == doctest::Approx(2000.0));
  REQUIRE(g.set_override(0.75) == Result::ok);
  double v_low = 2000.0;
  for (int i = 0; i < 400; ++i) {
    g.step(kCycle);
    v_low = std::min(v_low, g.setpoint().v);
  }
  CHECK(v_low >= 1500.0 * (1.0 - 1e-12));
  CHECK(g.setpoint().v == doctest::Approx(1500.0));
  CHECK(std::abs(g.setpoint().a) <= 1e-9 * 5000.0);
  REQUIRE(g.set_override(1.0) == Result::ok);
  double v_peak = 0.0;
  CHECK(run(g, 10000, &v_peak) > 0);
  CHECK(v_peak == doctest::Approx(2000.0));
  CHECK(g.setpoint().p == 5000.0);
}

TEST_CASE("override 0 stops and keeps the target; turning it up resumes") {
  SetpointGenerator g(config());
  REQUIRE(g.set_override(0.2) == Result::ok);
  REQUIRE(g.start_position(5000.0) == Result::ok);
  steps(g, 500);
  CHECK(g.setpoint().v == doctest::Approx(400.0));
  REQUIRE(g.set_override(0.0) == Result::ok);
  steps(g, 500);
  CHECK(g.setpoint().v == 0.0);
  CHECK(g.moving());
  REQUIRE(g.set_override(1.0) == Result::ok);
  CHECK(run(g, 10000) > 0);
  CHECK(g.setpoint().p == 5000.0);
}

TEST_CASE("override in the braking phase is ignored and the old profile kept") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(1000.0) == Result::ok);
  steps(g, 700);  // braking starts at 0.5 s
  CHECK(g.in_braking_phase());
  CHECK(g.set_override(0.5) == Result::ignored_braking_phase);
  CHECK(run(g, 1000) == 300);
}

TEST_CASE("override types: Reduced refers to the reduced level, Original to the command") {
  // 000_* 7.5.6: 2000 mm/s over 800 mm is reduced to 1765.56 mm/s (Dynamik 3.3).
  for (const auto type : {OverrideType::reduced_iterated, OverrideType::original_iterated}) {
    SetpointGenerator g(config(type));
    REQUIRE(g.start_position(800.0) == Result::ok);
    steps(g, 50);
    REQUIRE(g.set_override(0.8) == Result::ok);
    double v_peak = 0.0;
    CHECK(run(g, 5000, &v_peak) > 0);
    if (type == OverrideType::reduced_iterated) {
      CHECK(v_peak == doctest::Approx(0.8 * 1765.5644).epsilon(1e-4));
    } else {
      CHECK(v_peak == doctest::Approx(0.8 * 2000.0).epsilon(1e-4));  // 1600 < 1765: reached
    }
  }
}

TEST_CASE("stop has priority: other requests are rejected until the axis stands") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(5000.0) == Result::ok);
  steps(g, 1000);
  REQUIRE(g.stop() == Result::ok);
  CHECK(g.set_override(1.0) == Result::rejected_stopping);
  CHECK(g.new_end_position(6000.0) == Result::rejected_stopping);
  const int cycles = run(g, 2000);
  CHECK(cycles == 500);  // 2000 mm/s down with A- = 5000, J = 50000: 0.5 s
  CHECK(g.setpoint().v == 0.0);
  CHECK_FALSE(g.moving());
}

TEST_CASE("emergency stop takes larger deceleration and jerk and brakes faster") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(5000.0) == Result::ok);
  steps(g, 1000);
  REQUIRE(g.emergency_stop(20000.0, 400000.0) == Result::ok);
  CHECK(run(g, 2000) < 500);
}

TEST_CASE("new end position further on, in the stop phase: the axis restarts to it") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(3000.0) == Result::ok);
  steps(g, 1800);  // braking toward 3000
  REQUIRE(g.new_end_position(5000.0) == Result::ok);
  CHECK(run(g, 10000) > 0);
  CHECK(g.setpoint().p == 5000.0);
}

TEST_CASE("new end position behind the axis: stop, then return") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(3000.0) == Result::ok);
  steps(g, 1400);
  const double p_now = g.setpoint().p;
  REQUIRE(p_now > 2000.0);
  REQUIRE(g.new_end_position(2000.0) == Result::ok);
  double p_max = p_now;
  for (int i = 0; i < 10000 && g.step(kCycle) != Result::finished; ++i) {
    p_max = std::max(p_max, g.setpoint().p);
  }
  CHECK(p_max > p_now);  // it kept going forward while braking
  CHECK(g.setpoint().p == 2000.0);
}

TEST_CASE("new velocity and end position: new velocity only after the activation position") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(5000.0, 1000.0) == Result::ok);
  steps(g, 600);
  REQUIRE(g.new_velocity_and_end_position(2000.0, 6000.0, 2000.0) == Result::ok);  // case 1
  double v_before = 0.0;
  double v_after = 0.0;
  for (int i = 0; i < 20000 && g.step(kCycle) != Result::finished; ++i) {
    const double v = g.setpoint().v;
    (g.setpoint().p < 2000.0 ? v_before : v_after) =
        std::max(v, g.setpoint().p < 2000.0 ? v_before : v_after);
  }
  CHECK(v_before == doctest::Approx(1000.0));
  CHECK(v_after == doctest::Approx(2000.0));
  CHECK(g.setpoint().p == 6000.0);
}

TEST_CASE("new velocity and end position: activation position passed means at once") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(5000.0, 1000.0) == Result::ok);
  steps(g, 1000);
  REQUIRE(g.new_velocity_and_end_position(1500.0, 6000.0, 100.0) == Result::ok);  // case 2
  steps(g, 400);
  CHECK(g.setpoint().v == doctest::Approx(1500.0));
}

TEST_CASE("new velocity and end position behind the axis: return with the old velocity") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(5000.0, 1000.0) == Result::ok);
  steps(g, 2000);
  REQUIRE(g.new_velocity_and_end_position(1800.0, 500.0, 300.0) == Result::ok);  // case 5
  double v_min = 0.0;
  for (int i = 0; i < 20000 && g.step(kCycle) != Result::finished; ++i) {
    v_min = std::min(v_min, g.setpoint().v);
  }
  CHECK(v_min == doctest::Approx(-1000.0));
  CHECK(g.setpoint().p == 500.0);
}

TEST_CASE("full compensation adds D = 250 mm over L = 5000 mm: end position 10250") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(10000.0) == Result::ok);
  steps(g, 600);
  const CompensationRequest req{5000.0, 250.0, 2000.0, 300.0, 500.0, 1000.0};
  REQUIRE(g.start_compensation(req) == Result::ok);
  CHECK(g.compensation_difference() == doctest::Approx(250.0));
  CHECK(g.new_end_position(9000.0) == Result::rejected_compensation_active);
  CHECK(g.start_compensation(req) == Result::rejected_compensation_active);
  double v_prev = g.setpoint().v;
  double dv_max = 0.0;
  for (int i = 0; i < 20000 && g.step(kCycle) != Result::finished; ++i) {
    dv_max = std::max(dv_max, std::abs(g.setpoint().v - v_prev));
    v_prev = g.setpoint().v;
  }
  CHECK(dv_max < 10.0);  // velocity continuous (about 5 mm/s per cycle at most)
  CHECK(g.setpoint().p == doctest::Approx(10250.0));
}

TEST_CASE("negative compensation: end position 9750") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(10000.0) == Result::ok);
  steps(g, 600);
  REQUIRE(g.start_compensation({5000.0, -250.0, 2000.0, 300.0, 500.0, 1000.0}) == Result::ok);
  CHECK(run(g, 20000) > 0);
  CHECK(g.setpoint().p == doctest::Approx(9750.0));
}

TEST_CASE("an infeasible compensation is reduced to the maximum possible") {
  // 002_* 2.5 "Partielle Kompensation": VK = 500, L = 2000, D = 500. Closed form: 166.67 mm
  // (the manual's figure reads 10165.0; see docs/axes-profile.md).
  SetpointGenerator g(config());
  REQUIRE(g.start_position(10000.0) == Result::ok);
  steps(g, 600);
  REQUIRE(g.start_compensation({2000.0, 500.0, 2000.0, 500.0, 500.0, 1000.0}) == Result::ok);
  CHECK(g.compensation_difference() == doctest::Approx(500.0 / 3.0));
  CHECK(run(g, 20000) > 0);
  CHECK(g.setpoint().p == doctest::Approx(10000.0 + 500.0 / 3.0));
}

TEST_CASE("compensation stop keeps what was compensated and ramps the overspeed down") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position(10000.0) == Result::ok);
  steps(g, 600);
  REQUIRE(g.start_compensation({5000.0, 250.0, 2000.0, 300.0, 500.0, 1000.0}) == Result::ok);
  steps(g, 300);
  REQUIRE(g.stop_compensation() == Result::ok);
  const double d = g.compensation_difference();
  CHECK(d > 0.0);
  CHECK(d < 250.0);
  CHECK(run(g, 20000) > 0);
  CHECK(g.setpoint().p == doctest::Approx(10000.0 + d));
}

TEST_CASE("MC_MoveVelocity runs endlessly at Velocity in um/s, direction 3 is negative") {
  SetpointGenerator g(config());
  VelocityCommand cmd;
  cmd.velocity = 300.0;  // [mm/s]
  cmd.acceleration = 2000.0;
  cmd.deceleration = 2000.0;
  cmd.jerk = 750000.0;
  cmd.direction = MoveDirection::negative;
  REQUIRE(g.start_velocity(cmd) == Result::ok);
  int cycles = run(g, 5000);
  CHECK(cycles > 0);
  CHECK(g.setpoint().v == doctest::Approx(-300.0));
  const double p0 = g.setpoint().p;
  steps(g, 1000);
  CHECK(g.setpoint().p == doctest::Approx(p0 - 300.0));
  CHECK(g.moving());
  cmd.direction = MoveDirection::positive;  // reversal: stop with A-, then speed up with A+
  REQUIRE(g.start_velocity(cmd) == Result::ok);
  cycles = run(g, 5000);
  CHECK(g.setpoint().v == doctest::Approx(300.0));
  cmd.direction = MoveDirection::current;
  cmd.velocity = 100.0;
  REQUIRE(g.start_velocity(cmd) == Result::ok);
  run(g, 5000);
  CHECK(g.setpoint().v == doctest::Approx(100.0));
  REQUIRE(g.stop() == Result::ok);
  CHECK(run(g, 5000) > 0);
  CHECK(g.setpoint().v == 0.0);
}

TEST_CASE("a position start arriving with a velocity continues at it (sync-in, FEED_CONT)") {
  SetpointGenerator g(config());
  REQUIRE(g.start_position_moving(500.0, 300.0) == Result::ok);
  CHECK(run(g, 5000) > 0);
  // finished in the first cycle at or after the arrival: at most one cycle of 300 mm/s later
  CHECK(std::abs(g.setpoint().p - 500.0) <= 300.0 * kCycle);
  CHECK(g.setpoint().v == doctest::Approx(300.0));
  const double p_arrival = g.setpoint().p;
  steps(g, 100);
  CHECK(g.setpoint().p == doctest::Approx(p_arrival + 30.0));
}
