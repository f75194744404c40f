// The curvature step of the level searches (jerk/move.cpp top_level, jerk/reverse.cpp; the
// "level classifier" of issue 11, docs/axes-profile.md "Speed") against the Newton-only search
// it replaces (detail::fastest_move_newton) over issue 11's ranges: the same answer, the same
// case, the same time to 1e-12 relative (or to the search's tolerance, below), the same end.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "jerk/jerk.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::jerk::Move;
using ncsim::jerk::State;
using ncsim::jerk::Status;

constexpr double kEps = std::numeric_limits<double>::epsilon();

using Draw = ncsim::test::MoveDraw;

// Issue 11's ranges, an arrival velocity in half of the draws (jerk/test_random.hpp).
Draw draw(std::mt19937_64& rng) {
  return ncsim::test::draw_move(rng, ncsim::test::Arrival::half);
}

// The same case: the same frame, crossing or not, and the same limits held.
void check_same_case(const Move& a, const Move& b) {
  CHECK(a.sign == b.sign);
  CHECK((a.cross.time() > 0.0) == (b.cross.time() > 0.0));
  CHECK((a.first.duration[1] > 0.0) == (b.first.duration[1] > 0.0));
  CHECK((a.second.duration[1] > 0.0) == (b.second.duration[1] > 0.0));
}

}  // namespace

// Both searches stop where the chain's distance is within 8 eps of the way the ramps travel at
// V (the rounding of that chain) short of D. Over a tiny D after a long detour that tolerance
// is large against D, and the two levels may differ by it (seen: 10 of 100,000 draws, times
// 1.5e-12 to 7.8e-11 relative apart, e.g. D = 1.2e-4 mm from v0 = -3 mm/s at V = 1712 mm/s).
// So the times agree to 1e-12 relative or the cruise distances to 16 eps of a bound on that way.
TEST_CASE("the curvature step finds the single-peak level of the Newton-only search") {
  std::mt19937_64 rng(20261123);
  int solved = 0;
  int loose = 0;
  for (int n = 0; n < 100000; ++n) {
    const Draw d = draw(rng);
    Move fast;
    Move oracle;
    const Status st = ncsim::jerk::fastest_move(d.start, d.p1, d.v1, d.lim, fast);
    const Status st_o =
        ncsim::jerk::detail::fastest_move_newton(d.start, d.p1, d.v1, d.lim, oracle);
    CAPTURE(n);
    REQUIRE(st == st_o);
    if (st != Status::ok) continue;
    ++solved;
    check_same_case(fast, oracle);
    const double t = oracle.time();
    const double dt = std::abs(fast.time() - t);
    if (dt > 1e-12 * t) {
      ++loose;
      const double v = d.lim.v_max + std::abs(d.start.v);
      const double a_lo = std::min(d.lim.a_max, d.lim.d_max);
      const double a_hi = std::max(d.lim.a_max, d.lim.d_max);
      const double way = std::abs(d.p1 - d.start.p) + 4.0 * (v * v / a_lo + v * a_hi / d.lim.j_max);
      CHECK(dt * std::min(fast.v_level, oracle.v_level) <= 16.0 * kEps * way);
    }
    // Both end at the target (the end state of the phases, to the same rounding).
    const State e = ncsim::jerk::end_state(d.start, fast);
    const State e_o = ncsim::jerk::end_state(d.start, oracle);
    const double scale = std::abs(d.p1) + std::abs(d.start.p) + d.lim.v_max * t;
    CHECK(std::abs(e.p - e_o.p) <= 1e-12 * scale);
    CHECK(std::abs(e.v - e_o.v) <= 1e-12 * d.lim.v_max);
  }
  CHECK(solved > 50000);
  CHECK(loose < 100);
}
