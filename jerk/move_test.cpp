// Tests of single-peak moves of minimum and of prescribed duration: the 002_* figure, the end
// state met exactly, the duration met, limits respected, seeded random cases over wide ranges.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "jerk/jerk.hpp"

namespace {

using ncsim::jerk::Limits;
using ncsim::jerk::Move;
using ncsim::jerk::State;
using ncsim::jerk::Status;

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

// Independent minimum time of a change from rest to dv > 0 (textbook S-ramp).
double rest_ramp_time(double dv, double a, double j) {
  return dv * j <= a * a ? 2.0 * std::sqrt(dv / j) : dv / a + a / j;
}

}  // namespace

TEST_CASE("velocity_change from rest takes the textbook S-ramp time") {
  std::mt19937_64 rng(5);
  for (int n = 0; n < 10000; ++n) {
    const double dv = log_uniform(rng, 1e-3, 1e4);
    const double a = log_uniform(rng, 10.0, 1e5);
    const double j = log_uniform(rng, 1e2, 1e7);
    const double t = ncsim::jerk::velocity_change(0.0, 0.0, dv, a, j).t;
    REQUIRE(t == doctest::Approx(rest_ramp_time(dv, a, j)).epsilon(1e-12));
  }
}

TEST_CASE("the minimum single-peak time of Dynamik 1.1 is 1.0 s, 1.2 gives 0.95 s") {
  const Limits d11{2000.0, 5000.0, 5000.0, 50000.0};
  CHECK(ncsim::jerk::min_single_peak_time(State{}, 1000.0, 0.0, d11) ==
        doctest::Approx(1.0).epsilon(1e-14));
  const Limits d12{2000.0, 5000.0, 10000.0, 50000.0};
  CHECK(ncsim::jerk::min_single_peak_time(State{}, 1000.0, 0.0, d12) ==
        doctest::Approx(0.95).epsilon(1e-14));
}

TEST_CASE("move_of_duration stretches Dynamik 1.1 to 2 s by lowering the level") {
  const Limits d{2000.0, 5000.0, 5000.0, 50000.0};
  Move m;
  REQUIRE(ncsim::jerk::move_of_duration(State{}, 1000.0, 0.0, 2.0, d, m) == Status::ok);
  CHECK(m.time() == doctest::Approx(2.0).epsilon(1e-14));
  CHECK(m.v_level < 2000.0);
  const State end = ncsim::jerk::end_state(State{}, m);
  CHECK(end.p == doctest::Approx(1000.0).epsilon(1e-14));
  CHECK(end.v == 0.0);
  CHECK(end.a == 0.0);
  CHECK(ncsim::jerk::move_of_duration(State{}, 1000.0, 0.0, 0.999, d, m) == Status::too_short);
  CHECK(ncsim::jerk::move_of_duration(State{}, 1000.0, 3000.0, 5.0, d, m) == Status::invalid_input);
}

TEST_CASE("a stop-and-go that fills the distance dwells at rest for the remaining time") {
  const Limits d{1000.0, 1000.0, 1000.0, 1e4};
  const State start{0.0, 100.0, 0.0};
  // Distance of stopping from 100 mm/s plus speeding up to 100 mm/s again.
  const double s_stop = ncsim::jerk::stopping_distance(100.0, 0.0, 1000.0, 1e4).s;
  Move m;
  REQUIRE(ncsim::jerk::move_of_duration(start, 2.0 * s_stop, 100.0, 10.0, d, m) == Status::ok);
  CHECK(m.time() == doctest::Approx(10.0));
  CHECK(m.v_level == 0.0);
  const State end = ncsim::jerk::end_state(start, m);
  CHECK(end.p == doctest::Approx(2.0 * s_stop));
  CHECK(end.v == 100.0);
}

TEST_CASE("a move that must reverse is not supported by the single-peak family") {
  const Limits d{1000.0, 1000.0, 1000.0, 1e4};
  Move m;
  // Moving fast toward a target 1 mm away, to be met at rest after 10 s: needs an overshoot.
  CHECK(ncsim::jerk::move_of_duration(State{0.0, 1000.0, 0.0}, 1.0, 0.0, 10.0, d, m) ==
        Status::not_supported);
  CHECK(ncsim::jerk::min_single_peak_time(State{0.0, 1000.0, 0.0}, 1.0, 0.0, d) < 0.0);
}

TEST_CASE("move_of_duration over seeded random cases: exact end, exact time, limits hold") {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int solved = 0;
  int unsupported = 0;
  for (int n = 0; n < 50000; ++n) {
    Limits lim;
    lim.v_max = log_uniform(rng, 1.0, 1e4);
    lim.a_max = log_uniform(rng, 10.0, 1e5);
    lim.d_max = unit(rng) < 0.3 ? lim.a_max : log_uniform(rng, 10.0, 1e5);
    lim.j_max = log_uniform(rng, 1e2, 1e7);
    const double dist = (unit(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 1e-4, 1e4);
    const double dir = dist > 0.0 ? 1.0 : -1.0;
    State start{unit(rng) * 100.0, 0.0, 0.0};
    if (unit(rng) < 0.5) start.v = dir * lim.v_max * unit(rng);
    const double v1 = unit(rng) < 0.3 ? dir * lim.v_max * unit(rng) : 0.0;
    const double p1 = start.p + dist;
    const double t_min = ncsim::jerk::min_single_peak_time(start, p1, v1, lim);
    if (t_min < 0.0) continue;
    const double duration = t_min * (1.0 + 4.0 * unit(rng));
    Move m;
    INFO("p0=", start.p, " v0=", start.v, " p1=", p1, " v1=", v1, " T=", duration, " V=", lim.v_max,
         " A+=", lim.a_max, " A-=", lim.d_max, " J=", lim.j_max);
    const Status status = ncsim::jerk::move_of_duration(start, p1, v1, duration, lim, m);
    // A moving start may be unable to go slower without reversing (documented); a start at
    // rest can always be stretched.
    if (status == Status::not_supported && start.v != 0.0) {
      ++unsupported;
      continue;
    }
    REQUIRE(status == Status::ok);
    REQUIRE(std::abs(m.time() - duration) <= 1e-9 * duration);
    REQUIRE(m.v_level <= lim.v_max);
    REQUIRE(m.v_level >= 0.0);
    REQUIRE(m.t_cruise >= 0.0);
    for (const auto* r : {&m.first, &m.second}) {
      REQUIRE(r->a_peak <= lim.a_max * (1.0 + 1e-12));
      REQUIRE(-r->a_peak <= lim.d_max * (1.0 + 1e-12));
    }
    const State end = ncsim::jerk::end_state(start, m);
    REQUIRE(std::abs(end.p - p1) <= 1e-9 * std::abs(dist) + 1e-15 * std::abs(p1));
    REQUIRE(end.v == v1);
    REQUIRE(end.a == 0.0);
    ++solved;
  }
  MESSAGE("solved ", solved, ", moving starts not supported ", unsupported);
  CHECK(solved > 30000);
  CHECK(unsupported < 2000);
}
