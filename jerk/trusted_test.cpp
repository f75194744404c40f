// Tests of jerk/trusted.hpp: for valid inputs the unchecked entry points answer exactly what the
// checked ones do (the same status and the same phases, bit for bit), two_peak_applies holds
// wherever a two-peak change is found, and the checked ones still reject what the trusted ones
// leave to their caller.

#include "jerk/trusted.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "jerk/jerk.hpp"
#include "jerk/test_random.hpp"

namespace {

using ncsim::jerk::Move;
using ncsim::jerk::Reversal;
using ncsim::jerk::Status;
using ncsim::jerk::TwoPeak;

bool same_move(const Move& a, const Move& b) {
  return a.sign == b.sign && a.cross.duration == b.cross.duration &&
         a.cross.a_peak == b.cross.a_peak && a.first.duration == b.first.duration &&
         a.first.a_peak == b.first.a_peak && a.second.duration == b.second.duration &&
         a.second.a_peak == b.second.a_peak && a.v_level == b.v_level && a.t_cruise == b.t_cruise;
}

}  // namespace

TEST_CASE("the trusted searches answer what the checked ones answer for valid inputs") {
  std::mt19937_64 rng(2525);
  int moves = 0;
  int two_peaks = 0;
  int turns = 0;
  int applying = 0;
  for (int i = 0; i < 4000; ++i) {
    const auto d = ncsim::test::draw_move(rng, ncsim::test::Arrival::half);
    Move m1;
    Move m2;
    const Status s1 = ncsim::jerk::fastest_move(d.start, d.p1, d.v1, d.lim, m1);
    REQUIRE(ncsim::jerk::detail::fastest_move_trusted(d.start, d.p1, d.v1, d.lim, m2) == s1);
    if (s1 == Status::ok) {
      ++moves;
      CHECK(same_move(m1, m2));
    }
    TwoPeak t1;
    TwoPeak t2;
    const Status s2 = ncsim::jerk::two_peak_move(d.start, d.p1, d.v1, d.lim, t1);
    REQUIRE(ncsim::jerk::detail::two_peak_move_trusted(d.start, d.p1, d.v1, d.lim, t2) == s2);
    const bool applies = ncsim::jerk::detail::two_peak_applies(d.start, d.p1, d.v1, d.lim);
    applying += applies ? 1 : 0;
    if (s2 == Status::ok) {
      CHECK(applies);  // a change found where the shape applies only
      ++two_peaks;
      CHECK(t1.duration == t2.duration);
      CHECK(t1.jerk == t2.jerk);
    }
    Reversal r1;
    Reversal r2;
    const Status s3 = ncsim::jerk::reversal_move(d.start, d.p1, d.v1, d.lim, r1);
    REQUIRE(ncsim::jerk::detail::reversal_move_trusted(d.start, d.p1, d.v1, d.lim, r2) == s3);
    if (s3 == Status::ok) {
      ++turns;
      CHECK(same_move(r1.out, r2.out));
      CHECK(same_move(r1.back, r2.back));
    }
  }
  // Each family answered in a share of the draws (the comparison is not empty; with this seed
  // 2832 moves, 10 two-peak changes, 1194 turns).
  CHECK(moves > 2000);
  CHECK(two_peaks >= 5);
  CHECK(applying > two_peaks);  // the test is a filter, not the search
  CHECK(turns > 500);
}

TEST_CASE("the checked searches reject the inputs the trusted ones leave to their caller") {
  const ncsim::jerk::State start{0.0, 1.0, 0.0};
  const ncsim::jerk::Limits lim{100.0, 1000.0, 1000.0, 1e5};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Move m;
  TwoPeak t;
  Reversal r;
  CHECK(ncsim::jerk::fastest_move(start, nan, 0.0, lim, m) == Status::invalid_input);
  CHECK(ncsim::jerk::fastest_move(start, 10.0, 200.0, lim, m) == Status::invalid_input);
  CHECK(ncsim::jerk::two_peak_move(start, 10.0, 0.0, {100.0, 0.0, 1000.0, 1e5}, t) ==
        Status::invalid_input);
  CHECK(ncsim::jerk::reversal_move({0.0, nan, 0.0}, 10.0, 5.0, lim, r) == Status::invalid_input);
}
