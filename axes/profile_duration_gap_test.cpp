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

TEST_CASE("every duration with a known profile is met exactly; every NC5015 is a gap or counted") {
  std::mt19937_64 rng(2026112530);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int durations = 0;
  int met = 0;
  int proven_gaps = 0;
  int undecided = 0;
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
    for (int k = 1; k <= 60; ++k) {
      const double t = t_fastest * (1.0 + k / 30.0);  // up to 3x the fastest
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
  MESSAGE("durations ", durations, ", met ", met, ", proven gaps ", proven_gaps, ", undecided ",
          undecided);
  CHECK(durations == 90000);
  // Measured (session 30): before the rest families 221 durations answered NC5015, 12 of them
  // (2 draws) although a profile was known; the undecided ones are 3 starts moving away (v0 < 0 in
  // the frame toward the target), 2 arrivals against it (v1 < 0) and 2 within the bounds' jerk
  // slack (docs/axes-profile.md, "Prescribed durations", gaps).
  CHECK(met == 89791);
  CHECK(proven_gaps == 148);
  CHECK(undecided == 61);
}
