#include "conveyor/filter.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "conveyor/noise.hpp"

namespace ncsim::conveyor {
namespace {

constexpr double kT = 0.001;

machines::ConveyorAxisParams params(bool on, int pos_order, int normal, int dyn, int post) {
  machines::ConveyorAxisParams p;
  p.enable_filter = on;
  p.type_pos_filter = 1;
  p.order_pos_filter = pos_order;
  p.order_v_filter = normal;
  p.order_v_filter_dyn = dyn;
  p.order_post_v_filter = post;
  return p;
}

}  // namespace

TEST_CASE("the FIR low-pass of order n: n symmetric taps of sum 1 (the sinc's main lobe)") {
  for (const std::size_t n : {1U, 2U, 6U, 10U, 20U, 1000U}) {
    const auto h = sinc_taps(n);
    CAPTURE(n);
    REQUIRE(h.size() == n);
    CHECK(std::accumulate(h.begin(), h.end(), 0.0) == doctest::Approx(1.0).epsilon(1e-14));
    for (std::size_t k = 0; k < n; ++k) {
      CHECK(h[k] == doctest::Approx(h[n - 1 - k]).epsilon(1e-14));
      CHECK(h[k] > 0.0);  // the main lobe only
    }
  }
}

TEST_CASE(
    "a constant velocity passes the velocity filters unchanged after the filter length "
    "(P-AXIS-00623 normal, P-AXIS-00625 then P-AXIS-00624 reduced)") {
  for (const bool reduced : {false, true}) {
    ActualValueFilter f(params(true, 0, 20, 10, 6), kT);
    f.set_reduced(reduced);
    f.reset(0.0, 0.0);  // at rest
    const int length = reduced ? 10 + 6 - 1 : 20;
    double v_f = 0.0;
    for (int k = 1; k <= length + 5; ++k) {
      v_f = f.push(300.0 * k * kT, 300.0).v;
      CAPTURE(k);
      if (k < length) CHECK(v_f < 300.0 - 1e-9);  // still filling
      if (k >= length) CHECK(v_f == doctest::Approx(300.0).epsilon(1e-13));
    }
    CHECK(f.state().a == doctest::Approx(0.0).scale(1.0));
  }
}

TEST_CASE(
    "the position filter delays a constant velocity by (n - 1) T / 2 "
    "(conv_sync.order_pos_filter NCSIM-AXIS-006)") {
  ActualValueFilter f(params(true, 4, 10, 10, 6), kT);
  CHECK(f.position_delay() == doctest::Approx(1.5 * kT));
  f.reset(0.0, 300.0);
  for (int k = 1; k <= 10; ++k) {
    const double p = 300.0 * k * kT;
    CHECK(f.push(p, 300.0).p == doctest::Approx(p - 300.0 * 1.5 * kT).epsilon(1e-13));
  }
}

TEST_CASE("P-AXIS-00620 = 0: the measured value passes unfiltered") {
  ActualValueFilter f(params(false, 4, 20, 10, 6), kT);
  f.reset(0.0, 0.0);
  const BeltState& s = f.push(1.0, 1000.0);
  CHECK(s.p == 1.0);
  CHECK(s.v == 1000.0);
  CHECK(s.a == doctest::Approx(1000.0 / kT));
}

TEST_CASE("filter order 0 is off (P-AXIS-00623 = 0)") {
  ActualValueFilter f(params(true, 0, 0, 0, 0), kT);
  f.reset(0.0, 0.0);
  CHECK(f.push(0.3, 300.0).v == 300.0);
  f.set_reduced(true);
  CHECK(f.push(0.6, 250.0).v == 250.0);
}

TEST_CASE("switching to the reduced filter has no start-up transient: both chains run") {
  ActualValueFilter f(params(true, 0, 20, 10, 6), kT);
  f.reset(0.0, 300.0);
  for (int k = 1; k <= 50; ++k)
    f.push(300.0 * k * kT, 300.0);
  f.set_reduced(true);
  CHECK(f.push(300.0 * 51 * kT, 300.0).v == doctest::Approx(300.0).epsilon(1e-13));
}

TEST_CASE(
    "seeded 10 um position noise: the filtered velocity's noise is the raw difference "
    "quotient's times the filter's own gain (P-AXIS-00623 20; P-AXIS-00625 10 then "
    "P-AXIS-00624 6)") {
  // Position noise e_k, independent, sigma 0.01 mm. The raw velocity (p_k - p_k-1) / T carries
  // (e_k - e_k-1) / T: standard deviation sqrt(2) sigma / T = 14.1 mm/s at 1 ms. A velocity
  // filter of taps h makes it sum_j (h_j - h_j-1) e_k-j / T (h_-1 = h_n = 0): standard
  // deviation sigma / T * sqrt(sum_j (h_j - h_j-1)^2), from the taps alone.
  constexpr double kSigma = 0.01;  // [mm]
  constexpr double kV = 300.0;     // [mm/s]
  const auto gain = [](const std::vector<double>& h) {
    double sum = 0.0;
    for (std::size_t j = 0; j <= h.size(); ++j) {
      const double d = (j < h.size() ? h[j] : 0.0) - (j > 0 ? h[j - 1] : 0.0);
      sum += d * d;
    }
    return std::sqrt(sum);
  };
  // The reduced chain's taps: FIR(10) followed by the average of 6 (their convolution).
  const std::vector<double> fir10 = sinc_taps(10), avg6 = average_taps(6);
  std::vector<double> reduced_taps(fir10.size() + avg6.size() - 1, 0.0);
  for (std::size_t i = 0; i < fir10.size(); ++i)
    for (std::size_t j = 0; j < avg6.size(); ++j)
      reduced_taps[i + j] += fir10[i] * avg6[j];
  for (const bool reduced : {false, true}) {
    CAPTURE(reduced);
    const double g = gain(reduced ? reduced_taps : sinc_taps(20));
    ActualValueFilter f(params(true, 0, 20, 10, 6), kT);
    f.set_reduced(reduced);
    f.reset(0.0, kV);
    Gaussian noise(20261124);
    double p_prev = 0.0;
    double raw2 = 0.0, filtered2 = 0.0;
    constexpr int kWarmUp = 100, kCycles = 200000;
    for (int k = 1; k <= kWarmUp + kCycles; ++k) {
      const double p = kV * k * kT + kSigma * noise.next();
      const double v = (p - p_prev) / kT;
      p_prev = p;
      const double v_f = f.push(p, v).v;
      if (k <= kWarmUp) continue;
      raw2 += (v - kV) * (v - kV);
      filtered2 += (v_f - kV) * (v_f - kV);
    }
    const double raw = std::sqrt(raw2 / kCycles), filtered = std::sqrt(filtered2 / kCycles);
    CAPTURE(raw);
    CAPTURE(filtered);
    CAPTURE(g);
    CHECK(raw == doctest::Approx(std::sqrt(2.0) * kSigma / kT).epsilon(0.03));
    CHECK(filtered == doctest::Approx(g * kSigma / kT).epsilon(0.05));
    // The smooth taps difference to far less than a 1 / n boxcar's gain sqrt(2) / n: the
    // filtered noise is below a 20th (normal) and a 10th (reduced) of the raw one.
    CHECK(filtered < raw / (reduced ? 10.0 : 20.0));
  }
}

}  // namespace ncsim::conveyor
