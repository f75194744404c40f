#include "conveyor/filter.hpp"

#include <doctest/doctest.h>

#include <numeric>

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

}  // namespace ncsim::conveyor
