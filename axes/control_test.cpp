#include "axes/control.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace ncsim::axes {
namespace {

constexpr double kT = 0.001;  // [s] interpolation cycle of the tests

// Runs the model along a constant-velocity ramp and returns the lag after `cycles`.
double lag_on_ramp(const PositionControlParams& params, double v, int cycles) {
  PositionControlModel model(params, kT, 0.0);
  ActualValue actual;
  for (int k = 0; k <= cycles; ++k) {
    actual = model.step(Setpoint{v * kT * k, v, 0.0, 0.0});
  }
  return actual.following_error;
}

TEST_CASE("the PT1 filter follows the formula of 000 7.5.8") {
  Pt1Filter filter(0.001, 0.004, 10.0);
  const double weight = 0.001 / (0.001 + 0.004);
  CHECK(filter.weight() == doctest::Approx(0.2));
  CHECK(filter.step(20.0) == doctest::Approx(weight * 20.0 + (1.0 - weight) * 10.0));
  Pt1Filter pass(0.001, 0.0, 3.0);
  CHECK(pass.step(7.0) == 7.0);
  CHECK_THROWS_AS(Pt1Filter(0.001, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(Pt1Filter(0.0, 1.0), std::invalid_argument);
}

TEST_CASE("without feedforward the steady following error is v / Kv") {
  PositionControlParams params;
  params.kv = 20.0;
  params.feedforward_weight = 0.0;
  CHECK(lag_on_ramp(params, 100.0, 3000) == doctest::Approx(100.0 / 20.0).epsilon(1e-9));
  params.drive_pt1_time = 0.005;  // a PT1 drive changes the transient, not the steady lag
  CHECK(lag_on_ramp(params, 100.0, 5000) == doctest::Approx(100.0 / 20.0).epsilon(1e-9));
}

TEST_CASE("half feedforward halves the steady following error") {
  PositionControlParams params;
  params.kv = 25.0;
  params.feedforward_weight = 0.5;
  CHECK(lag_on_ramp(params, 200.0, 3000) == doctest::Approx(0.5 * 200.0 / 25.0).epsilon(1e-9));
}

TEST_CASE("full feedforward without PT1 leaves no following error on a ramp") {
  PositionControlParams params;
  params.kv = 30.0;
  params.feedforward_weight = 1.0;
  CHECK(std::fabs(lag_on_ramp(params, 500.0, 2000)) < 1e-9);
}

TEST_CASE("the actual position lags the command while moving and settles on the target") {
  PositionControlParams params;
  params.kv = 40.0;
  params.feedforward_weight = 0.0;
  params.drive_pt1_time = 0.002;
  PositionControlModel model(params, kT, 5.0);
  ActualValue actual = model.step(Setpoint{5.0, 0.0, 0.0, 0.0});
  CHECK(actual.position == 5.0);
  // A step of the command to 6 mm.
  actual = model.step(Setpoint{6.0, 0.0, 0.0, 0.0});
  CHECK(actual.following_error == doctest::Approx(1.0));
  for (int k = 0; k < 2000; ++k)
    actual = model.step(Setpoint{6.0, 0.0, 0.0, 0.0});
  CHECK(actual.position == doctest::Approx(6.0).epsilon(1e-9));
  CHECK(std::fabs(actual.velocity) < 1e-6);
}

TEST_CASE("encoder noise is bounded and the same for the same seed") {
  PositionControlParams params;
  params.noise_amplitude = 0.002;
  params.noise_seed = 42;
  PositionControlModel a(params, kT, 0.0);
  PositionControlModel b(params, kT, 0.0);
  params.noise_seed = 43;
  PositionControlModel c(params, kT, 0.0);
  bool differs = false;
  for (int k = 0; k < 500; ++k) {
    const Setpoint command{0.1 * k * kT, 0.1, 0.0, 0.0};
    const ActualValue va = a.step(command);
    const ActualValue vb = b.step(command);
    const ActualValue vc = c.step(command);
    CHECK(va.position == vb.position);
    CHECK(std::fabs(va.position - a.true_position()) <= 0.002);
    if (va.position != vc.position) differs = true;
  }
  CHECK(differs);
}

TEST_CASE("the first noise draws of a seed are fixed (platform independent)") {
  EncoderNoise noise(1.0, 7);
  std::mt19937_64 engine(7);
  for (int k = 0; k < 3; ++k) {
    const double expected = 2.0 * static_cast<double>(engine() >> 11) * 0x1.0p-53 - 1.0;
    CHECK(noise.draw() == expected);
  }
}

TEST_CASE("invalid control parameters throw naming the parameter") {
  PositionControlParams params;
  params.kv = 0.0;
  CHECK_THROWS_WITH_AS(validate(params, kT), doctest::Contains("Kv"), std::invalid_argument);
  params.kv = 2000.0;  // Kv * T = 2 > 1
  CHECK_THROWS_WITH_AS(validate(params, kT), doctest::Contains("Kv"), std::invalid_argument);
  params.kv = 10.0;
  params.feedforward_weight = 1.5;
  CHECK_THROWS_WITH_AS(validate(params, kT), doctest::Contains("Pre-Control Weighting"),
                       std::invalid_argument);
  params.feedforward_weight = 1.0;
  params.drive_pt1_time = -0.001;
  CHECK_THROWS_AS(PositionControlModel(params, kT, 0.0), std::invalid_argument);
}

TEST_CASE("property: random stable parameters never give NaN and the lag converges") {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> kv_dist(10.0, 200.0);
  std::uniform_real_distribution<double> pt1_dist(0.0, 0.01);
  std::uniform_real_distribution<double> ff_dist(0.0, 1.0);
  std::uniform_real_distribution<double> v_dist(-500.0, 500.0);
  for (int trial = 0; trial < 50; ++trial) {
    PositionControlParams params;
    params.kv = kv_dist(rng);
    params.drive_pt1_time = pt1_dist(rng);
    params.feedforward_weight = ff_dist(rng);
    const double v = v_dist(rng);
    CAPTURE(params.kv);
    CAPTURE(params.drive_pt1_time);
    CAPTURE(params.feedforward_weight);
    PositionControlModel model(params, kT, 0.0);
    ActualValue actual;
    // Ramp for 1 s, then hold the end position for 10 s.
    const int ramp = 1000;
    bool finite = true;
    for (int k = 0; k <= ramp; ++k) {
      actual = model.step(Setpoint{v * kT * k, v, 0.0, 0.0});
      finite = finite && std::isfinite(actual.position) && std::isfinite(actual.velocity);
    }
    for (int k = 0; k < 10000; ++k) {
      actual = model.step(Setpoint{v * kT * ramp, 0.0, 0.0, 0.0});
      finite = finite && std::isfinite(actual.position);
    }
    CHECK(finite);
    CHECK(std::fabs(actual.following_error) < 1e-6);
  }
}

TEST_CASE("an encoder axis's set value is its actual value, noise included") {
  EncoderAxisParams params;
  params.noise_amplitude = 0.001;
  params.noise_seed = 5;
  EncoderAxis encoder(params, kT, 0.0);
  EncoderNoise same_noise(0.001, 5);
  for (int k = 1; k <= 100; ++k) {
    const double physical = 250.0 * kT * k;  // belt at 250 mm/s
    const Setpoint value = encoder.step(physical);
    CHECK(value.p == physical + same_noise.draw());
  }
  // Without noise and filters the velocity is the difference quotient.
  EncoderAxis clean(EncoderAxisParams{}, kT, 0.0);
  clean.step(0.25);
  CHECK(clean.step(0.5).v == doctest::Approx(250.0));
  CHECK(clean.value().a == doctest::Approx(0.0));
}

TEST_CASE("the encoder velocity filter smooths the noise") {
  EncoderAxisParams params;
  params.noise_amplitude = 0.001;
  params.velocity_filter_time = 0.05;
  EncoderAxis filtered(params, kT, 0.0);
  params.velocity_filter_time = 0.0;
  EncoderAxis raw(params, kT, 0.0);
  double err_filtered = 0.0;
  double err_raw = 0.0;
  for (int k = 1; k <= 2000; ++k) {
    const double physical = 100.0 * kT * k;
    const double vf = filtered.step(physical).v;
    const double vr = raw.step(physical).v;
    if (k > 500) {
      err_filtered = std::max(err_filtered, std::fabs(vf - 100.0));
      err_raw = std::max(err_raw, std::fabs(vr - 100.0));
    }
  }
  CHECK(err_filtered < 0.2 * err_raw);
}

}  // namespace
}  // namespace ncsim::axes
