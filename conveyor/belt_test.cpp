#include "conveyor/belt.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

namespace ncsim::conveyor {
namespace {

// Advances in 1 ms cycles to t and returns the state there.
BeltState run_to(Belt& b, double t) {
  while (b.time() + 1e-12 < t)
    b.advance(std::min(t, b.time() + 0.001));
  return b.state();
}

}  // namespace

TEST_CASE("encoder belt: constant velocity, a ramp to a stop, a restart and a step are exact") {
  // 300 mm/s, stop over 0.5 s at 1 s, restart over 0.5 s at 3 s, step to 150 mm/s at 5 s.
  Belt b =
      Belt::encoder(300.0, {{1.0, 0.0, 0.5}, {3.0, 300.0, 0.5}, {5.0, 150.0, 0.0}}, std::nullopt);
  BeltState s = run_to(b, 1.25);
  CHECK(s.v == doctest::Approx(150.0).epsilon(1e-12));
  CHECK(s.a == doctest::Approx(-600.0).epsilon(1e-12));
  CHECK(s.p == doctest::Approx(356.25).epsilon(1e-12));  // 300 + 75 - 18.75
  s = run_to(b, 2.0);
  CHECK(s.v == 0.0);
  CHECK(s.p == doctest::Approx(375.0).epsilon(1e-12));  // stopped: stays
  s = run_to(b, 4.0);
  CHECK(s.v == 300.0);
  CHECK(s.p == doctest::Approx(600.0).epsilon(1e-12));  // 375 + 75 + 150
  s = run_to(b, 6.0);
  CHECK(s.v == 150.0);  // the step
  CHECK(s.p == doctest::Approx(1050.0).epsilon(1e-12));
}

TEST_CASE("encoder belt before t = 0 moves at its start velocity (the delay line's past)") {
  Belt b = Belt::encoder(300.0, {}, std::nullopt);
  CHECK(b.base(-0.5).p == doctest::Approx(-150.0));
  CHECK(b.base(-0.5).v == 300.0);
}

TEST_CASE(
    "spindle belt: MC_MoveVelocity ramps jerk-limited, Acceleration 2000 mm/s^2, Jerk "
    "750000 mm/s^3 (PROG-208363915 units)") {
  Belt b = Belt::spindle(std::nullopt);
  run_to(b, 0.1);
  CHECK(b.state().v == 0.0);
  b.command(300.0, VelocityDynamics{2000.0, 2000.0, 750000.0});
  const double t_ramp = 300.0 / 2000.0 + 2000.0 / 750000.0;  // 0.15267 s
  BeltState s = run_to(b, 0.1 + 0.08);
  CHECK(s.a == doctest::Approx(2000.0));  // the constant-acceleration phase
  s = run_to(b, 1.1);
  CHECK(s.v == 300.0);
  CHECK(s.a == 0.0);
  // A symmetric S-ramp from rest covers v t_ramp / 2.
  CHECK(s.p == doctest::Approx(300.0 * (1.0 - t_ramp) + 300.0 * t_ramp / 2.0).epsilon(1e-9));
  // Stop: deceleration with the same dynamics.
  b.command(0.0, VelocityDynamics{2000.0, 1000.0, 750000.0});
  s = run_to(b, 1.1 + 0.1);
  CHECK(s.a == doctest::Approx(-1000.0));
  s = run_to(b, 2.0);
  CHECK(s.v == 0.0);
}

TEST_CASE(
    "spindle belt: a command during a ramp starts from the current velocity and "
    "acceleration") {
  Belt b = Belt::spindle(std::nullopt);
  b.command(300.0, VelocityDynamics{2000.0, 2000.0, 750000.0});
  run_to(b, 0.05);
  const BeltState before = b.state();
  b.command(100.0, VelocityDynamics{2000.0, 2000.0, 750000.0});
  const BeltState after = run_to(b, 0.051);
  // Continuous: the velocity goes on rising from where it was, the acceleration is reduced.
  CHECK(after.v > before.v);
  CHECK(after.v < before.v + 0.001 * before.a);
  CHECK(after.a < before.a);
  run_to(b, 1.0);
  CHECK(b.state().v == 100.0);
}

TEST_CASE("fluctuation: v = v0 (1 + A sin 2 pi f t), travel v0 t + v0 A (1 - cos) / w") {
  const scenario::BeltFluctuation f{0.05, 1.0};
  Belt b = Belt::encoder(300.0, {}, f);
  const double w = 2.0 * std::numbers::pi;
  for (const double t : {0.25, 0.6, 1.3}) {
    const BeltState s = run_to(b, t);
    CAPTURE(t);
    CHECK(s.v == doctest::Approx(300.0 * (1.0 + 0.05 * std::sin(w * t))).epsilon(1e-12));
    CHECK(s.a == doctest::Approx(300.0 * 0.05 * w * std::cos(w * t)).epsilon(1e-9));
    CHECK(s.p ==
          doctest::Approx(300.0 * t + 300.0 * 0.05 * (1.0 - std::cos(w * t)) / w).epsilon(1e-12));
  }
}

TEST_CASE("fluctuation keeps a stopped belt stopped") {
  Belt b = Belt::encoder(300.0, {{0.5, 0.0, 0.0}}, scenario::BeltFluctuation{0.1, 2.0});
  const double p = run_to(b, 1.0).p;
  CHECK(run_to(b, 2.0).p == doctest::Approx(p).epsilon(1e-12));
  CHECK(b.state().v == 0.0);
}

}  // namespace ncsim::conveyor
