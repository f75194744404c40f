// Tests of the jerk kernel's velocity changes and their inverses: the 002_* figures, the
// consistency of forward and inverse functions, limits, monotonicity and totality over seeded
// random cases across wide ranges (V 1..1e4 mm/s, A 10..1e5 mm/s^2, J 1e2..1e7 mm/s^3,
// distances 1e-4..1e4 mm).

#include "jerk/jerk.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "jerk/test_random.hpp"

namespace {

using ncsim::jerk::Ramp;

using ncsim::test::log_uniform;

struct Dyn {
  double v = 0.0;
  double a = 0.0;
  double j = 0.0;
};

Dyn random_dyn(std::mt19937_64& rng) {
  return Dyn{log_uniform(rng, 1.0, 1e4), log_uniform(rng, 10.0, 1e5), log_uniform(rng, 1e2, 1e7)};
}

// Largest |a| along the ramp and its end velocity, integrated phase by phase.
struct Walk {
  double a_abs_max = 0.0;
  double v_end = 0.0;
};

Walk walk(double v0, double a0, const Ramp& r) {
  ncsim::jerk::State st{0.0, v0, a0};
  Walk w;
  w.a_abs_max = std::abs(a0);
  for (std::size_t i = 0; i < 3; ++i) {
    st = ncsim::jerk::advance(st, r.jerk[i], r.duration[i]);
    w.a_abs_max = std::max(w.a_abs_max, std::abs(st.a));
  }
  w.v_end = st.v;
  return w;
}

}  // namespace

TEST_CASE("velocity_change reproduces the 002 figure Dynamik 1.1 ramp (0 -> 2000 mm/s)") {
  const auto td = ncsim::jerk::velocity_change(0.0, 0.0, 2000.0, 5000.0, 50000.0);
  CHECK(td.t == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(td.s == doctest::Approx(500.0).epsilon(1e-14));
  // Dynamik 2.1: A not reached (J = 20000): t = 2 sqrt(v / J) with v = 1696.772 mm/s.
  const auto td2 = ncsim::jerk::velocity_change(0.0, 0.0, 1000.0, 5000.0, 20000.0);
  CHECK(td2.t == doctest::Approx(2.0 * std::sqrt(1000.0 / 20000.0)).epsilon(1e-15));
  CHECK(ncsim::jerk::ramp_distance(2000.0, 5000.0, 50000.0) == doctest::Approx(500.0));
}

TEST_CASE("stopping_distance from a start still accelerating first takes the acceleration away") {
  // v0 = 100, a0 = 1000, D = 1000, J = 1e4: a goes 1000 -> -1000 (0.2 s) ...
  const auto st = ncsim::jerk::stopping_distance(100.0, 1000.0, 1000.0, 1e4);
  const Ramp r = ncsim::jerk::velocity_ramp(100.0, 1000.0, 0.0, 1000.0, 1000.0, 1e4);
  CHECK(r.jerk[0] < 0.0);
  CHECK(st.t == doctest::Approx(r.time()));
  CHECK(walk(100.0, 1000.0, r).v_end == doctest::Approx(0.0).epsilon(1e-12).scale(100.0));
  CHECK(st.s > 0.0);
  // Releasing the acceleration alone (0.1 s) travels 100*0.1 + 1000*0.01/2 - 1e4*1e-3/6.
  CHECK(st.s > 10.0 + 5.0 - 10.0 / 6.0);
}

TEST_CASE("a start acceleration beyond the limit is first brought back to it with J") {
  const Ramp r = ncsim::jerk::velocity_ramp(0.0, 3000.0, 1000.0, 2000.0, 2000.0, 1e4);
  CHECK(r.jerk[0] == -1e4);
  CHECK(r.duration[0] == doctest::Approx(0.1));
  CHECK(r.a_peak == 2000.0);
  CHECK(walk(0.0, 3000.0, r).v_end == doctest::Approx(1000.0));
}

TEST_CASE("reachable_velocity inverts velocity_change over seeded random cases") {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int n = 0; n < 100000; ++n) {
    const Dyn d = random_dyn(rng);
    const double v0 = unit(rng) < 0.3 ? 0.0 : d.v * unit(rng);
    const double a0 = unit(rng) < 0.5 ? 0.0 : d.a * (2.0 * unit(rng) - 1.0);
    const double v_zero = v0 + a0 * std::abs(a0) / (2.0 * d.j);
    if (v_zero < 0.0) continue;  // documented domain: forward motion
    const double v1 = v_zero + (d.v - std::min(v_zero, d.v)) * unit(rng) + 1e-3 * unit(rng);
    const auto td = ncsim::jerk::velocity_change(v0, a0, v1, d.a, d.j);
    const double v_back = ncsim::jerk::reachable_velocity(v0, a0, td.s, d.a, d.j);
    INFO("v0=", v0, " a0=", a0, " v1=", v1, " A=", d.a, " J=", d.j, " s=", td.s);
    REQUIRE(std::isfinite(v_back));
    REQUIRE(std::abs(v_back - v1) <= 1e-9 * std::max(v1, v0));
    // Backward pass: the exit v0 from the entry v1 over the same distance (a0 = 0).
    if (a0 == 0.0) {
      const double v_entry = ncsim::jerk::entry_velocity_for_exit(v0, td.s, d.a, d.j);
      REQUIRE(std::abs(v_entry - v1) <= 1e-9 * v1);
    }
    ++checked;
  }
  CHECK(checked > 80000);
}

TEST_CASE("reachable_velocity over distances 1e-4..1e4 mm: limits hold, the distance is met") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < 100000; ++n) {
    const Dyn d = random_dyn(rng);
    const double v0 = unit(rng) < 0.3 ? 0.0 : d.v * unit(rng);
    const double s = log_uniform(rng, 1e-4, 1e4);
    const double v1 = ncsim::jerk::reachable_velocity(v0, 0.0, s, d.a, d.j);
    INFO("v0=", v0, " s=", s, " A=", d.a, " J=", d.j, " v1=", v1);
    REQUIRE(std::isfinite(v1));
    REQUIRE(v1 >= v0);
    const Ramp r = ncsim::jerk::velocity_ramp(v0, 0.0, v1, d.a, d.a, d.j);
    const Walk w = walk(v0, 0.0, r);
    REQUIRE(w.a_abs_max <= d.a * (1.0 + 1e-12));
    // v1 is a double: near v0 its last bit can be worth more than 1e-9 of s, so the check is
    // that s lies between the distances of v1's neighbours a few ulp away.
    const auto dist_of = [&](double v) {
      return ncsim::jerk::distance(v0, 0.0, ncsim::jerk::velocity_ramp(v0, 0.0, v, d.a, d.a, d.j));
    };
    const double ulps = 4.0 * std::numeric_limits<double>::epsilon() * v1;
    REQUIRE(dist_of(std::max(v0, v1 - ulps)) <= s * (1.0 + 1e-12));
    REQUIRE(dist_of(v1 + ulps) >= s * (1.0 - 1e-12));
  }
}

TEST_CASE("reachable_velocity and entry_velocity_for_exit are monotone in the distance") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < 2000; ++n) {
    const Dyn d = random_dyn(rng);
    const double v0 = d.v * unit(rng);
    const double a0 = d.a * (2.0 * unit(rng) - 1.0);
    double last_r = -1e300;
    double last_e = -1e300;
    for (double s = 1e-4; s <= 1e4; s *= 1.07) {
      const double r = ncsim::jerk::reachable_velocity(v0, a0, s, d.a, d.j);
      const double e = ncsim::jerk::entry_velocity_for_exit(v0, s, d.a, d.j);
      INFO("v0=", v0, " a0=", a0, " s=", s, " A=", d.a, " J=", d.j);
      REQUIRE(r >= last_r - 1e-15 * std::abs(last_r));
      REQUIRE(e >= last_e - 1e-15 * std::abs(last_e));
      REQUIRE(e >= v0);
      last_r = r;
      last_e = e;
    }
  }
}

TEST_CASE("below the distance of releasing the start acceleration the answer is v_zero") {
  // v0 = 10, a0 = 100, J = 1000: releasing takes 0.1 s and 10*0.1 + 0.5 - 1/6 mm.
  const double v_zero = 10.0 + 100.0 * 100.0 / 2000.0;
  CHECK(ncsim::jerk::reachable_velocity(10.0, 100.0, 0.5, 1000.0, 1000.0) == v_zero);
  CHECK(ncsim::jerk::reachable_velocity(10.0, 100.0, 2.0, 1000.0, 1000.0) > v_zero);
}

TEST_CASE("the kernel is total: extreme and degenerate inputs never give NaN") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < 20000; ++n) {
    const Dyn d = random_dyn(rng);
    const double v0 = d.v * (4.0 * unit(rng) - 2.0);
    const double a0 = d.a * (6.0 * unit(rng) - 3.0);
    const double s = (unit(rng) < 0.1 ? -1.0 : 1.0) * log_uniform(rng, 1e-9, 1e6);
    const double v1 = d.v * (4.0 * unit(rng) - 2.0);
    INFO("v0=", v0, " a0=", a0, " s=", s, " v1=", v1, " A=", d.a, " J=", d.j);
    REQUIRE(std::isfinite(ncsim::jerk::reachable_velocity(v0, a0, s, d.a, d.j)));
    REQUIRE(std::isfinite(ncsim::jerk::entry_velocity_for_exit(std::abs(v0), s, d.a, d.j)));
    const auto td = ncsim::jerk::velocity_change(v0, a0, v1, d.a, d.j);
    REQUIRE(std::isfinite(td.t));
    REQUIRE(std::isfinite(td.s));
    const Ramp r = ncsim::jerk::velocity_ramp(v0, a0, v1, d.a, d.a, d.j);
    const Walk w = walk(v0, a0, r);
    REQUIRE(w.a_abs_max <= std::max(d.a, std::abs(a0)) * (1.0 + 1e-12));
    REQUIRE(std::abs(w.v_end - v1) <= 1e-9 * (std::abs(v0) + std::abs(v1) + d.a * d.a / d.j));
  }
}
