#include "axes/homing.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "axes/control.hpp"

namespace ncsim::axes {
namespace {

constexpr double kT = 0.001;  // [s]

// A machine with a referencing cam over [cam_lo, cam_hi] and a zero pulse at sync_at (physical
// positions); the axis coordinate is physical + shift until homing shifts it.
struct Machine {
  double cam_lo = 100.0;
  double cam_hi = 120.0;
  double sync_at = 95.0;
  double shift = 0.0;  // [mm] axis coordinate - physical position
  double last_physical = 0.0;

  HomingInput sense(double coordinate) {
    const double physical = coordinate - shift;
    HomingInput input;
    input.cam = physical >= cam_lo && physical <= cam_hi;
    input.sync_pulse =
        (last_physical - sync_at) * (physical - sync_at) <= 0.0 && physical != last_physical;
    last_physical = physical;
    return input;
  }
};

HomingParams params_for_test() {
  HomingParams params;
  params.v_to_cam = 50.0;
  params.v_off_cam = 5.0;
  params.home_position = 5.0;
  params.dynamics = Dynamics{1000.0, 2000.0, 2000.0, 50000.0};
  return params;
}

// Runs homing to its end; returns the phases seen in order of first appearance.
int run(Homing& homing, Machine& machine, HomingPhase* sequence, int max_cycles = 100000) {
  int count = 0;
  Setpoint last = homing.setpoint();
  for (int k = 0; k < max_cycles && !homing.finished(); ++k) {
    const HomingOutput out = homing.step(machine.sense(last.p), kT);
    if (out.shift) machine.shift += *out.shift;
    if (count == 0 || sequence[count - 1] != out.phase) sequence[count++] = out.phase;
    // Set values are continuous apart from the latch shift.
    if (!out.shift) CHECK(std::fabs(out.setpoint.p - last.p) <= 1000.0 * kT + 1e-9);
    last = out.setpoint;
  }
  return count;
}

TEST_CASE("homing on the cam: search, reverse, latch the falling edge, stop, go home") {
  Machine machine;
  Homing homing(params_for_test(), 0.0);
  HomingPhase seen[16];
  const int n = run(homing, machine, seen);
  REQUIRE(n == 5);
  CHECK(seen[0] == HomingPhase::search_cam);
  CHECK(seen[1] == HomingPhase::leave_cam);
  CHECK(seen[2] == HomingPhase::stopping);
  CHECK(seen[3] == HomingPhase::to_home);
  CHECK(seen[4] == HomingPhase::done);
  // Latched where the cam ends (the lower edge, left in negative direction), within one cycle
  // of the off-cam velocity.
  REQUIRE(homing.latched_at());
  CHECK(std::fabs(*homing.latched_at() - 100.0) <= 5.0 * kT + 1e-9);
  // Ends at rest on the home position, i.e. on the cam edge of the machine.
  CHECK(homing.setpoint().p == doctest::Approx(5.0));
  CHECK(homing.setpoint().v == 0.0);
  CHECK(homing.setpoint().p - machine.shift == doctest::Approx(*homing.latched_at()));
}

TEST_CASE("homing with a sync pulse latches at the pulse after the cam") {
  Machine machine;
  HomingParams params = params_for_test();
  params.reference = HomingReference::sync_pulse;
  params.move_to_home = false;
  Homing homing(params, 0.0);
  HomingPhase seen[16];
  run(homing, machine, seen);
  CHECK(homing.phase() == HomingPhase::done);
  REQUIRE(homing.latched_at());
  CHECK(std::fabs(*homing.latched_at() - 95.0) <= 5.0 * kT + 1e-9);
  // Without moving home, the axis stands a little beyond the home position (000 7.2.4).
  CHECK(homing.setpoint().p < 5.0);
  CHECK(homing.setpoint().p > 5.0 - 1.0);
}

TEST_CASE("homing from on the cam leaves it at once") {
  Machine machine;
  Homing homing(params_for_test(), 110.0);
  HomingPhase seen[16];
  run(homing, machine, seen);
  CHECK(seen[0] == HomingPhase::leave_cam);
  CHECK(homing.phase() == HomingPhase::done);
  CHECK(std::fabs(*homing.latched_at() - 100.0) <= 5.0 * kT + 1e-9);
}

TEST_CASE("homing without a cam in reach fails and comes to rest") {
  Machine machine;
  machine.cam_lo = 1e6;
  machine.cam_hi = 1e6 + 1;
  HomingParams params = params_for_test();
  params.max_search_distance = 200.0;
  Homing homing(params, 0.0);
  HomingPhase seen[16];
  run(homing, machine, seen);
  CHECK(homing.phase() == HomingPhase::failed);
  CHECK(homing.finished());
  CHECK(homing.setpoint().v == 0.0);
  CHECK(homing.setpoint().p > 200.0);
  CHECK_FALSE(homing.latched_at());
}

TEST_CASE("the latch shift moves the position controller's coordinates, not the mechanics") {
  PositionControlModel model(PositionControlParams{}, kT, 0.0);
  Machine machine;
  Homing homing(params_for_test(), 0.0);
  Setpoint last = homing.setpoint();
  for (int k = 0; k < 100000 && !homing.finished(); ++k) {
    const HomingOutput out = homing.step(machine.sense(last.p), kT);
    if (out.shift) {
      machine.shift += *out.shift;
      model.shift(*out.shift);
    }
    const ActualValue actual = model.step(out.setpoint);
    CHECK(std::fabs(actual.following_error) < 1.0);
    last = out.setpoint;
  }
  CHECK(homing.phase() == HomingPhase::done);
}

TEST_CASE("invalid homing parameters throw naming the parameter") {
  HomingParams params = params_for_test();
  params.v_to_cam = 0.0;
  CHECK_THROWS_WITH_AS(Homing(params, 0.0), doctest::Contains("towards plc cam"),
                       std::invalid_argument);
  params = params_for_test();
  params.dynamics.j_max = -1.0;
  CHECK_THROWS_AS(Homing(params, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace ncsim::axes
