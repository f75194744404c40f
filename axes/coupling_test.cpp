#include "axes/coupling.hpp"

#include <doctest/doctest.h>

#include <cmath>

#include "axes/control.hpp"

namespace ncsim::axes {
namespace {

constexpr double kT = 0.001;  // [s]
const Dynamics kDynamics{2000.0, 10000.0, 10000.0, 200000.0};

// The master of the manual's figures: a PTP positioning from 0 to `target` at V = 2000 mm/s.
Profile master_move(double target) {
  Profile profile;
  REQUIRE(plan_position(MotionState{}, PositionTarget{target, 0.0}, kDynamics, profile) ==
          Result::ok);
  return profile;
}

TEST_CASE("a coupled slave follows factor x master + offset, also with a negative factor") {
  const Profile master = master_move(2000.0);
  SlaveAxis slave(kDynamics, 100.0);
  REQUIRE(slave.couple(master.at(0.0), -0.5) == CouplingResult::ok);
  CHECK(slave.coupled());
  CHECK(slave.coupling()->offset == doctest::Approx(100.0));
  for (int k = 1; k <= 1500; ++k) {
    const Setpoint m = master.at(k * kT);
    const Setpoint s = slave.step(m, kT);
    CHECK(s.p == doctest::Approx(-0.5 * m.p + 100.0));
    CHECK(s.v == doctest::Approx(-0.5 * m.v));
    CHECK(s.a == doctest::Approx(-0.5 * m.a));
  }
}

TEST_CASE("coupling needs a non-zero factor and both axes at rest") {
  const Profile master = master_move(2000.0);
  SlaveAxis slave(kDynamics, 0.0);
  CHECK(slave.couple(master.at(0.0), 0.0) == CouplingResult::error_zero_factor);
  CHECK(slave.couple(master.at(0.3), 1.0) == CouplingResult::error_not_at_rest);
  CHECK(slave.set_factor(master.at(0.0), 2.0) == CouplingResult::error_not_coupled);
  CHECK(slave.decouple() == CouplingResult::error_not_coupled);
  REQUIRE(slave.couple(master.at(0.0), 1.0) == CouplingResult::ok);
  CHECK(slave.stop() == CouplingResult::error_coupled);
  CHECK(slave.move_position(5.0) == CouplingResult::error_coupled);
  CHECK(slave.set_factor(master.at(0.0), 0.0) == CouplingResult::error_zero_factor);
  CHECK(diagnostic_id(CouplingResult::error_zero_factor) == "NC5520");
}

TEST_CASE("an online factor change keeps the slave position and switches its velocity") {
  // 002_* 3.2.2 figure: factor -0.7, then -0.8.
  const Profile master = master_move(2000.0);
  SlaveAxis slave(kDynamics, 0.0);
  REQUIRE(slave.couple(master.at(0.0), -0.7) == CouplingResult::ok);
  Setpoint before;
  const int k_switch = 700;
  for (int k = 1; k <= k_switch; ++k)
    before = slave.step(master.at(k * kT), kT);
  REQUIRE(slave.set_factor(master.at(k_switch * kT), -0.8) == CouplingResult::ok);
  const Setpoint m = master.at((k_switch + 1) * kT);
  const Setpoint after = slave.step(m, kT);
  // The position moves on by one cycle of the new velocity, without a jump.
  CHECK(after.p - before.p ==
        doctest::Approx(-0.8 * (m.p - master.at(k_switch * kT).p)).epsilon(1e-9));
  CHECK(after.v == doctest::Approx(-0.8 * m.v));
  // Sign change: the slave reverses.
  REQUIRE(slave.set_factor(m, 0.8) == CouplingResult::ok);
  CHECK(slave.step(master.at((k_switch + 2) * kT), kT).v > 0.0);
}

// Largest cycle-to-cycle jumps of the set values across a decoupling.
void check_continuous(const Setpoint& a, const Setpoint& b) {
  // One cycle apart: position moves with the velocity, velocity with the acceleration,
  // acceleration with at most the jerk J.
  CHECK(std::fabs(b.p - a.p - 0.5 * (a.v + b.v) * kT) < 1e-3);
  CHECK(std::fabs(b.v - a.v) <= std::fabs(a.a) * kT + kDynamics.j_max * kT * kT + 1e-9);
  CHECK(std::fabs(b.a - a.a) <= kDynamics.j_max * kT + 1e-6);
}

TEST_CASE("online decoupling at constant velocity: the slave carries on, then stops alone") {
  // 002_* 3.2.3 figure: master 0 -> 20000 mm at 2000 mm/s, slave factor 0.5, online
  // decoupling, slave stop, then master stop.
  const Profile master = master_move(20000.0);
  SlaveAxis slave(kDynamics, 0.0);
  REQUIRE(slave.couple(master.at(0.0), 0.5) == CouplingResult::ok);
  Setpoint last;
  int k = 1;
  for (; k <= 2000; ++k)
    last = slave.step(master.at(k * kT), kT);
  REQUIRE(last.v == doctest::Approx(1000.0));
  REQUIRE(slave.decouple() == CouplingResult::ok);
  CHECK_FALSE(slave.coupled());
  // Carries on at 1000 mm/s, whatever the master does.
  for (int i = 0; i < 500; ++i, ++k) {
    const Setpoint s = slave.step(Setpoint{}, kT);
    check_continuous(last, s);
    CHECK(s.v == doctest::Approx(1000.0));
    last = s;
  }
  REQUIRE(slave.stop() == CouplingResult::ok);
  for (int i = 0; i < 1000; ++i, ++k) {
    const Setpoint s = slave.step(Setpoint{}, kT);
    check_continuous(last, s);
    last = s;
  }
  CHECK_FALSE(slave.moving());
  CHECK(last.v == 0.0);
  CHECK(master.at(k * kT).v == doctest::Approx(2000.0));  // the master moves on
}

TEST_CASE("decoupling while the master accelerates keeps position, velocity, acceleration") {
  const Profile master = master_move(20000.0);
  SlaveAxis slave(kDynamics, 0.0);
  REQUIRE(slave.couple(master.at(0.0), -0.8) == CouplingResult::ok);
  Setpoint last;
  for (int k = 1; k <= 100; ++k)
    last = slave.step(master.at(k * kT), kT);
  REQUIRE(std::fabs(last.a) > 1000.0);
  REQUIRE(slave.decouple() == CouplingResult::ok);
  for (int i = 0; i < 300; ++i) {
    const Setpoint s = slave.step(Setpoint{}, kT);
    check_continuous(last, s);
    last = s;
  }
  CHECK(last.a == doctest::Approx(0.0));
  // Then a new end position in the direction of motion, reached at rest.
  const double target = last.p - 500.0;
  REQUIRE(slave.move_position(target) == CouplingResult::ok);
  for (int i = 0; i < 5000 && slave.moving(); ++i) {
    const Setpoint s = slave.step(Setpoint{}, kT);
    check_continuous(last, s);
    last = s;
  }
  CHECK(last.p == doctest::Approx(target));
  CHECK(last.v == doctest::Approx(0.0));
}

TEST_CASE("decoupling at standstill leaves the slave at rest") {
  SlaveAxis slave(kDynamics, 7.0);
  REQUIRE(slave.couple(Setpoint{3.0, 0, 0, 0}, 2.0) == CouplingResult::ok);
  REQUIRE(slave.decouple() == CouplingResult::ok);
  CHECK(slave.step(Setpoint{}, kT).p == 7.0);
  CHECK_FALSE(slave.moving());
  REQUIRE(slave.move_velocity(50.0) == CouplingResult::ok);
  for (int i = 0; i < 1000; ++i)
    slave.step(Setpoint{}, kT);
  CHECK(slave.setpoint().v == doctest::Approx(50.0));
}

TEST_CASE("a slave of an encoder axis inherits the encoder noise") {
  EncoderAxisParams params;
  params.noise_amplitude = 0.01;
  params.noise_seed = 3;
  EncoderAxis encoder(params, kT, 0.0);
  SlaveAxis slave(kDynamics, 10.0);
  REQUIRE(slave.couple(encoder.value(), 2.0) == CouplingResult::ok);
  bool noisy = false;
  for (int k = 1; k <= 200; ++k) {
    const Setpoint m = encoder.step(100.0 * kT * k);
    const Setpoint s = slave.step(m, kT);
    CHECK(s.p == doctest::Approx(2.0 * m.p + 10.0));
    if (std::fabs(s.p - (2.0 * 100.0 * kT * k + 10.0)) > 1e-6) noisy = true;
  }
  CHECK(noisy);
}

}  // namespace
}  // namespace ncsim::axes
