// plan_synchronized over seeded random cases (issue 11: "time-synchronised multi-axis motion,
// every axis gets exactly the slowest axis's duration"): 2..6 axes with their own limits over
// issue 11's ranges, starts inside the limits (moving in most cases), targets 1e-4..1e4 mm
// away, arrival velocities in a quarter of the axes, both profile rules, INDP TIME= (a longer
// prescribed duration) in a third of the cases.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "axes/profile.hpp"
#include "axes/profile_duration_bound.hpp"
#include "axes/profile_limits_check.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;
using ncsim::axes::Result;

constexpr std::size_t kMaxAxes = 6;

}  // namespace

TEST_CASE("synchronised random axes end bitwise on their targets at the slowest axis's duration") {
  std::mt19937_64 rng(2026112529);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int cases = 0;
  int stretched = 0;  // TIME= longer than every axis's own duration
  int gaps = 0;       // the common duration moved past an axis's gap
  int undecided = 0;  // ... not proven physical by the relaxed bounds
  int inexact = 0;    // axes whose duration is not t_common to the bit
  double worst = 0.0;
  for (int n = 0; n < 3000; ++n) {
    const std::size_t axes = 2 + static_cast<std::size_t>(unit(rng) * 5.0);  // 2..6
    std::array<MotionState, kMaxAxes> starts{};
    std::array<PositionTarget, kMaxAxes> targets{};
    std::array<Dynamics, kMaxAxes> dyn{};
    for (std::size_t i = 0; i < axes; ++i) {
      // draw_move: issue 11's ranges, starts inside the limits; a start at rest in a quarter.
      ncsim::test::MoveDraw m = ncsim::test::draw_move(rng, ncsim::test::Arrival::half);
      if (unit(rng) < 0.25) m.start.v = m.start.a = 0.0;
      if (unit(rng) < 0.5) m.v1 = 0.0;  // arrival velocities in a quarter of the axes
      starts[i] = m.start;
      targets[i] = PositionTarget{m.p1, m.v1};
      dyn[i] = m.lim;
    }
    const ProfileRule rule = unit(rng) < 0.5 ? ProfileRule::manual : ProfileRule::time_optimal;
    // Each axis alone under the same rule: the slowest one's duration is the common one.
    double t_slowest = 0.0;
    for (std::size_t i = 0; i < axes; ++i) {
      Profile alone;
      REQUIRE(ncsim::axes::plan_position(starts[i], targets[i], dyn[i], alone, rule) == Result::ok);
      t_slowest = std::max(t_slowest, alone.duration());
    }
    const double t_time = unit(rng) < 1.0 / 3.0 ? t_slowest * (1.0 + unit(rng)) : 0.0;
    const double t_want = std::max(t_slowest, t_time);
    std::array<Profile, kMaxAxes> out{};
    const auto s = std::span(starts).first(axes);
    const auto t = std::span(targets).first(axes);
    const auto d = std::span(dyn).first(axes);
    INFO("case ", n, " axes ", axes, std::string(rule == ProfileRule::manual ? " manual" : " fast"),
         " t_slowest=", t_slowest, " TIME=", t_time);
    REQUIRE(ncsim::axes::plan_synchronized(s, t, d, rule, t_time, std::span(out).first(axes)) ==
            Result::ok);
    ++cases;
    if (t_time > 0.0) ++stretched;
    const double t_common = out[0].duration();
    INFO("t_common=", t_common);
    if (t_common > t_want * (1.0 + 1e-9)) {
      // Later only past a gap: some axis has no profile of the wanted duration, proven a
      // physical gap by the relaxed bounds (profile_duration_bound.hpp) or counted undecided.
      bool gap = false;
      bool proven = false;
      for (std::size_t i = 0; i < axes; ++i) {
        Profile q;
        if (ncsim::axes::plan_position_of_duration(starts[i], targets[i], dyn[i], t_want, q) ==
            Result::error_not_synchronizable) {
          gap = true;
          proven =
              proven || ncsim::test::proven_gap(
                            ncsim::test::duration_bounds(starts[i], targets[i], dyn[i]), t_want);
        }
      }
      REQUIRE(gap);
      ++gaps;
      if (!proven) ++undecided;
    } else {
      REQUIRE(t_common >= t_want * (1.0 - 1e-9));
    }
    for (std::size_t i = 0; i < axes; ++i) {
      INFO("axis ", i, " v0=", starts[i].v, " a0=", starts[i].a, " p1=", targets[i].p,
           " v1=", targets[i].v, " V=", dyn[i].v_max, " A+=", dyn[i].a_max, " A-=", dyn[i].d_max,
           " J=", dyn[i].j_max);
      const double dev = std::abs(out[i].duration() / t_common - 1.0);
      worst = std::max(worst, dev);
      if (dev != 0.0) ++inexact;
      REQUIRE(dev <= 1e-14);  // seen: 3.6e-15 (the stretched profiles' own rounding)
      const auto end = out[i].at(out[i].duration());
      REQUIRE(end.p == targets[i].p);
      REQUIRE(end.v == targets[i].v);
      REQUIRE(end.a == 0.0);
      const std::string bad = ncsim::test::profile_limit_violation(out[i], dyn[i], starts[i]);
      REQUIRE_MESSAGE(bad.empty(), bad);
    }
  }
  MESSAGE("cases ", cases, ", TIME= ", stretched, ", past a gap ", gaps, " (undecided ", undecided,
          "), durations off the bit ", inexact, " (worst ", worst, ")");
  CHECK(cases == 3000);
  CHECK(gaps == 5);
  CHECK(undecided == 1);
}

TEST_CASE("a prescribed duration from a start released beyond V is met by the turn, not 0.18 s") {
  // Case 388 of the seeded test above (jerk/move_test.cpp has the kernel's side): asked for
  // 599.198 s, plan_position_of_duration returned ok with a 0.178 s profile, so the synchronised
  // axes ended at different times. The turn takes exactly the duration.
  const Dynamics d{0x1.142096cb3afc7p+8, 0x1.319f3e226a50cp+13, 0x1.5a250b287ffb4p+16,
                   0x1.666e040cc9504p+19};
  const MotionState start{-0x1.3749b8aaf1c5ap+6, 0x1.a352d098852a1p+6, -0x1.13e7db1e75f2fp+15};
  const PositionTarget target{-0x1.de39a262fc5b4p+6, 0x1.092e7dd64221ep+8};
  const double duration = 0x1.2b995c8630c8cp+9;
  Profile p;
  REQUIRE(ncsim::axes::plan_position_of_duration(start, target, d, duration, p) == Result::ok);
  CHECK(p.duration() == doctest::Approx(duration).epsilon(1e-14));
  CHECK(p.at(p.duration()).p == target.p);
  CHECK(p.at(p.duration()).v == target.v);
  const std::string bad = ncsim::test::profile_limit_violation(p, d, start);
  CHECK_MESSAGE(bad.empty(), bad);
}
