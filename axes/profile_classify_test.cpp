// The lower bounds that let the time-optimal rule skip candidates (profile_classify.hpp) are
// below the candidates' planned durations, over seeded random cases across issue 11's ranges
// (distances 1e-4..1e4 mm, V 1..1e4 mm/s, A 10..1e5 mm/s^2, J 1e2..1e7 mm/s^3, starts inside
// the limits, arrival velocities in a quarter of the cases). A bound above its candidate
// would let plan_fastest / plan_position drop a faster candidate; with every bound below, a
// skip changes nothing (a candidate is only taken when strictly faster).

#include "axes/profile_classify.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "axes/profile.hpp"
#include "axes/profile_builder.hpp"
#include "axes/profile_limits_check.hpp"
#include "axes/profile_outside.hpp"
#include "jerk/jerk.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;
using ncsim::axes::Result;
using ncsim::test::log_uniform;
namespace detail = ncsim::axes::detail;

struct Case {
  MotionState start;
  PositionTarget target;
  Dynamics dyn;
};

// A start inside the limits: |v| <= V, |a| within A+ where it speeds the motion up, A- where it
// slows it down; the target 1e-4..1e4 mm away on either side, with an arrival velocity in a
// share p_arrival of the cases.
Case draw(std::mt19937_64& rng, double p_arrival = 0.25) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Case c;
  c.dyn = {log_uniform(rng, 1.0, 1e4), log_uniform(rng, 10.0, 1e5), log_uniform(rng, 10.0, 1e5),
           log_uniform(rng, 1e2, 1e7)};
  c.start.p = (u(rng) - 0.5) * 100.0;
  c.start.v = (2.0 * u(rng) - 1.0) * c.dyn.v_max;
  const double a_cap = u(rng) < 0.5 ? c.dyn.a_max : c.dyn.d_max;
  c.start.a = (2.0 * u(rng) - 1.0) * a_cap;
  if (c.start.a * c.start.v > 0.0 && std::abs(c.start.a) > c.dyn.a_max) {
    c.start.a = std::copysign(c.dyn.a_max, c.start.a);
  }
  if (c.start.a * c.start.v < 0.0 && std::abs(c.start.a) > c.dyn.d_max) {
    c.start.a = std::copysign(c.dyn.d_max, c.start.a);
  }
  const double side = u(rng) < 0.5 ? -1.0 : 1.0;
  c.target.p = c.start.p + side * log_uniform(rng, 1e-4, 1e4);
  if (u(rng) < p_arrival) c.target.v = (2.0 * u(rng) - 1.0) * c.dyn.v_max;
  return c;
}

// plan_fastest's candidate 4: stop (append_stop), then the fastest move from rest (to an
// arrival velocity the single-peak move jerk::fastest_move; infinite where it has none).
double stop_then_go_duration(const Case& c) {
  Profile stop;
  detail::ProfileBuilder b(stop, c.start);
  detail::append_stop(b, c.dyn);
  b.finish();
  const MotionState rest{stop.end_state().p, 0.0, 0.0};
  if (c.target.v != 0.0) {
    ncsim::jerk::Move m;
    if (ncsim::jerk::fastest_move(rest, c.target.p, c.target.v, c.dyn, m) !=
        ncsim::jerk::Status::ok) {
      return std::numeric_limits<double>::infinity();
    }
    return stop.duration() + m.time();
  }
  Profile go;
  REQUIRE(ncsim::axes::plan_position(rest, c.target, c.dyn, go, ProfileRule::time_optimal) ==
          Result::ok);
  return stop.duration() + go.duration();
}

}  // namespace

TEST_CASE("the stop-then-go bound is below the stop-then-go duration (100000 seeded cases)") {
  std::mt19937_64 rng(20261123);
  int skippable = 0;
  for (int i = 0; i < 100000; ++i) {
    const Case c = draw(rng);
    if (c.start.v == 0.0 && c.start.a == 0.0) continue;
    const double bound = detail::stop_then_go_bound(c.start, c.target, c.dyn);
    const double t = stop_then_go_duration(c);
    INFO("case " << i << " v0 " << c.start.v << " a0 " << c.start.a << " p1 " << c.target.p
                 << " v1 " << c.target.v);
    REQUIRE(bound <= t);
    if (bound >= 0.9 * t) ++skippable;
  }
  CHECK(skippable > 50000);  // the bound is close enough to decide (else it would cost only)
}

TEST_CASE(
    "to an arrival velocity the stop-then-go bound is below the candidate, infinite only "
    "where the single peak from rest has none (100000 seeded cases)") {
  // Issue 11, session 26: plan_fastest skips candidate 4 where this bound is >= the best found,
  // or infinite: then jerk::fastest_move from the stop point must fail.
  std::mt19937_64 rng(2026112426);
  int none = 0;
  int exists = 0;
  int skippable = 0;
  for (int i = 0; i < 100000; ++i) {
    const Case c = draw(rng, 1.0);
    if (c.start.v == 0.0 && c.start.a == 0.0) continue;
    const double bound = detail::stop_then_go_bound(c.start, c.target, c.dyn);
    const double t = stop_then_go_duration(c);
    INFO("case " << i << " v0 " << c.start.v << " a0 " << c.start.a << " p1 " << c.target.p
                 << " v1 " << c.target.v);
    REQUIRE(bound <= t);
    if (std::isinf(bound)) ++none;
    if (std::isinf(t)) continue;
    ++exists;
    if (bound >= 0.9 * t) ++skippable;
  }
  MESSAGE("no go part " << none << ", go part " << exists << ", bound >= 0.9 t " << skippable);
  CHECK(none > 30000);
  CHECK(skippable > exists / 2);
}

TEST_CASE("the manual bound is below the manual plan's duration (100000 seeded cases)") {
  // Issue 11, session 28: where it is not 0 (the manual stops and returns) the bound is the
  // plan's own parts (the manual's rest-to-rest time, not the fastest one), so it is also
  // within 1e-6 of the plan's duration: tight enough that plan_position skips the manual plan
  // wherever the time-optimal candidates are faster. Failed before (the bound took the fastest
  // rest-to-rest time: within 1e-6 in 3,041 of 9,222).
  std::mt19937_64 rng(112);
  int bounded = 0;
  int tight = 0;
  for (int i = 0; i < 100000; ++i) {
    const Case c = draw(rng);
    // From outside the limits the manual plan first recovers
    // (profile_outside.hpp, manual_recover); the bound is not used there (profile_general.cpp).
    if (detail::outside_limits(c.start, c.dyn)) continue;
    const double bound = detail::manual_bound(c.start, c.target, c.dyn);
    Profile manual;
    REQUIRE(ncsim::axes::plan_position(c.start, c.target, c.dyn, manual, ProfileRule::manual) ==
            Result::ok);
    INFO("case " << i << " v0 " << c.start.v << " a0 " << c.start.a << " p1 " << c.target.p
                 << " v1 " << c.target.v);
    REQUIRE(bound <= manual.duration());
    if (bound > 0.0) ++bounded;
    if (bound >= (1.0 - 1e-6) * manual.duration()) ++tight;
  }
  MESSAGE("bounded " << bounded << ", within 1e-6 " << tight);
  CHECK(bounded > 5000);  // starts moving against an arrival velocity: ~1/8 of the cases
  CHECK(tight == bounded);
}

TEST_CASE("the two-peak bound is below the two-peak change's duration (1000000 seeded cases)") {
  // Issue 11, session 24: plan_fastest skips jerk::two_peak_move where this bound is >= the
  // best candidate found. Arrival velocities in half of the cases (the two-peak change needs
  // v1 beyond the start's release velocity). 3,000,000 draws (5334 changes) checked by hand.
  std::mt19937_64 rng(2026112401);
  int changes = 0;
  for (int i = 0; i < 1000000; ++i) {
    const Case c = draw(rng, 0.5);
    ncsim::jerk::TwoPeak tp;
    if (ncsim::jerk::two_peak_move(c.start, c.target.p, c.target.v, c.dyn, tp) !=
        ncsim::jerk::Status::ok) {
      continue;
    }
    ++changes;
    INFO("case " << i << " v0 " << c.start.v << " a0 " << c.start.a << " p1 " << c.target.p
                 << " v1 " << c.target.v);
    REQUIRE(detail::two_peak_bound(c.start, c.target, c.dyn) <= tp.time());
    // With `enough` the bound stops early, never above the full one.
    const double full = detail::two_peak_bound(c.start, c.target, c.dyn);
    REQUIRE(detail::two_peak_bound(c.start, c.target, c.dyn, 0.5 * full) <= full);
  }
  CHECK(changes > 1000);  // ~1800: the change applies only in a narrow window of distances
}

TEST_CASE("the stop point is append_stop's end (position to 1e-12 relative, duration to 1e-15)") {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const Case c = draw(rng);
    Profile stop;
    detail::ProfileBuilder b(stop, c.start);
    detail::append_stop(b, c.dyn);
    b.finish();
    const detail::StopPoint sp = detail::stop_point(c.start, c.dyn);
    const double scale = std::abs(c.start.p) + std::abs(stop.end_state().p - c.start.p);
    REQUIRE(std::abs(sp.p - stop.end_state().p) <= 1e-12 * scale + 1e-300);
    REQUIRE(std::abs(sp.t - stop.duration()) <= 1e-15 * stop.duration() + 1e-300);
  }
}

TEST_CASE("the fastest rest-to-rest time is the planned profile's duration") {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 20000; ++i) {
    const Case c = draw(rng);
    const double dist = std::abs(c.target.p - c.start.p);
    Profile p;
    REQUIRE(ncsim::axes::plan_position(MotionState{0.0, 0.0, 0.0}, PositionTarget{dist, 0.0}, c.dyn,
                                       p, ProfileRule::time_optimal) == Result::ok);
    REQUIRE(std::abs(detail::rest_to_rest_fastest_time(dist, c.dyn) - p.duration()) <=
            1e-12 * p.duration());
  }
}

TEST_CASE("with the skips the time-optimal plan is never slower than a skipped candidate") {
  // The observable form of "a skip changes nothing", where the skips apply: the plan is at most
  // as long as stop-then-go (where it exists) and as the manual plan where the manual's
  // stop-and-return has a bound (1e-9 relative, issue 11's proof tolerance). (Elsewhere the
  // manual can be faster than a direct single-peak plan: docs/axes-profile.md, "Weak points".)
  std::mt19937_64 rng(4242);
  int manual_cases = 0;
  for (int i = 0; i < 100000; ++i) {
    const Case c = draw(rng);
    if (c.start.v == 0.0 && c.start.a == 0.0) continue;
    // A start whose release of a at full jerk ends beyond V (or that crosses v = 0 above A+) is
    // outside the limits (axes/profile_outside.hpp): there the least time outside comes first
    // and the total may be longer (docs/axes-profile-outside.md).
    if (detail::outside_limits(c.start, c.dyn)) continue;
    Profile best;
    REQUIRE(ncsim::axes::plan_position(c.start, c.target, c.dyn, best, ProfileRule::time_optimal) ==
            Result::ok);
    INFO("case " << i << " v0 " << c.start.v << " a0 " << c.start.a << " p1 " << c.target.p
                 << " v1 " << c.target.v);
    REQUIRE(best.end_state().p == c.target.p);
    REQUIRE(best.duration() <= stop_then_go_duration(c) * (1.0 + 1e-9));
    if (c.target.v != 0.0 && detail::manual_bound(c.start, c.target, c.dyn) > 0.0) {
      Profile manual;
      REQUIRE(ncsim::axes::plan_position(c.start, c.target, c.dyn, manual, ProfileRule::manual) ==
              Result::ok);
      REQUIRE(best.duration() <= manual.duration() * (1.0 + 1e-9));
      ++manual_cases;
    }
  }
  CHECK(manual_cases > 5000);
}

TEST_CASE("from every start inside the limits time-optimal is never slower than the manual plan") {
  // Issue 11 (late round): the manual plan against the time-optimal one directly (no bound
  // decides which cases are compared), 2 x 50000 seeded cases: arrival velocities in a quarter
  // of the cases and in every case. Starts outside the limits (profile_outside.hpp) are left
  // out: there the shortest time outside comes first by decision (docs/axes-profile-outside.md).
  int compared = 0;
  for (const double p_arrival : {0.25, 1.0}) {
    std::mt19937_64 rng(p_arrival < 1.0 ? 97 : 98);
    for (int i = 0; i < 50000; ++i) {
      const Case c = draw(rng, p_arrival);
      if (detail::outside_limits(c.start, c.dyn)) continue;
      Profile best;
      Profile manual;
      REQUIRE(ncsim::axes::plan_position(c.start, c.target, c.dyn, best,
                                         ProfileRule::time_optimal) == Result::ok);
      REQUIRE(ncsim::axes::plan_position(c.start, c.target, c.dyn, manual, ProfileRule::manual) ==
              Result::ok);
      INFO("case " << i << " v0 " << c.start.v << " a0 " << c.start.a << " p1 " << c.target.p
                   << " v1 " << c.target.v);
      REQUIRE(best.end_state().p == c.target.p);
      REQUIRE(best.at(best.duration()).p == c.target.p);
      REQUIRE(best.at(best.duration()).v == c.target.v);
      REQUIRE(best.at(best.duration()).a == 0.0);
      REQUIRE(best.duration() <= manual.duration() * (1.0 + 1e-9));
      // Both plans within V, A+/A-, J (axes/profile_limits_check.hpp; starts inside here).
      for (const Profile* p : {&best, &manual}) {
        const std::string bad = ncsim::test::profile_limit_violation(*p, c.dyn, c.start);
        const char* rule = p == &best ? "time-optimal" : "manual";
        INFO(rule);
        REQUIRE_MESSAGE(bad.empty(), bad);
      }
      ++compared;
    }
  }
  CHECK(compared > 70000);  // 73635: about a quarter of the draws start outside
}

TEST_CASE("the former weak point (+0.97 % against the manual) is an outside start, now faster") {
  // docs/axes-profile.md "Weak points" (seed 4242, case 19584): braking from -2667 mm/s with
  // a0 = 8169 mm/s^2 crosses v = 0 at |a| = sqrt(a0^2 - 2 J |v0|) = 4815 mm/s^2 > A+ = 1289: a
  // forced excess, outside the limits (profile_outside.hpp). Time-optimal took 3.44768 s
  // against the manual's 3.41473 s before the recovery; then the recovery came first and the
  // plan took 3.15219 s; since the turn search finds the fastest turn (jerk/reverse.cpp, session
  // 23) 2.89725 s.
  const Case c{
      {0x1.20e7f522ef016p+5, -0x1.4d6b030a676bp+11, 0x1.fe8abab586ad1p+12},
      {0x1.20afb6a12c0c3p+5, -0x1.4b3f083e5360bp+10},
      {0x1.9d2c7a87bce36p+11, 0x1.423f85a75be86p+10, 0x1.f298bd24bf988p+13, 0x1.fdfd23ff38305p+12}};
  REQUIRE(detail::outside_limits(c.start, c.dyn));
  Profile best;
  Profile manual;
  REQUIRE(ncsim::axes::plan_position(c.start, c.target, c.dyn, best, ProfileRule::time_optimal) ==
          Result::ok);
  REQUIRE(ncsim::axes::plan_position(c.start, c.target, c.dyn, manual, ProfileRule::manual) ==
          Result::ok);
  CHECK(manual.duration() == doctest::Approx(3.41473).epsilon(1e-5));
  CHECK(best.duration() == doctest::Approx(2.89725).epsilon(1e-5));
  CHECK(best.end_state().p == c.target.p);
  CHECK(best.end_state().v == c.target.v);
}
