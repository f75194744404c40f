// The checks while synchronised: 50653 (seed 004 l.514, A15), 50587 (l.515), and the
// velocity split of §2.1.2 (l.311-319, A12).

#include "tracking/sync_checks.hpp"

#include <doctest/doctest.h>

namespace {

using namespace ncsim::tracking;
namespace planner = ncsim::planner;

planner::AxisLimits x_axis() {
  planner::AxisLimits a;
  a.v_max = 1000.0;
  a.v_reference = 1000.0;
  a.v_rapid = 800.0;
  a.a_max = 5000.0;
  a.d_max = 5000.0;
  a.j_max = 50000.0;
  return a;
}

TEST_CASE("50653: a belt more than 10 % above CONV_VEL (18000 mm/min: 331 errors, 329 not)") {
  const double conv_vel = 18000.0 / 60.0;
  CHECK_FALSE(check_belt_velocity(329.0, conv_vel));
  CHECK_FALSE(check_belt_velocity(330.0, conv_vel));
  const auto e = check_belt_velocity(331.0, conv_vel);
  REQUIRE(e);
  CHECK(e->id == "50653");
  CHECK(e->message.find("331 mm/s") != std::string::npos);
  CHECK(check_belt_velocity(-331.0, conv_vel));  // either sign of the spindle velocity
  // sync_wait as printed: CONV_VEL 30 (mm/min) against a 300 mm/s belt.
  CHECK(check_belt_velocity(300.0, 30.0 / 60.0));
}

TEST_CASE("50653 exactly at the limit: a velocity from position differences rounding over it") {
  // belt-split (issue 14): a 330 mm/s belt measured as position differences over 1 ms reads
  // above 330 (synchro_lag_comoving stopped at t 0.505 s; bound 4e-11 mm/s there); it is within
  // the limit (kBeltVelocityRounding), 1e-6 above it is not.
  const double conv_vel = 18000.0 / 60.0;
  CHECK_FALSE(check_belt_velocity(330.0 + 4e-11, conv_vel));
  CHECK_FALSE(check_belt_velocity(-330.0 * (1 + 1e-10), conv_vel));
  CHECK(check_belt_velocity(330.0 * (1 + 1e-8), conv_vel));
  CHECK(check_belt_velocity(330.000001, conv_vel));
}

TEST_CASE("50587: CONV_VEL above the maximum velocity of the conveying axis") {
  CHECK_FALSE(check_conv_vel(x_axis(), 1.0, 1000.0, "X"));
  const auto e = check_conv_vel(x_axis(), 1.0, 1000.5, "X");
  REQUIRE(e);
  CHECK(e->id == "50587");
  CHECK_FALSE(check_conv_vel(x_axis(), 0.0, 5000.0, "Y"));  // no share of the belt
  CHECK(check_conv_vel(x_axis(), -0.8, 1300.0, "Y"));       // a rotated T0: 1040 mm/s on Y
}

TEST_CASE("PCS1 limits: v_max - v_conv with v_conv the fastest belt 50653 lets through") {
  const planner::AxisLimits l = pcs1_limits(x_axis(), 1.0, 300.0);
  CHECK(l.v_max == doctest::Approx(1000.0 - 330.0));
  CHECK(l.v_reference == doctest::Approx(670.0));
  CHECK(l.v_rapid == doctest::Approx(470.0));
  CHECK(l.a_max == 5000.0);
  CHECK(l.j_max == 50000.0);
  const planner::AxisLimits y = pcs1_limits(x_axis(), 0.0, 300.0);
  CHECK(y.v_max == 1000.0);
  // A belt taking all of the axis's velocity leaves 1 %, never 0.
  CHECK(pcs1_limits(x_axis(), 1.0, 1000.0).v_max == doctest::Approx(10.0));
}

}  // namespace
