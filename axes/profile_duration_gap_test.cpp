// Prescribed durations against an independent decision of feasibility (docs/axes-profile.md,
// "Prescribed durations", gaps): every duration for which a profile is known to exist apart
// from plan_position_of_duration's families is met exactly; every NC5015 is either proven a
// physical gap (axes/profile_duration_bound.hpp: relaxed bounds without the jerk) or counted
// as undecided.

#include <doctest/doctest.h>

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

// Durations that have a profile by construction, apart from the stretched families: the
// fastest profile followed by a rest at a target at rest, or a stop (plan_stop), a rest and
// the fastest profile from there (at once for a start at rest). Every such profile keeps the
// limits because its parts do (each part is checked where the test plans it).
double known_feasible_from(const MotionState& start, const PositionTarget& target,
                           const Dynamics& d, double t_fastest) {
  if (target.v == 0.0 || (start.v == 0.0 && start.a == 0.0)) return t_fastest;
  Profile stop;
  if (ncsim::axes::plan_stop(start, d, stop) != Result::ok) return INFINITY;
  const MotionState rest{stop.end_state().p, 0.0, 0.0};
  Profile go;
  if (ncsim::axes::plan_position(rest, target, d, go, ProfileRule::time_optimal) != Result::ok)
    return INFINITY;
  return stop.duration() + go.duration();
}

}  // namespace

namespace {

struct Counts {
  int durations = 0;
  int met = 0;
  int proven_gaps = 0;
  int undecided = 0;
};

// 1500 seeded draws, durations t_fastest (1 + k step), k = 1..steps.
Counts sweep(int steps, double step) {
  Counts c;
  std::mt19937_64 rng(2026112530);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int& durations = c.durations;
  int& met = c.met;
  int& proven_gaps = c.proven_gaps;
  int& undecided = c.undecided;
  for (int n = 0; n < 1500; ++n) {
    ncsim::test::MoveDraw m = ncsim::test::draw_move(rng, ncsim::test::Arrival::half);
    if (unit(rng) < 0.25) m.start.v = m.start.a = 0.0;
    if (unit(rng) < 0.5) m.v1 = 0.0;
    const PositionTarget target{m.p1, m.v1};
    Profile fastest;
    REQUIRE(ncsim::axes::plan_position(m.start, target, m.lim, fastest,
                                       ProfileRule::time_optimal) == Result::ok);
    const double t_fastest = fastest.duration();
    const double t_known = known_feasible_from(m.start, target, m.lim, t_fastest);
    const ncsim::test::DurationBounds bounds = ncsim::test::duration_bounds(m.start, target, m.lim);
    for (int k = 1; k <= steps; ++k) {
      const double t = t_fastest * (1.0 + k * step);
      INFO("draw ", n, " v0=", m.start.v, " a0=", m.start.a, " p0=", m.start.p, " p1=", m.p1,
           " v1=", m.v1, " V=", m.lim.v_max, " A+=", m.lim.a_max, " A-=", m.lim.d_max,
           " J=", m.lim.j_max, " t_fastest=", t_fastest, " T=", t);
      ++durations;
      Profile p;
      const Result r = ncsim::axes::plan_position_of_duration(m.start, target, m.lim, t, p);
      if (r == Result::ok) {
        ++met;
        REQUIRE(std::abs(p.duration() / t - 1.0) <= 1e-9);
        const auto end = p.at(p.duration());
        REQUIRE(end.p == target.p);
        REQUIRE(end.v == target.v);
        REQUIRE(end.a == 0.0);
        const std::string bad = ncsim::test::profile_limit_violation(p, m.lim, m.start);
        REQUIRE_MESSAGE(bad.empty(), bad);
        continue;
      }
      REQUIRE(r == Result::error_not_synchronizable);
      REQUIRE(t < t_known);  // a known profile of this duration exists: no gap
      if (ncsim::test::proven_gap(bounds, t)) {
        ++proven_gaps;
      } else {
        ++undecided;
      }
    }
  }
  return c;
}

}  // namespace

TEST_CASE("every duration with a known profile is met exactly; every NC5015 is a gap or counted") {
  const Counts c = sweep(60, 1.0 / 30.0);  // up to 3x the fastest
  const int durations = c.durations;
  const int met = c.met;
  const int proven_gaps = c.proven_gaps;
  const int undecided = c.undecided;
  MESSAGE("durations ", durations, ", met ", met, ", proven gaps ", proven_gaps, ", undecided ",
          undecided);
  CHECK(durations == 90000);
  // Measured (session 30): before the rest families 221 durations answered NC5015, 12 of them
  // (2 draws) although a profile was known; the undecided ones are 3 starts moving away (v0 < 0 in
  // the frame toward the target), 2 arrivals against it (v1 < 0) and 2 within the bounds' jerk
  // slack (docs/axes-profile.md, "Prescribed durations", gaps). Session 31: draw 313's fastest
  // profile is now a braking turn through v = 0 (jerk/dip_cross.cpp); without its stretch (a
  // cruise at v1 after it) 89790 met, 62 undecided.
  CHECK(met == 89791);
  CHECK(proven_gaps == 148);
  CHECK(undecided == 61);
}

TEST_CASE("durations just above the fastest: the stretched two-peak change takes more of them") {
  // Up to 1 % above the fastest, where the single-peak family's levels can leave holes that a
  // two-peak change with a lowered dip fills (profile_optimal.cpp, plan_two_peak_of_duration).
  const Counts c = sweep(30, 1.0 / 3000.0);
  MESSAGE("durations ", c.durations, ", met ", c.met, ", proven gaps ", c.proven_gaps,
          ", undecided ", c.undecided);
  CHECK(c.durations == 45000);
  // Measured (session 30): without the stretched two-peak change 44941 met, 59 undecided;
  // without its first dip of the start's acceleration 44952, 48. Session 31: draw 313's fastest
  // is now a braking turn through v = 0 (jerk/dip_cross.cpp); without its stretch (a cruise at
  // v1 after it) its 30 durations up to 1 % above it were undecided (44927 met, 73 undecided).
  CHECK(c.met == 44957);
  CHECK(c.proven_gaps == 0);
  CHECK(c.undecided == 43);
}

TEST_CASE("a duration between the level family's runs is met by a stretched two-peak change") {
  // Draw 15 of the sweep above (docs/axes-profile.md, "Prescribed durations" (c)): the
  // single-peak family's levels take the fastest 0.038448 s up to 0.038453 s and then only
  // 0.038778..0.038788 s; scripts/duration_lp.py finds profiles up to 0.0387 s (a short dip of
  // the start's acceleration, then two peaks with a dip between; none at 0.0388 s). The
  // stretched two-peak change now takes up to 0.038655 s (before: NC5015 from 0.038453 s).
  // 0.0386 s needs the first dip.
  const Dynamics d{0x1.033c3cb02630ep+6, 0x1.1fe37ecfdda0cp+13, 0x1.5a3edf994cfcbp+3,
                   0x1.e171d615767b5p+14};
  const MotionState start{0x1.84038212e5170p+6, 0x1.69289710dc40bp+5, -0x1.63dda692ac002p+1};
  const PositionTarget target{0x1.8bcaf1a772fe7p+6, 0x1.bd2aed226340dp+5};
  for (const double duration : {0.03846, 0.0385, 0.03859, 0.0386, 0.03865}) {
    CAPTURE(duration);
    Profile p;
    REQUIRE(ncsim::axes::plan_position_of_duration(start, target, d, duration, p) == Result::ok);
    CHECK(std::abs(p.duration() / duration - 1.0) <= 1e-9);
    const auto end = p.at(p.duration());
    CHECK(end.p == target.p);
    CHECK(end.v == target.v);
    CHECK(end.a == 0.0);
    const std::string bad = ncsim::test::profile_limit_violation(p, d, start);
    CHECK_MESSAGE(bad.empty(), bad);
  }
}
