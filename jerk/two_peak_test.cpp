// jerk::two_peak_move: the change whose acceleration dips toward 0 between two peaks of one
// sign (jerk.hpp, "ptp additions").

#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "jerk/jerk.hpp"

using ncsim::jerk::Limits;
using ncsim::jerk::State;
using ncsim::jerk::Status;
using ncsim::jerk::TwoPeak;

TEST_CASE("two-peak braking eases the start's braking, then brakes harder, and stops on D") {
  // docs/axes-profile.md: the direct stop covers 0.004891 mm, releasing first 0.005093 mm.
  const Limits lim{47.66, 116.6, 512.1, 489102.0};
  const State start{0.0, 2.009, -25.24};
  TwoPeak tp;
  REQUIRE(ncsim::jerk::two_peak_move(start, 0.005089, 0.0, lim, tp) == Status::ok);
  const State end = ncsim::jerk::end_state(start, tp);
  CHECK(end.p == doctest::Approx(0.005089).epsilon(1e-12));
  CHECK(end.v == 0.0);
  CHECK(end.a == 0.0);
  CHECK(tp.a_end[0] < 0.0);                       // the dip stays below 0
  CHECK(tp.a_end[1] == doctest::Approx(-512.1));  // then A-
  CHECK(tp.time() < 5.1e-3);
  // Outside (direct, release-first) no two-peak change exists.
  CHECK(ncsim::jerk::two_peak_move(start, 0.0048, 0.0, lim, tp) == Status::not_supported);
  CHECK(ncsim::jerk::two_peak_move(start, 0.0052, 0.0, lim, tp) == Status::not_supported);
}

TEST_CASE("two-peak changes end on the target with a monotone velocity inside the limits") {
  std::mt19937_64 rng(515);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int found = 0;
  for (int n = 0; n < 20000; ++n) {
    const Limits lim{1.0 + 1e3 * unit(rng), 10.0 + 1e4 * unit(rng), 10.0 + 1e4 * unit(rng),
                     1e2 + 1e6 * unit(rng)};
    const double v0 = lim.v_max * unit(rng);
    const double a0 = (2.0 * unit(rng) - 1.0) * 1.2 * lim.a_max;
    const double v1 = lim.v_max * unit(rng);
    const double d = v0 * 10.0 * unit(rng) * std::pow(10.0, -4.0 * unit(rng));
    TwoPeak tp;
    if (ncsim::jerk::two_peak_move(State{0.0, v0, a0}, d, v1, lim, tp) != Status::ok) continue;
    ++found;
    const State end = ncsim::jerk::end_state(State{0.0, v0, a0}, tp);
    INFO("v0=", v0, " a0=", a0, " v1=", v1, " D=", d);
    REQUIRE(std::abs(end.p - d) <= 1e-9 * d + 1e-15);
    REQUIRE(end.v == v1);
    // One sign of acceleration: the velocity moves monotonically from v0 to v1.
    const double sign = v1 > v0 ? 1.0 : -1.0;
    for (std::size_t i = 0; i < 4; ++i) {
      REQUIRE(sign * tp.a_end[i] >= 0.0);
      const double lim_a = sign > 0.0 ? lim.a_max : lim.d_max;
      if (i > 0) REQUIRE(std::abs(tp.a_end[i]) <= lim_a * (1.0 + 1e-12));
    }
  }
  CHECK(found > 100);
}
