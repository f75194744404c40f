// The hold against the conveying direction (seed 004 §2.1.3, §4.4.2; P-AXIS-00555,
// P-CHAN-00366, P-CHAN-00367, P-CHAN-00374; docs/conveyor.md "Workspace: the hold methods").

#include "tracking/workspace_hold.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "jerk/jerk.hpp"

namespace {

using namespace ncsim;
using tracking::HoldConfig;
using tracking::HoldMethod;
using tracking::HoldState;
using tracking::WorkspaceHold;

// The laser portal's list (4.8.1): X [-200, 4000], pos_limit -190, factor 950, tolerance 5.
machines::ConveyorSyncChannel laser() {
  machines::ConveyorSyncChannel c;
  c.workspace.lower = Eigen::Vector3d(-200.0, -200.0, -100.0);
  c.workspace.upper = Eigen::Vector3d(4000.0, 2500.0, 300.0);
  c.hold_limit_vel_factor = 0.95;
  c.hold_limit_tolerance = 5.0;
  c.pos_limit = -190.0;
  return c;
}

constexpr std::array<int, 3> kXyz{0, 1, 2};

HoldConfig config(double pos_limit, bool optimised, double factor = 0.95) {
  machines::ConveyorSyncChannel c = laser();
  c.pos_limit = pos_limit;
  c.hold_limit_vel_factor = factor;
  auto h = tracking::hold_config(c, Eigen::Vector3d::UnitX(), optimised, kXyz.data(), 3);
  REQUIRE(h);
  return *h;
}

planner::Chain line_chain(double x0, double x1) {
  planner::AxisVec a{}, b{};
  a[0] = x0;
  b[0] = x1;
  return planner::Chain(planner::Segment::line(3, 0b111, a, b), 7);
}

}  // namespace

TEST_CASE("the hold line is pos_limit P-CHAN-00374 inside the cuboid, else the face") {
  CHECK(config(-190.0, false).line == -190.0);  // the laser list: 10 mm inside swe_neg
  CHECK(config(-190.0, false).face == -200.0);
  CHECK(config(0.0, false).line == -200.0);     // 0: not set (pick & place's list)
  CHECK(config(-250.0, false).line == -200.0);  // beyond the face: the face
  CHECK(config(-190.0, true).method == HoldMethod::optimised);
  CHECK(config(-190.0, false).method == HoldMethod::simple);
  // A belt in -X of MCS: the upper X face is against it.
  machines::ConveyorSyncChannel c = laser();
  c.pos_limit = 0.0;
  auto h = tracking::hold_config(c, -Eigen::Vector3d::UnitX(), false, kXyz.data(), 3);
  REQUIRE(h);
  CHECK(h->face == 4000.0);
  CHECK(h->sign == -1.0);
  CHECK(h->share == -1.0);
  CHECK(h->axis == 0);
  // No interpolated axis on X: no hold.
  constexpr std::array<int, 2> yz{1, 2};
  CHECK_FALSE(tracking::hold_config(laser(), Eigen::Vector3d::UnitX(), false, yz.data(), 2));
}

TEST_CASE("simple method: a -X block that would cross the line runs at factor x v_conv") {
  const planner::Chain path = line_chain(0.0, -600.0);
  HoldState st;
  st.path = &path;
  st.line = 7;
  st.feed = 200.0;
  st.v = 0.0;
  st.travel = 20.0;
  st.belt_v = 100.0;
  for (const double factor : {0.95, 1.0}) {
    WorkspaceHold h(config(-190.0, false, factor));
    // 600 mm at 200 mm/s against a 100 mm/s belt: MCS X goes to 20 - 300 = -280 < -190.
    CHECK(h.decide(st) == doctest::Approx(factor * 100.0));
    CHECK(h.capped());
    // The cap follows a belt that slows by more than the hysteresis, and holds otherwise.
    st.belt_v = 99.5;
    CHECK(h.decide(st) == doctest::Approx(factor * 100.0));
    st.belt_v = 80.0;
    CHECK(h.decide(st) == doctest::Approx(factor * 80.0));
    st.belt_v = 100.0;
    // The next block releases it.
    st.line = 8;
    const planner::Chain plus = line_chain(0.0, 300.0);
    st.path = &plus;
    CHECK(h.decide(st) == WorkspaceHold::kNone);
    CHECK_FALSE(h.capped());
    st.path = &path;
    st.line = 7;
  }
  // A feed below the belt velocity never goes against it in MCS: no cap.
  WorkspaceHold h(config(-190.0, false));
  st.feed = 90.0;
  CHECK(h.decide(st) == WorkspaceHold::kNone);
  // A short -X block that ends before the line: no cap.
  const planner::Chain short_block = line_chain(0.0, -100.0);
  st.path = &short_block;
  st.feed = 200.0;
  CHECK(h.decide(st) == WorkspaceHold::kNone);
}

TEST_CASE("optimised method: braking starts so that v_conv is reached just before the line") {
  // -X line at 300 mm/s against a 100 mm/s belt: the TCP approaches the line at 200 mm/s in MCS.
  const planner::Chain path = line_chain(0.0, -1000.0);
  const double d = 2000.0, j = 40000.0, t = 0.001, v = 300.0, vb = 100.0;
  WorkspaceHold h(config(-190.0, true, 1.0));
  HoldState st;
  st.path = &path;
  st.line = 7;
  st.feed = v;
  st.v = v;
  st.d_max = d;
  st.j_max = j;
  st.belt_v = vb;
  st.t_cycle = t;
  // The MCS distance the braking ramp 300 -> 100 mm/s uses up: path distance - belt travel.
  const jerk::Ramp ramp = jerk::velocity_ramp(v, 0.0, vb, d, d, j);
  const double used = jerk::distance(v, 0.0, ramp) - vb * ramp.time();
  // March the state at constant velocity; the first cycle that brakes.
  double trigger_gap = -1.0;
  for (int k = 0; k < 20000; ++k) {
    st.s = v * t * k;
    st.travel = vb * t * k;
    const double gap = h.inside(-st.s + st.travel);  // MCS X - line
    if (h.decide(st) != WorkspaceHold::kNone) {
      trigger_gap = gap;
      break;
    }
  }
  REQUIRE(trigger_gap > 0.0);
  // Brakes no later than needed and at most one cycle's approach (+ sampling) earlier.
  CHECK(trigger_gap >= used);
  CHECK(trigger_gap <= used + (v - vb) * t * 1.5 + 0.05);
  CHECK(h.cap() == doctest::Approx(100.0));
}

TEST_CASE("NC9080 only beyond the line by more than hold_limit_tolerance, or beyond the face") {
  WorkspaceHold h(config(-190.0, false));  // tolerance 5
  CHECK_FALSE(h.check(-150.0));
  CHECK_FALSE(h.check(-194.9));
  const auto m = h.check(-195.5);
  REQUIRE(m);
  CHECK(m->find("P-CHAN-00367") != std::string::npos);
  CHECK(m->find("-190") != std::string::npos);
  HoldConfig wide = config(-190.0, false);
  wide.tolerance = 50.0;  // a tolerance beyond the face: the face still stops it
  WorkspaceHold hw(wide);
  CHECK_FALSE(hw.check(-199.0));
  const auto f = hw.check(-200.5);
  REQUIRE(f);
  CHECK(f->find("face") != std::string::npos);
}

// Across block ends (docs/conveyor.md "Across block ends")
TEST_CASE("simple method across block ends: the run that crosses in a later block caps now") {
  // 5 blocks of -120 mm at 200 mm/s against a 100 mm/s belt: the crossing (MCS X -190) lies in
  // the 4th block; the whole run is capped from the first one.
  std::array<planner::Chain, 4> next;
  std::array<tracking::HoldEntry, 4> ahead;
  for (std::size_t k = 0; k < next.size(); ++k) {
    const double x = -120.0 * static_cast<double>(k + 1);
    next[k] = line_chain(x, x - 120.0);
    ahead[k] = tracking::HoldEntry{&next[k], 200.0, k + 1 == next.size()};
  }
  const planner::Chain first = line_chain(0.0, -120.0);
  HoldState st;
  st.path = &first;
  st.line = 7;
  st.feed = 200.0;
  st.belt_v = 100.0;
  WorkspaceHold h(config(-190.0, false, 1.0));
  CHECK(h.decide(st) == WorkspaceHold::kNone);  // nothing ahead known: block 1 alone is inside
  st.ahead = ahead.data();
  st.ahead_count = ahead.size();
  CHECK(h.decide(st) == doctest::Approx(100.0));
  // The next block goes on against the belt: the cap holds.
  st.path = &next[0];
  st.line = 8;
  st.ahead = ahead.data() + 1;
  st.ahead_count = ahead.size() - 1;
  CHECK(h.decide(st) == doctest::Approx(100.0));
  // A block along +Y ends the run: released, and nothing ahead crosses.
  planner::AxisVec a{}, b{};
  b[1] = 100.0;
  const planner::Chain y(planner::Segment::line(3, 0b111, a, b), 9);
  st.path = &y;
  st.line = 9;
  st.ahead_count = 0;
  CHECK(h.decide(st) == WorkspaceHold::kNone);
  // A run that stays inside the line: no cap.
  WorkspaceHold far(config(-190.0, false, 1.0));
  st.path = &first;
  st.line = 7;
  st.ahead = ahead.data();
  st.ahead_count = 1;  // 240 mm: MCS X ends at -120
  CHECK(far.decide(st) == WorkspaceHold::kNone);
}

TEST_CASE(
    "optimised method across block ends: braking for a line that continues in the next "
    "entry") {
  // The active entry ends 10 mm before the line; at 300 mm/s, 14 mm before it, the ramp to
  // v_conv (about 15 mm in MCS) must start now, and runs on in the next entry.
  const double d = 2000.0, j = 40000.0;
  const planner::Chain active = line_chain(0.0, -180.0);
  const planner::Chain next = line_chain(-180.0, -1000.0);
  const std::array<tracking::HoldEntry, 1> ahead{tracking::HoldEntry{&next, 300.0, false}};
  HoldState st;
  st.path = &active;
  st.line = 7;
  st.feed = 300.0;
  st.v = 300.0;
  st.d_max = d;
  st.j_max = j;
  st.belt_v = 100.0;
  st.s = 176.0;  // MCS X -176 (travel 0)
  st.ahead = ahead.data();
  st.ahead_count = 1;
  WorkspaceHold h(config(-190.0, true, 1.0));
  CHECK(h.decide(st) == doctest::Approx(100.0));
  // Without the next entry known the worst case is taken: the same decision.
  WorkspaceHold w(config(-190.0, true, 1.0));
  st.ahead_count = 0;
  CHECK(w.decide(st) == doctest::Approx(100.0));
  // The active entry ends with a stop: the path stands at -180, inside: no cap.
  WorkspaceHold s(config(-190.0, true, 1.0));
  st.stops = true;
  CHECK(s.decide(st) == WorkspaceHold::kNone);
}
