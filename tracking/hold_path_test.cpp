// The path ahead of the workspace hold (tracking/hold_path; docs/conveyor.md "Across block ends"):
// the rest of the active entry, then the following entries, block by block; beyond what is
// known the worst case (straight against the conveying direction), or standing at a stop.

#include "tracking/hold_path.hpp"

#include <doctest/doctest.h>

#include <array>

namespace {

using namespace ncsim;

planner::Chain line_chain(double x0, double x1, std::uint32_t line) {
  planner::AxisVec a{}, b{};
  a[0] = x0;
  b[0] = x1;
  return planner::Chain(planner::Segment::line(3, 0b111, a, b), line);
}

}  // namespace

TEST_CASE("the path ahead runs through the active entry's rest and the following entries") {
  planner::Chain active = line_chain(0.0, -100.0, 1);
  active.append(line_chain(-100.0, -200.0, 2));  // two blocks in one entry
  const planner::Chain next = line_chain(-200.0, -250.0, 3);
  const std::array<tracking::HoldEntry, 1> ahead{tracking::HoldEntry{&next, 50.0, false}};
  tracking::HoldPath p(active, 30.0, 200.0, false, ahead.data(), ahead.size(), 0, 1.0);
  CHECK(p.known() == doctest::Approx(220.0));
  CHECK(p.q(0.0) == doctest::Approx(-30.0));
  CHECK(p.q(100.0) == doctest::Approx(-130.0));
  CHECK(p.q(200.0) == doctest::Approx(-230.0));
  CHECK(p.q(10.0) == doctest::Approx(-40.0));  // back again: the cursor restarts
  // Beyond what is known, no stop: the worst case, straight against +X.
  CHECK(p.q(300.0) == doctest::Approx(-330.0));
  // Block by block: the rest of block 1, block 2, then the next entry with its feed.
  tracking::HoldBlock b;
  REQUIRE(p.next_block(b));
  CHECK(b.from == doctest::Approx(30.0));
  CHECK(b.to == doctest::Approx(100.0));
  CHECK(b.ahead == doctest::Approx(0.0));
  CHECK(b.feed == 200.0);
  REQUIRE(p.next_block(b));
  CHECK(b.from == doctest::Approx(100.0));
  CHECK(b.to == doctest::Approx(200.0));
  CHECK(b.ahead == doctest::Approx(70.0));
  REQUIRE(p.next_block(b));
  CHECK(b.path == &next);
  CHECK(b.from == 0.0);
  CHECK(b.to == doctest::Approx(50.0));
  CHECK(b.ahead == doctest::Approx(170.0));
  CHECK(b.feed == 50.0);
  CHECK_FALSE(p.next_block(b));
}

TEST_CASE("nothing beyond a stop: the path stands at its end") {
  const planner::Chain active = line_chain(0.0, -100.0, 1);
  const planner::Chain next = line_chain(-100.0, -200.0, 2);
  const planner::Chain after = line_chain(-200.0, -300.0, 3);
  const std::array<tracking::HoldEntry, 2> ahead{tracking::HoldEntry{&next, 50.0, true},
                                                 tracking::HoldEntry{&after, 50.0, false}};
  tracking::HoldPath p(active, 0.0, 100.0, false, ahead.data(), ahead.size(), 0, 1.0);
  CHECK(p.known() == doctest::Approx(200.0));
  CHECK(p.q(500.0) == doctest::Approx(-200.0));
  // The active entry itself stops: its end is all.
  tracking::HoldPath q(active, 0.0, 100.0, true, ahead.data(), ahead.size(), 0, 1.0);
  CHECK(q.known() == doctest::Approx(100.0));
  CHECK(q.q(150.0) == doctest::Approx(-100.0));
}

TEST_CASE("the bound: at most kHoldAhead following entries, the worst case after them") {
  std::array<planner::Chain, tracking::kHoldAhead + 4> chains;
  std::array<tracking::HoldEntry, tracking::kHoldAhead + 4> ahead;
  for (std::size_t k = 0; k < chains.size(); ++k) {
    const double x = -10.0 * static_cast<double>(k + 1);
    chains[k] = line_chain(x, x - 10.0, static_cast<std::uint32_t>(k + 2));
    ahead[k] = tracking::HoldEntry{&chains[k], 100.0, false};
  }
  const planner::Chain active = line_chain(0.0, -10.0, 1);
  // The conveying direction -X (sign -1): the worst case beyond runs towards +X.
  tracking::HoldPath p(active, 0.0, 100.0, false, ahead.data(), ahead.size(), 0, -1.0);
  const double known = 10.0 * static_cast<double>(tracking::kHoldAhead + 1);
  CHECK(p.known() == doctest::Approx(known));
  CHECK(p.q(known + 5.0) == doctest::Approx(-known + 5.0));
}
