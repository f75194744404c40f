// tracking/sync_error: the stop after an error while synchronised (seed 004 §2.3).

#include "tracking/sync_error.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

namespace ncsim::tracking {
namespace {

AfterErrorAxis axis(double lo, double hi) {
  AfterErrorAxis a;
  a.soft = axes::SoftLimitParams{true, lo, true, hi};
  a.v_max = 1000.0;
  a.a_max = 5000.0;
  a.d_max = 4000.0;
  a.j_max = 50000.0;
  return a;
}

/// Follows a belt at `v_belt` from `p0` until the stop says brake, then brakes; returns the
/// largest position reached and checks the ramp's limits on the way.
double follow_and_stop(SyncErrorStop& stop, double p0, double v_belt, double t_cycle,
                       AfterErrorEnd& why) {
  std::array<axes::Setpoint, 1> sp{axes::Setpoint{p0, v_belt, 0.0, 0.0}};
  stop.begin();
  double p_max = p0;
  for (int k = 0; k < 1000000 && !stop.stood(); ++k) {
    if (stop.stopping()) {
      const double v0 = sp[0].v;
      stop.step(sp);
      CHECK(std::fabs(sp[0].a) <= stop.limits(0).d_max * (1 + 1e-9));
      CHECK(std::fabs(sp[0].v) <= std::fabs(v0) + 1e-9);  // it brakes, never speeds up
    } else {
      sp[0].p += v_belt * t_cycle;
      int a = -1;
      if (stop.must_stop(sp, why, a)) stop.start_stopping(sp, why, a);
      stop.follow_cycle();
    }
    p_max = std::max(p_max, sp[0].p);
  }
  REQUIRE(stop.stood());
  CHECK(sp[0].v == 0.0);
  CHECK(sp[0].a == 0.0);
  return p_max;
}

TEST_CASE("after an error the axis follows the belt and stops before its soft limit") {
  SyncErrorStop stop;
  const std::array<AfterErrorAxis, 1> ax{axis(-100.0, 1500.0)};
  REQUIRE(stop.configure(ax, 0.001));
  AfterErrorEnd why = AfterErrorEnd::time_limit;
  const double p_max = follow_and_stop(stop, 1000.0, 300.0, 0.001, why);
  CHECK(why == AfterErrorEnd::soft_limit);
  CHECK(stop.axis() == 0);
  CHECK(p_max <= 1500.0);
  // It brakes at the latest cycle: within a cycle's travel (0.3 mm) of the limit, and it
  // followed for the time to the braking point (the stop from 300 mm/s is 23.2 mm).
  CHECK(p_max >= 1500.0 - 0.3 - 1e-6);
  const double brake = jerk::stopping_distance(300.0, 0.0, 4000.0, 50000.0).s;
  CHECK(brake == doctest::Approx(23.24).epsilon(1e-3));
  CHECK(std::fabs(stop.followed() - (500.0 - brake) / 300.0) <= 0.001 + 1e-9);
}

TEST_CASE("after an error an axis moving towards its lower soft limit stops before it") {
  SyncErrorStop stop;
  const std::array<AfterErrorAxis, 1> ax{axis(-200.0, 1500.0)};
  REQUIRE(stop.configure(ax, 0.002));
  AfterErrorEnd why = AfterErrorEnd::time_limit;
  std::array<axes::Setpoint, 1> sp{axes::Setpoint{0.0, -250.0, 0.0, 0.0}};
  stop.begin();
  double p_min = 0.0;
  for (int k = 0; k < 100000 && !stop.stood(); ++k) {
    if (stop.stopping()) {
      stop.step(sp);
    } else {
      sp[0].p -= 250.0 * 0.002;
      int a = -1;
      if (stop.must_stop(sp, why, a)) stop.start_stopping(sp, why, a);
    }
    p_min = std::min(p_min, sp[0].p);
  }
  CHECK(why == AfterErrorEnd::soft_limit);
  CHECK(p_min >= -200.0);
  CHECK(p_min <= -200.0 + 0.5 + 1e-6);
}

TEST_CASE("seeded: the stop never passes the soft limit, whatever the belt and the limits") {
  std::mt19937 rng(20260514);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 200; ++n) {
    AfterErrorAxis a = axis(-1e6, 500.0 + 1000.0 * u(rng));
    a.d_max = 500.0 + 9500.0 * u(rng);
    a.j_max = 1e3 + 1e6 * u(rng);
    SyncErrorStop stop;
    const std::array<AfterErrorAxis, 1> ax{a};
    const double t = u(rng) < 0.5 ? 0.001 : 0.002;
    REQUIRE(stop.configure(ax, t));
    AfterErrorEnd why = AfterErrorEnd::time_limit;
    const double v = 10.0 + 900.0 * u(rng);
    CAPTURE(n);
    const double p_max = follow_and_stop(stop, 0.0, v, t, why);
    CHECK(p_max <= a.soft.max_position);
  }
}

TEST_CASE("after an error the stop brakes an axis that following would take above v_max") {
  SyncErrorStop stop;
  AfterErrorAxis a = axis(-1e6, 1e6);
  a.v_max = 200.0;
  const std::array<AfterErrorAxis, 1> ax{a};
  REQUIRE(stop.configure(ax, 0.001));
  std::array<axes::Setpoint, 1> sp{axes::Setpoint{0.0, 190.0, 20000.0, 0.0}};
  AfterErrorEnd why = AfterErrorEnd::time_limit;
  int i = -1;
  CHECK(stop.must_stop(sp, why, i));
  CHECK(why == AfterErrorEnd::velocity);
  CHECK(i == 0);
}

TEST_CASE("without a soft limit ahead the machine follows for kFollowMax, then brakes") {
  SyncErrorStop stop;
  AfterErrorAxis a = axis(0.0, 0.0);
  a.soft = axes::SoftLimitParams{};
  const std::array<AfterErrorAxis, 1> ax{a};
  REQUIRE(stop.configure(ax, 0.01));
  AfterErrorEnd why = AfterErrorEnd::soft_limit;
  follow_and_stop(stop, 0.0, 100.0, 0.01, why);
  CHECK(why == AfterErrorEnd::time_limit);
  CHECK(stop.followed() == doctest::Approx(SyncErrorStop::kFollowMax).epsilon(1e-4));
}

TEST_CASE("a soft limit error ends the run at once, every other error keeps synchronisation") {
  CHECK_FALSE(SyncErrorStop::keeps_synchronisation("NC5501"));
  CHECK_FALSE(SyncErrorStop::keeps_synchronisation("NC5502"));
  CHECK(SyncErrorStop::keeps_synchronisation("NC9052"));
  CHECK(SyncErrorStop::keeps_synchronisation("0x4550"));
  CHECK(SyncErrorStop::keeps_synchronisation("50653"));
}

TEST_CASE("unusable limits: the stop cannot be planned") {
  SyncErrorStop stop;
  AfterErrorAxis a = axis(0.0, 1.0);
  a.d_max = 0.0;
  const std::array<AfterErrorAxis, 1> ax{a};
  CHECK_FALSE(stop.configure(ax, 0.001));
  CHECK_FALSE(stop.usable());
  a.d_max = 100.0;
  a.j_max = 0.0;  // a STEP slope: d_max / T
  const std::array<AfterErrorAxis, 1> ok{a};
  CHECK(stop.configure(ok, 0.001));
}

}  // namespace
}  // namespace ncsim::tracking
