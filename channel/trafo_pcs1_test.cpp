// Machining in PCS1 under #TRAFO ON (issue 14; docs/conveyor.md "Conveyor tracking under
// #TRAFO ON", "Machining in PCS1"): the belt's share of the joints' acceleration and jerk on a
// PCS1 block (tracking::belt_share: the travel it covers, the overload behind NC6211), spline
// pieces, the tolerance ball between two PCS1 blocks, G00 and G93 in PCS1 and an override above 100
// %.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "channel/trafo_test_support.hpp"
#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "planner/blend.hpp"
#include "program/program_source.hpp"
#include "program/trafo.hpp"
#include "tracking/test_port.hpp"
#include "tracking/trafo_sync.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;

using channel::test::check_far_side;
using channel::test::picker;
using channel::test::track_clean;
using channel::test::Tracked;

}  // namespace

TEST_CASE("a PCS1 block the belt carries towards the far side keeps the joints' a and j") {
  // docs/conveyor.md "Machining in PCS1": the belt carries the block while it runs; the joints
  // see q(s, b) = IK(x(s) + b e), whose belt terms (2 q_sb v w + q_bb w^2 in the acceleration,
  // 3 q_ssb v^2 w + 3 q_sbb v w^2 + q_bbb w^3 + 3 q_sb a w in the jerk) and whose growth of the
  // path's own terms the planner does not see at belt travel 0. The block runs after a dwell of
  // 0.5 s in PCS1 (the belt carries it 150 / 250 mm further) from X-450 down to Z-880, where
  // the inverse is most curved. Without the acceleration and jerk shares (the velocity cap
  // alone) the joints' jerk reached 135.4 % (300 mm/s) and 152.6 % (500 mm/s) of J here, 69 /
  // 122 audit violations (measured); with them 70.4 % and 79.8 %, none.
  const double belts[] = {300.0, 500.0};  // [mm/s]
  for (const double belt : belts) {
    const std::string program =
        "%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-400 Y0 Z-700 F60000\n"
        "N40 #SYNC IN [CONV_VEL=" +
        std::to_string(static_cast<int>(belt * 60.0)) +
        "]\nN50 G01 X-450 Y0 Z-700 F60000\nN55 G04 0.5\nN60 G01 X-200 Y-200 Z-880 F60000\n"
        "N70 G04 0.05\nN80 #SYNC OUT\nN90 M30\n";
    CAPTURE(program);
    const Tracked r = track_clean(program, belt);
    check_far_side(r, 8, 8, belt);
  }
}

TEST_CASE(
    "B-spline pieces in PCS1 the belt carries towards the far side keep the joints' a and j") {
  // docs/conveyor.md "Machining in PCS1": a spline piece in PCS1 runs with the belt on top as a
  // line or an arc does, so it gets the same shares (tracking::belt_share samples the piece's
  // curve). A B-spline section after a 0.5 s dwell in PCS1, from X-450 down to Z-880 as in the test
  // above, on a 300 mm/s belt. Without the shares on the pieces the joints' jerk reached 104.1 %
  // of J, 18 audit violations (measured); with them 69.3 %, none. (On a 500 mm/s belt the
  // capped pieces run long enough for the belt to carry them out of the workspace: NC9052.)
  const double belts[] = {300.0};  // [mm/s]
  for (const double belt : belts) {
    const std::string program =
        "%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-400 Y0 Z-700 F60000\n"
        "N40 #SYNC IN [CONV_VEL=" +
        std::to_string(static_cast<int>(belt * 60.0)) +
        "]\nN50 G01 X-450 Y0 Z-700 F60000\nN55 G04 0.5\nN57 #SPLINE TYPE BSPLINE\n"
        "N58 #SPLINE ON\nN60 G01 X-420 Y-60 Z-820 F60000\nN61 X-330 Y-120 Z-880\n"
        "N62 X-260 Y-200 Z-880\nN63 X-200 Y-200 Z-880\nN64 #SPLINE OFF\n"
        "N70 G04 0.05\nN80 #SYNC OUT\nN90 M30\n";
    CAPTURE(program);
    const Tracked r = track_clean(program, belt);
    check_far_side(r, 10, 13, belt);
  }
}

namespace {

// The block of the test above at belt travel 0 (MCS), on the picker's transform.
struct ShareRig {
  machines::Machine m = picker();
  channel::ChannelConfig cfg = channel::channel_config(m, kT);
  std::optional<program::MachineTrafo> trafo = program::machine_trafo(m, cfg.path);
  planner::Move move;
  ShareRig() {
    move.axis_count = static_cast<std::uint8_t>(cfg.path.axes.size());
    move.start[0] = -450.0;
    move.start[1] = 0.0;
    move.start[2] = -700.0;
    move.end = move.start;
    move.end[0] = -200.0;
    move.end[1] = -200.0;
    move.end[2] = -880.0;
    move.feed = 1000.0;
    move.transformed = true;
  }
  std::variant<tracking::BeltShare, tracking::BeltOverload> share(
      const tracking::BeltCarry& carry, std::span<const planner::AxisLimits> joints) const {
    return tracking::belt_share(planner::Segment::from_move(move), move.feed, trafo->limits.inverse,
                                trafo->xyz, joints, carry);
  }
  std::variant<tracking::BeltShare, tracking::BeltOverload> share(
      const tracking::BeltCarry& carry) const {
    return share(carry, trafo->limits.joints);
  }
};

tracking::BeltCarry carry_in(double x_lo, double x_hi) {
  tracking::BeltCarry c;
  c.v_belt = 550.0;  // 1.1 x CONV_VEL 30000 mm/min
  c.workspace = {{{x_lo, -600.0, -900.0}, {x_hi, 600.0, 0.0}}};
  return c;
}

}  // namespace

TEST_CASE("the belt's share covers the travel from the latch forward to the workspace's face") {
  // docs/conveyor.md "Machining in PCS1": the belt only moves forward (travel b >= 0 since the
  // latch) and carries a point no further than the face in the conveying direction (NC9052
  // beyond): the shares are taken over that travel alone.
  const ShareRig rig;
  REQUIRE(rig.trafo);
  const auto full = rig.share(carry_in(-600.0, 600.0));
  const auto behind = rig.share(carry_in(-2000.0, 600.0));  // the box reaches far behind
  const auto near = rig.share(carry_in(-600.0, -199.0));    // the face just past the block
  REQUIRE(std::holds_alternative<tracking::BeltShare>(full));
  REQUIRE(std::holds_alternative<tracking::BeltShare>(behind));
  REQUIRE(std::holds_alternative<tracking::BeltShare>(near));
  const tracking::BeltShare& f = std::get<tracking::BeltShare>(full);
  const tracking::BeltShare& b = std::get<tracking::BeltShare>(behind);
  const tracking::BeltShare& n = std::get<tracking::BeltShare>(near);
  double grows = 0.0;  // the largest ratio of a joint's jerk share, full travel over near
  for (std::size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    MESSAGE("joint " << i << ": j share to the face at X-199 " << n.joints.j[i] << ", to X600 "
                     << f.joints.j[i]);
    CHECK(b.joints.a[i] == f.joints.a[i]);  // nothing behind the latch counts
    CHECK(b.joints.j[i] == f.joints.j[i]);
    CHECK(n.joints.j[i] <= f.joints.j[i]);
    grows = std::max(grows, f.joints.j[i] / n.joints.j[i]);
  }
  CHECK(b.feed == f.feed);
  CHECK(grows > 1.5);  // further travel, more curvature: the range matters
}

TEST_CASE("NC6211's overload: the belt's own jerk beyond a joint's J at a travel it reaches") {
  // A share that leaves a joint less than 1 % of its J with the path at rest (the belt's own
  // q_bbb w^3 and its cross term with the path's acceleration) cannot be met by any feed: the
  // adapter refuses the block (NC6211, program/program_kinematics.cpp). With the joints' own J the
  // same block has a share and a feed.
  const ShareRig rig;
  REQUIRE(rig.trafo);
  std::vector<planner::AxisLimits> joints = rig.trafo->limits.joints;
  const auto ok = rig.share(carry_in(-600.0, 600.0), joints);
  REQUIRE(std::holds_alternative<tracking::BeltShare>(ok));
  CHECK(std::get<tracking::BeltShare>(ok).feed > 0.0);
  for (planner::AxisLimits& l : joints)
    l.j_max = 2000.0;  // [deg/s^3]
  const auto over = rig.share(carry_in(-600.0, 600.0), joints);
  REQUIRE(std::holds_alternative<tracking::BeltOverload>(over));
  const tracking::BeltOverload& o = std::get<tracking::BeltOverload>(over);
  MESSAGE("joint " << o.joint << " " << std::string(1, o.quantity) << " " << o.needed << " of "
                   << o.limit << " at X" << o.tcp[0] << " moved " << o.shift);
  CHECK(o.quantity == 'j');
  CHECK(o.needed >= 0.99 * o.limit);
  CHECK(o.shift >= 0.0);
  CHECK(o.tcp[0] + o.shift <= 600.0 + 1e-6);  // inside the workspace: a travel the run reaches
}

// What was not reserved (docs/conveyor.md "Machining in PCS1").

namespace {

// The Moves the adapter hands out for `program` on the picker, by source line.
std::vector<planner::Move> moves_of(const std::string& program) {
  const machines::Machine m = picker();
  const core::SourceFile file("t.nc", program);
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  std::vector<planner::Move> out;
  ipo::Item item;
  while (src.next(item))
    if (const auto* mv = std::get_if<planner::Move>(&item)) out.push_back(*mv);
  if (const core::Diagnostic* e = src.error()) MESSAGE(e->id << ": " << e->message);
  REQUIRE_FALSE(src.error());
  return out;
}

const planner::Move& line_of(const std::vector<planner::Move>& moves, std::uint32_t line) {
  const auto it = std::find_if(moves.begin(), moves.end(),
                               [line](const planner::Move& mv) { return mv.line == line; });
  REQUIRE(it != moves.end());
  return *it;
}

// A G261 corner between two PCS1 blocks after a dwell, on a `belt` [mm/s] belt, ball radius
// `dev` [mm]: lines 10 (N60, the block before the ball) and 11 (N70).
// `mode`: the #CONTOUR MODE parameters.
std::string ball_program_mode(double belt, const std::string& mode) {
  return "%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-400 Y0 Z-700 F60000\n"
         "N40 #SYNC IN [CONV_VEL=" +
         std::to_string(static_cast<int>(belt * 60.0)) +
         "]\nN50 G01 X-450 Y0 Z-700 F60000\nN55 G04 0.3\n"
         "N57 #CONTOUR MODE [" +
         mode +
         "]\nN58 G261\nN60 G01 X-300 Y-150 Z-880 F60000\nN70 G01 X-150 Y50 Z-850\n"
         "N75 G260\nN80 G04 0.05\nN90 #SYNC OUT\nN100 M30\n";
}

std::string ball_program(double belt, double dev) {
  return ball_program_mode(belt, "DEV PATH_DEV=" + std::to_string(dev));
}

}  // namespace

TEST_CASE("a tolerance ball between two PCS1 blocks gets the belt's share on its own curve") {
  // The planner builds the ball from both neighbours (planner::make_blend) and runs it with the
  // limits of the block before it; the adapter holds that block back until the next motion and
  // gives it the ball's share where larger (belt_share sampled on the ball's curve) and the
  // ball's feed cap where lower. Before, the block kept the share of its own curve only: joint
  // Z's a and j shares 3571 deg/s^2 and 93113 deg/s^3 against the ball's 10663 and 385677 (5 mm
  // ball), its F 1000 mm/s against the ball's cap 110.6 mm/s (measured).
  const double belt = 500.0;  // [mm/s]
  const double devs[] = {5.0, 40.0};
  const ShareRig rig;
  REQUIRE(rig.trafo);
  tracking::BeltCarry carry;
  carry.v_belt = 1.1 * belt;
  carry.workspace = {{{-600.0, -600.0, -900.0}, {600.0, 600.0, 0.0}}};  // picker()'s
  for (const double dev : devs) {
    CAPTURE(dev);
    const std::vector<planner::Move> moves = moves_of(ball_program(belt, dev));
    const planner::Move& in = line_of(moves, 10);
    const planner::Move& out = line_of(moves, 11);
    const planner::Segment in_path = planner::Segment::from_move(in);
    const planner::Segment out_path = planner::Segment::from_move(out);
    const auto ball =
        planner::make_blend(in_path, out_path, dev, in_path.length() / 2, out_path.length() / 2);
    REQUIRE(ball);
    const auto ball_share =
        tracking::belt_share(ball->curve, std::min(in.feed, out.feed), rig.trafo->limits.inverse,
                             rig.trafo->xyz, rig.trafo->limits.joints, carry);
    REQUIRE(std::holds_alternative<tracking::BeltShare>(ball_share));
    const tracking::BeltShare& s = std::get<tracking::BeltShare>(ball_share);
    REQUIRE(in.belt_joints);
    for (std::size_t i = 0; i < 3; ++i) {
      CAPTURE(i);
      MESSAGE("joint " << i << ": a share " << in.belt_joints->a[i] << " (ball " << s.joints.a[i]
                       << "), j share " << in.belt_joints->j[i] << " (ball " << s.joints.j[i]
                       << ")");
      CHECK(in.belt_joints->a[i] >= s.joints.a[i] * (1.0 - 1e-9));
      CHECK(in.belt_joints->j[i] >= s.joints.j[i] * (1.0 - 1e-9));
    }
    MESSAGE("feed " << in.feed << " (ball's cap " << s.feed << ")");
    CHECK(in.feed <= s.feed * (1.0 + 1e-9));
  }
}

TEST_CASE(
    "under DIST the PCS1 block carries the share of the planner's PRE_DIST / POST_DIST curve") {
  // planner::corner_blend builds the same curve for the planner and for the adapter's share:
  // PRE_DIST 40 mm before the corner, POST_DIST 5 mm after it (isg-language.md §5.3).
  const double belt = 500.0;  // [mm/s]
  const ShareRig rig;
  REQUIRE(rig.trafo);
  tracking::BeltCarry carry;
  carry.v_belt = 1.1 * belt;
  carry.workspace = {{{-600.0, -600.0, -900.0}, {600.0, 600.0, 0.0}}};  // picker()'s
  const std::vector<planner::Move> moves =
      moves_of(ball_program_mode(belt, "DIST PRE_DIST=40 POST_DIST=5"));
  const planner::Move& in = line_of(moves, 10);
  const planner::Move& out = line_of(moves, 11);
  REQUIRE(in.contour == planner::Contour::distance);
  const planner::Segment in_path = planner::Segment::from_move(in);
  const planner::Segment out_path = planner::Segment::from_move(out);
  const planner::JointEnds ends = planner::joint_ends(in_path, out_path);
  const auto ball =
      planner::make_blend(in_path, out_path, ends, planner::CornerDistances{40.0, 5.0, false},
                          in_path.length() / 2, out_path.length() / 2);
  REQUIRE(ball);
  CHECK(ball->cut_in == doctest::Approx(40.0));
  const auto ball_share =
      tracking::belt_share(ball->curve, std::min(in.feed, out.feed), rig.trafo->limits.inverse,
                           rig.trafo->xyz, rig.trafo->limits.joints, carry);
  REQUIRE(std::holds_alternative<tracking::BeltShare>(ball_share));
  const tracking::BeltShare& s = std::get<tracking::BeltShare>(ball_share);
  REQUIRE(in.belt_joints);
  for (std::size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    CHECK(in.belt_joints->a[i] >= s.joints.a[i] * (1.0 - 1e-9));
    CHECK(in.belt_joints->j[i] >= s.joints.j[i] * (1.0 - 1e-9));
  }
  MESSAGE("feed " << in.feed << " (the DIST curve's cap " << s.feed << ")");
  CHECK(in.feed <= s.feed * (1.0 + 1e-9));
}

TEST_CASE("a ball across a command that emits nothing and does not stop the path keeps its share") {
  // An M function riding on the next block, a message and #FLUSH CONTINUE between the two PCS1
  // blocks emit no item and do not stop the path: the planner blends the two blocks as without
  // them (the contour cuts the corner by up to PATH_DEV), so the block before the ball must carry
  // the ball's share as without them (a plain #FLUSH stops the path: no ball). Before, any command
  // released the held block as it was
  // (`ProgramSource::ball_release(nullptr)`): its own curve's shares only (measured: joint Z's
  // j share 93113 deg/s^3 against the ball's 385677, F 1000 mm/s against the ball's 110.6).
  const double belt = 500.0;  // [mm/s]
  const std::string plain = ball_program(belt, 5.0);
  const std::vector<planner::Move> base = moves_of(plain);
  const planner::Move& want = line_of(base, 10);
  REQUIRE(want.belt_joints);
  const std::string mark = "N70 G01";
  REQUIRE(plain.find(mark) != std::string::npos);
  for (const char* between : {"N65 M08\n", "N65 #MSG [\"over the ball\"]\n",
                              "N65 #FLUSH CONTINUE\n", "N65 M08\nN66 #FLUSH CONTINUE\n"}) {
    CAPTURE(between);
    std::string program = plain;
    program.insert(program.find(mark), between);
    const std::vector<planner::Move> moves = moves_of(program);
    const planner::Move& in = line_of(moves, 10);
    MESSAGE("feed " << in.feed << " (without the command " << want.feed << ")");
    CHECK(in.feed == doctest::Approx(want.feed).epsilon(1e-12));
    REQUIRE(in.belt_joints);
    for (std::size_t i = 0; i < 3; ++i) {
      CAPTURE(i);
      CHECK(in.belt_joints->a[i] == doctest::Approx(want.belt_joints->a[i]).epsilon(1e-12));
      CHECK(in.belt_joints->j[i] == doctest::Approx(want.belt_joints->j[i]).epsilon(1e-12));
    }
  }
  // The planner does blend across them: a run with a 40 mm ball on a 300 mm/s belt cuts the
  // corner as without the commands, the joints' audit clean.
  const Tracked r_plain = track_clean(ball_program(300.0, 40.0), 300.0);
  std::string program = ball_program(300.0, 40.0);
  program.insert(program.find(mark), "N65 M08\nN66 #FLUSH CONTINUE\n");
  const Tracked r = track_clean(program, 300.0);
  MESSAGE("contour deviation " << r.verdict.contour_max << " mm (without the commands "
                               << r_plain.verdict.contour_max << " mm)");
  CHECK(r.verdict.contour_max > 1.0);
  CHECK(r.verdict.contour_max == doctest::Approx(r_plain.verdict.contour_max).epsilon(1e-9));
  CHECK(r.verdict.ok());
  CHECK_FALSE(r.warning);
}

TEST_CASE("a tolerance ball between two PCS1 blocks near the far side keeps the joints' a and j") {
  // A guard, not a failing-first test: no ball was found that the audit flags without its own
  // share (docs/conveyor.md: 906 scratch runs); this one reached 68.8 % of J before, 69.3 % now.
  const double belt = 300.0;  // [mm/s]
  const Tracked r = track_clean(ball_program(belt, 40.0), belt);
  check_far_side(r, 10, 11, belt);
}

TEST_CASE("G00 in PCS1 the belt carries towards the far side keeps the joints' a and j") {
  // docs/conveyor.md "Machining in PCS1": a G00 runs each joint at its rapid rule (000 l.360);
  // the belt's share is taken of those limits as of a G01's (tracking::belt_share), the velocity
  // share caps the rapid (planner/joint_limits.cpp). Before (the G00 unreserved) the third case
  // reached 108.8 % of J, 55 audit violations (measured); with the shares 16.0 %, none.
  struct Case {
    double belt;         // [mm/s]
    const char* start;   // the catch-up's target (PCS1)
    const char* dwell;   // [s]
    const char* target;  // the G00's
    double used;         // of J, at least (the short stroke is capped hard: 16 %)
  };
  const Case cases[] = {
      {300.0, "X-450 Y0 Z-700", "0.5", "X-200 Y-200 Z-880", 0.5},
      {500.0, "X-450 Y0 Z-700", "0.5", "X-200 Y-200 Z-880", 0.5},
      {600.0, "X-408.9 Y-5.7 Z-709.1", "0.5", "X-363 Y21.5 Z-711.2", 0.1},
  };
  for (const Case& c : cases) {
    const std::string program =
        "%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-400 Y0 Z-700 F60000\n"
        "N40 #SYNC IN [CONV_VEL=" +
        std::to_string(static_cast<int>(c.belt * 60.0)) + "]\nN50 G01 " + c.start +
        " F60000\nN55 G04 " + c.dwell + "\nN60 G00 " + c.target +
        "\nN70 G04 0.05\nN80 #SYNC OUT\nN90 M30\n";
    CAPTURE(program);
    const Tracked r = track_clean(program, c.belt);
    check_far_side(r, 8, 8, c.belt, c.used);
  }
}

TEST_CASE("G93 in PCS1: the belt's shares cap the block's velocity, the block takes longer") {
  // docs/conveyor.md "Machining in PCS1": under G93 the block time sets the path velocity
  // (length / time, planner::path_limits); the adapter reserves the belt's shares at that
  // velocity as at a G01's F, and where the feed cap is lower the block time grows to length /
  // cap. The far-side block of the tests above in 0.3 s (1223 mm/s programmed). Before (G93
  // unreserved) the joints' jerk reached 133.6 % of J, 68 audit violations (measured).
  const double belt = 300.0;  // [mm/s]
  const std::string program =
      "%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-400 Y0 Z-700 F60000\n"
      "N40 #SYNC IN [CONV_VEL=18000]\nN50 G01 X-450 Y0 Z-700 F60000\nN55 G04 0.5\n"
      "N60 G93 G01 X-200 Y-200 Z-880 F0.3\nN65 G94\nN70 G04 0.05\nN80 #SYNC OUT\nN90 M30\n";
  const std::vector<planner::Move> moves = moves_of(program);
  const planner::Move& g93 = line_of(moves, 8);
  REQUIRE(g93.block_time);
  MESSAGE("block time " << *g93.block_time << " s (programmed 0.3 s)");
  CHECK(*g93.block_time >= 0.3);  // here the joints' own limits slow it more than the cap
  CHECK(g93.belt_joints);
  const Tracked r = track_clean(program, belt);
  check_far_side(r, 8, 8, belt);
}

TEST_CASE("an override above 100 % keeps a PCS1 block under #TRAFO ON at its 100 % plan") {
  // REDUCED_ABOVE_100 raises the path above its F up to the joints' G00 rule
  // (ipo/override_trafo.cpp); the belt's shares of a PCS1 block were taken at its capped F, so
  // there the path keeps its 100 % plan (decision, docs/conveyor.md "Machining in PCS1"); off
  // the belt the override still raises it. The far-side block on a 300 mm/s belt at 150 %:
  // before, the block ran in 303 instead of 412 cycles, joint jerk 67.3 % of J and no audit
  // violation (measured: the raised limits keep the planned a, d, j).
  const double belt = 300.0;  // [mm/s]
  const std::string program =
      "%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-400 Y0 Z-700 F60000\n"
      "N40 #SYNC IN [CONV_VEL=18000]\nN50 G01 X-450 Y0 Z-700 F60000\nN55 G04 0.5\n"
      "N60 G01 X-200 Y-200 Z-880 F60000\nN70 G04 0.05\nN80 #SYNC OUT\n"
      "N85 G01 X0 Y0 Z-700 F60000\nN86 G01 X100 Y0 Z-700 F6000\nN90 M30\n";
  const auto cycles_of = [](const Tracked& r, std::uint32_t line) {
    return std::count(r.line.begin(), r.line.end(), line);
  };
  const Tracked base = track_clean(program, belt, picker(), "100");
  const Tracked raised = track_clean(program, belt, picker(), "150");
  MESSAGE("N86 (off the belt): " << cycles_of(base, 12) << " cycles at 100 %, "
                                 << cycles_of(raised, 12) << " at 150 %; N60 (PCS1): "
                                 << cycles_of(base, 8) << ", " << cycles_of(raised, 8));
  CHECK(cycles_of(raised, 12) < cycles_of(base, 12));  // off the belt 150 % is faster
  CHECK(cycles_of(raised, 8) == cycles_of(base, 8));   // in PCS1 the 100 % plan
  check_far_side(raised, 8, 8, belt);
}