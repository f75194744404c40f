// Joint limits under a kinematic transform (#TRAFO ON, delta #KIN ID[37]): a delta-robot move
// planned in Cartesian space whose joints, computed with machines' delta kinematics from the
// planned path sampled finely in time, stay inside their v, a, j; and the same moves planned
// with the axis limits alone break them (so the check can fail).

#include "planner/joint_limits.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "machines/delta_kinematics.hpp"
#include "planner/lookahead.hpp"

namespace {

using namespace ncsim::planner;
using ncsim::machines::DeltaGeometry;
using ncsim::machines::DeltaKinematics;

DeltaKinematics delta() {
  // TF5264 pick & place listing (seed 004 §4.9.1), docs/machines.md "Kinematic 37".
  DeltaGeometry g;
  g.r_effector = 48.0;
  g.r_base = 200.0;
  g.l_lower = 1050.0;
  g.l_upper = 465.544;
  return DeltaKinematics(g);
}

JointMap joint_map(const DeltaKinematics& kin) {
  return [&kin](const AxisVec& x, AxisVec& q) {
    const auto r = kin.inverse(Eigen::Vector3d(x[0], x[1], x[2]));
    if (!r.ok()) return false;
    q = AxisVec{};
    for (std::size_t i = 0; i < 3; ++i)
      q[i] = r.value[static_cast<Eigen::Index>(i)];
    return true;
  };
}

AxisLimits limits(double v, double a, double j) {
  AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = v;
  ax.a_max = ax.d_max = a;
  ax.j_max = j;
  return ax;
}

/// The same limits for each of the three axes (or joints).
std::array<AxisLimits, 3> each_axis(double v, double a, double j) {
  const AxisLimits ax = limits(v, a, j);
  return {ax, ax, ax};
}

/// The effector's position with the joints at (20, 20, 20): the delta's home of these tests.
AxisVec delta_home(const DeltaKinematics& kin) {
  const auto r = kin.forward(Eigen::Vector3d(20, 20, 20));
  REQUIRE(r.ok());
  AxisVec home{};
  for (std::size_t i = 0; i < 3; ++i)
    home[i] = r.value[static_cast<Eigen::Index>(i)];
  return home;
}

struct Peak {
  std::array<double, 3> v{}, a{}, j{};  // largest |joint v, a, j| over the move [deg/s^k]
};

/// Plans `seg` from stop to stop with `pl` and measures the joints every dt.
Peak joint_peaks(const Segment& seg, const PathLimits& pl, const DeltaKinematics& kin) {
  PlannedSegment planned;
  planned.segment.path = Chain(seg);
  planned.segment.limits = pl;
  planned.a_max = pl.a_max;
  planned.d_max = pl.d_max;
  planned.j_max = pl.j_max;
  const SegmentProfile profile_move = profile(planned);
  constexpr double dt = 2e-4;
  const auto steps = static_cast<int>(std::ceil(profile_move.time() / dt)) + 8;
  std::vector<Eigen::Vector3d> q;
  for (int k = -4; k <= steps; ++k) {
    const PathState st = profile_at(profile_move, k * dt);
    const AxisVec x = seg.point(st.s);
    const auto r = kin.inverse(Eigen::Vector3d(x[0], x[1], x[2]));
    REQUIRE(r.ok());
    q.push_back(r.value);
  }
  Peak p;
  for (std::size_t k = 2; k + 2 < q.size(); ++k)
    for (Eigen::Index i = 0; i < 3; ++i) {
      const auto u = static_cast<std::size_t>(i);
      p.v[u] = std::max(p.v[u], std::abs(q[k + 1][i] - q[k - 1][i]) / (2 * dt));
      p.a[u] = std::max(p.a[u], std::abs(q[k + 1][i] - 2 * q[k][i] + q[k - 1][i]) / (dt * dt));
      p.j[u] =
          std::max(p.j[u], std::abs(q[k + 2][i] - 3 * q[k + 1][i] + 3 * q[k][i] - q[k - 1][i]) /
                               (dt * dt * dt));
    }
  return p;
}

std::vector<Move> delta_moves(const AxisVec& home) {
  std::vector<Move> moves;
  auto at = [&](double dx, double dy, double dz) {
    AxisVec p = home;
    p[0] += dx;
    p[1] += dy;
    p[2] += dz;
    return p;
  };
  Move m;
  m.feed = 2000.0;
  m.slope = SlopeType::trapez;
  m.start = at(-250, -100, 0);
  m.end = at(250, 150, -80);  // a long diagonal pick-and-place stroke
  moves.push_back(m);
  m.start = at(0, 0, 100);
  m.end = at(0, 0, -150);  // a vertical stroke
  moves.push_back(m);
  m.start = at(150, 0, 0);  // a full circle of R = 150 (G03)
  m.end = m.start;
  m.arc = Arc{0, 1, home[0], home[1], false, true};
  moves.push_back(m);
  return moves;
}

}  // namespace

TEST_CASE("a delta-robot move planned in Cartesian space keeps every joint inside its limits") {
  const DeltaKinematics kin = delta();
  const AxisVec home = delta_home(kin);
  // Cartesian axes fast, joints slow: the joints must be what limits the path.
  const std::array<AxisLimits, 3> axes = each_axis(5000, 5e4, 5e6);
  const std::array<AxisLimits, 3> joints = each_axis(40, 400, 8000);
  const JointMap ik = joint_map(kin);
  double worst = 0.0;
  for (const Move& m : delta_moves(home)) {
    const Segment seg = Segment::from_move(m);
    const auto pl = path_limits(seg, m, axes, ik, joints);
    REQUIRE(pl.has_value());
    CHECK(pl->limit == VelocityLimit::joint);
    const Peak p = joint_peaks(seg, *pl, kin);
    for (std::size_t i = 0; i < 3; ++i) {
      CHECK(p.v[i] <= joints[i].v_max * (1 + 1e-6));
      CHECK(p.a[i] <= joints[i].a_max * (1 + 1e-3));  // finite differences, dt = 0.2 ms
      CHECK(p.j[i] <= joints[i].j_max * (1 + 1e-3));
      worst = std::max(
          {worst, p.v[i] / joints[i].v_max, p.a[i] / joints[i].a_max, p.j[i] / joints[i].j_max});
    }
    // The axis limits alone would break the joints' (the check above can fail).
    const PathLimits axis_only = path_limits(seg, m, axes);
    const Peak fast = joint_peaks(seg, axis_only, kin);
    CHECK(std::max({fast.v[0], fast.v[1], fast.v[2]}) > 2 * joints[0].v_max);
  }
  // The bound is used, not wasted: some joint comes near one of its limits.
  CHECK(worst > 0.5);
  MESSAGE("largest joint v/a/j over its limit: " << worst);
}

TEST_CASE("a segment that leaves the delta's workspace cannot be planned") {
  const DeltaKinematics kin = delta();
  const std::array<AxisLimits, 3> lim = each_axis(500, 5e3, 5e5);
  Move m;
  m.feed = 100.0;
  m.start[2] = -900.0;
  m.end[2] = 2000.0;  // far above the base
  const Segment seg = Segment::from_move(m);
  CHECK_FALSE(path_limits(seg, m, lim, joint_map(kin), lim).has_value());
}

TEST_CASE("G00 under a transform: each joint at MIN(rapid, reference, max) with its G00 slope") {
  // issue 12 (trafo-conveyor): 000 l.360 per joint; P-AXIS-00004 / 00200 as a_rapid / j_rapid.
  const DeltaKinematics kin = delta();
  const AxisVec home = delta_home(kin);
  const std::array<AxisLimits, 3> axes = each_axis(5000, 5e4, 5e6);
  std::array<AxisLimits, 3> joints = each_axis(40, 400, 8000);
  Move m = delta_moves(home)[0];  // the long diagonal stroke
  m.rapid = true;
  const Segment seg = Segment::from_move(m);
  const JointMap ik = joint_map(kin);
  const auto same = path_limits(seg, m, axes, ik, joints);
  REQUIRE(same.has_value());
  // A slower rapid velocity, G00 acceleration and G00 jerk of the joints: the G00 block obeys
  // them, the same block as G01 at a high F does not.
  for (AxisLimits& j : joints) {
    j.v_rapid = 20.0;
    j.a_rapid = 100.0;
    j.j_rapid = 1000.0;
  }
  const auto slow = path_limits(seg, m, axes, ik, joints);
  REQUIRE(slow.has_value());
  CHECK(slow->v_max == doctest::Approx(same->v_max / 2.0).epsilon(1e-9));
  CHECK(slow->a_max < same->a_max / 3.0);
  CHECK(slow->j_max < same->j_max / 7.0);
  const Peak p = joint_peaks(seg, *slow, kin);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(p.v[i] <= 20.0 * (1 + 1e-6));
    CHECK(p.a[i] <= 100.0 * (1 + 1e-3));
    CHECK(p.j[i] <= 1000.0 * (1 + 1e-3));
  }
  Move g1 = m;
  g1.rapid = false;
  g1.feed = 1e5;
  const auto feed = path_limits(seg, g1, axes, ik, joints);
  REQUIRE(feed.has_value());
  CHECK(feed->v_max == doctest::Approx(same->v_max).epsilon(1e-9));
}

TEST_CASE("G00 in PCS1: the belt's shares come off the G00 slope and its feed caps the rapid") {
  // trafo-pcs1 (issue 14, docs/conveyor.md "Machining in PCS1"): the adapter reserves the belt's
  // share of each joint on a G00 in PCS1 too (tracking::belt_share of the joints' rapid limits);
  // the planner gets the joints lowered by it (Preparer::limits, belt_joint_limits), and where
  // a G00 slope (a_rapid, j_rapid) replaces the feed values the share comes off it as well;
  // Move::feed carries the velocity share's cap.
  const DeltaKinematics kin = delta();
  const AxisVec home = delta_home(kin);
  const std::array<AxisLimits, 3> axes = each_axis(5000, 5e4, 5e6);
  std::array<AxisLimits, 3> joints = each_axis(40, 400, 8000);
  for (AxisLimits& j : joints) {
    j.a_rapid = 300.0;
    j.j_rapid = 6000.0;
  }
  Move m = delta_moves(home)[0];
  m.rapid = true;
  m.slope = SlopeType::trapez;
  const Segment seg = Segment::from_move(m);
  const JointMap ik = joint_map(kin);
  const auto own = path_limits(seg, m, axes, ik, joints);
  REQUIRE(own.has_value());
  // The belt takes 150 of each joint's acceleration and 3000 of its jerk; the Preparer hands
  // the joints over lowered by it (the feed values), with the share on the Move.
  auto share = std::make_shared<JointShare>();
  for (std::size_t i = 0; i < 3; ++i) {
    share->a[i] = 150.0;
    share->j[i] = 3000.0;
  }
  m.belt_joints = share;
  m.feed = 0.5 * own->v_max;  // the velocity share's cap
  std::array<AxisLimits, 3> lowered{};
  for (std::size_t i = 0; i < 3; ++i)
    lowered[i] = belt_joint_limits(joints[i], share->a[i], share->j[i]);
  const auto belt = path_limits(seg, m, axes, ik, lowered);
  REQUIRE(belt.has_value());
  // The G00 obeys what the shares leave of the G00 slope (300 - 150, 6000 - 3000) and the cap.
  CHECK(belt->v_max <= m.feed * (1 + 1e-12));
  const Peak p = joint_peaks(seg, *belt, kin);
  for (std::size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    CHECK(p.a[i] <= 150.0 * (1 + 1e-3));
    CHECK(p.j[i] <= 3000.0 * (1 + 1e-3));
  }
  const Peak q = joint_peaks(seg, *own, kin);  // without the belt the G00 slope is used
  CHECK(std::max({q.a[0], q.a[1], q.a[2]}) > 200.0);
  // Off the conveyor (no share) the feed does not cap a G00.
  Move off = m;
  off.belt_joints.reset();
  const auto plain = path_limits(seg, off, axes, ik, joints);
  REQUIRE(plain.has_value());
  CHECK(plain->v_max == doctest::Approx(own->v_max).epsilon(1e-9));
}

TEST_CASE(
    "joint_rapid_limits: a joint's G00 runs at MIN(rapid, reference, maximum) on its G00 slope") {
  AxisLimits j;
  j.v_max = 720.0;
  j.v_reference = 600.0;
  j.v_rapid = 650.0;
  j.a_max = j.d_max = 20000.0;
  j.j_max = 500000.0;
  j.a_rapid = 15000.0;
  j.j_rapid = 300000.0;
  const AxisLimits r = joint_rapid_limits(j);
  CHECK(r.v_max == 600.0);  // the reference velocity is the least of the three (000 l.360)
  CHECK(r.a_max == 15000.0);
  CHECK(r.d_max == 15000.0);
  CHECK(r.j_max == 300000.0);
  j.v_rapid = 500.0;
  CHECK(joint_rapid_limits(j).v_max == 500.0);
}
