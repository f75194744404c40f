// The per-cycle joint stage and the joint audit under a delta transform (#KIN ID[37]): the
// issue's hand-checked "delta-robot move whose joints stay inside their limits" through
// PathInterpolator (planned in Cartesian space with the joint limits) + JointStage + Audit;
// the same moves planned with the Cartesian limits alone break the joints and the audit says
// so (the check can fail); the stage's v, a, j agree with the joints' own finite differences.

#include "ipo/joint_stage.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "ipo/interpolator.hpp"
#include "machines/delta_kinematics.hpp"

namespace {

using namespace ncsim;
using ipo::AxisVec;

machines::DeltaKinematics delta() {
  // TF5264 pick & place listing (seed 004 §4.9.1), docs/machines.md "Kinematic 37".
  machines::DeltaGeometry g;
  g.r_effector = 48.0;
  g.r_base = 200.0;
  g.l_lower = 1050.0;
  g.l_upper = 465.544;
  return machines::DeltaKinematics(g);
}

planner::JointMap joint_map(const machines::DeltaKinematics& kin) {
  return [&kin](const AxisVec& x, AxisVec& q) {
    const auto r = kin.inverse(Eigen::Vector3d(x[0], x[1], x[2]));
    if (!r.ok()) return false;
    q = AxisVec{};
    for (std::size_t i = 0; i < 3; ++i)
      q[i] = r.value[static_cast<Eigen::Index>(i)];
    return true;
  };
}

planner::AxisLimits limits(double v, double a, double j) {
  planner::AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = v;
  ax.a_max = ax.d_max = a;
  ax.j_max = j;
  return ax;
}

struct Result {
  audit::Verdict verdict;
  ipo::Status status = ipo::Status::running;
  std::string message;
  bool stage_ok = true;
  double stage_vs_diff = 0.0;  ///< largest |stage v - central difference of q| [deg/s]
  double dv_max = 0.0;         ///< largest |joint v(k) - v(k-1)| between cycles [deg/s]
  AxisVec final_x{};
};

/// Audit + joint stage as the channel would use them, in one sink.
struct JointSink final : ipo::Sink {
  audit::Audit audit;
  const ipo::JointStage& stage;
  Result* out;
  std::vector<ipo::JointSetpoint> last;  // the last three setpoints
  JointSink(const ipo::Config& c, const ipo::JointStage& s, Result* r)
      : audit(c.axes, c.channel.t_cycle, c.start), stage(s), out(r) {}
  void on_joint(const ipo::Joint& j) override { audit.on_joint(j); }
  void on_cycle(const ipo::Cycle& c) override {
    audit.on_cycle(c);
    ipo::JointSetpoint s;
    if (!stage.step(c.x, c.v, c.a, c.j, s)) {
      out->stage_ok = false;
      return;
    }
    audit.on_joints(c, s);
    if (!last.empty())
      for (std::size_t i = 0; i < 3; ++i)
        out->dv_max = std::max(out->dv_max, std::abs(s.v[i] - last.back().v[i]));
    last.push_back(s);
    if (last.size() > 3) last.erase(last.begin());
    if (last.size() == 3 && c.activity == ipo::Activity::motion) {
      const double t = 0.001;
      for (std::size_t i = 0; i < 3; ++i)
        out->stage_vs_diff = std::max(
            out->stage_vs_diff, std::abs(last[1].v[i] - (last[2].q[i] - last[0].q[i]) / (2 * t)));
    }
    out->final_x = c.x;
  }
};

Result run(const std::vector<planner::Move>& moves, const AxisVec& start, bool with_joints,
           const std::array<planner::AxisLimits, 3>& joints, const machines::DeltaKinematics& kin) {
  ipo::Config cfg;
  cfg.axes.assign(3, limits(5000, 5e4, 5e6));  // Cartesian X, Y, Z: fast; the joints limit
  cfg.channel.t_cycle = 0.001;
  cfg.start = start;
  if (with_joints)
    cfg.joints = planner::JointLimits{joint_map(kin), {joints.begin(), joints.end()}, {}};
  std::size_t next = 0;
  ipo::CallbackSource src([&](ipo::Item& item) {
    if (next >= moves.size()) return false;
    item = moves[next++];
    return true;
  });
  const ipo::JointStage stage(joint_map(kin), 3);
  Result r;
  JointSink sink(cfg, stage, &r);
  AxisVec q0{};
  REQUIRE(joint_map(kin)(start, q0));
  sink.audit.set_joint_limits(joints, q0);
  ipo::PathInterpolator ipo(cfg, src, &sink);
  while ((r.status = ipo.step()) == ipo::Status::running) {
  }
  r.message = ipo.message();
  r.verdict = sink.audit.verdict();
  return r;
}

std::vector<planner::Move> strokes(const AxisVec& home) {
  const auto at = [&](double dx, double dy, double dz) {
    AxisVec p = home;
    p[0] += dx;
    p[1] += dy;
    p[2] += dz;
    return p;
  };
  std::vector<planner::Move> out;
  planner::Move m;
  m.axis_count = 3;
  m.feed = 2000.0;
  m.slope = planner::SlopeType::trapez;
  m.transition = planner::Transition::stop_at_end;
  m.transformed = true;  // #TRAFO ON: X, Y, Z are the TCP
  m.line = 10;
  m.start = home;
  m.end = at(250, 150, -80);  // a long diagonal pick-and-place stroke
  out.push_back(m);
  m.line = 20;
  m.start = m.end;
  m.end = at(150, 0, 0);  // back up, towards the circle's start
  out.push_back(m);
  m.line = 30;
  m.start = m.end;
  m.end = m.start;  // a full circle of R = 150 about home (G03)
  m.arc = planner::Arc{0, 1, home[0], home[1], false, true};
  out.push_back(m);
  return out;
}

}  // namespace

TEST_CASE("a delta-robot move keeps every joint inside its limits: planner, joint stage, audit") {
  const machines::DeltaKinematics kin = delta();
  const auto home_r = kin.forward(Eigen::Vector3d(20, 20, 20));
  REQUIRE(home_r.ok());
  AxisVec home{};
  for (std::size_t i = 0; i < 3; ++i)
    home[i] = home_r.value[static_cast<Eigen::Index>(i)];
  const std::array<planner::AxisLimits, 3> joints = {limits(40, 400, 8000), limits(40, 400, 8000),
                                                     limits(40, 400, 8000)};
  const std::vector<planner::Move> moves = strokes(home);

  const Result ok = run(moves, home, true, joints, kin);
  CHECK(ok.status == ipo::Status::finished);
  CHECK(ok.message.empty());
  CHECK(ok.stage_ok);
  CHECK(ok.verdict.ok());
  REQUIRE(ok.verdict.joints.size() == 3);
  double worst = 0.0;
  for (const audit::AxisAudit& j : ok.verdict.joints) {
    CHECK(j.v_closed <= 40.0 * (1 + 1e-9));
    CHECK(j.a_closed <= 400.0 * (1 + 1e-9));
    CHECK(j.j_closed <= 8000.0 * (1 + 1e-9));
    worst = std::max({worst, j.v_closed / 40.0, j.a_closed / 400.0, j.j_closed / 8000.0});
  }
  CHECK(worst > 0.5);  // the joints are what limits the path: the bound is used
  MESSAGE("largest joint v/a/j over its limit: " << worst);
  // The stage's velocity is the joints' own: central differences of the setpoints agree.
  CHECK(ok.stage_vs_diff < 0.05);
  for (std::size_t i = 0; i < 3; ++i)
    CHECK(ok.final_x[i] == doctest::Approx(moves.back().end[i]).epsilon(1e-9));

  // The Cartesian limits alone break the joints, and the audit reports them as joints.
  const Result fast = run(moves, home, false, joints, kin);
  CHECK(fast.status == ipo::Status::finished);
  CHECK_FALSE(fast.verdict.ok());
  REQUIRE_FALSE(fast.verdict.violations.empty());
  CHECK(fast.verdict.violations.front().joint);
}

TEST_CASE("a delta corner passed without a stop: each joint's velocity step keeps VELOJUMP") {
  const machines::DeltaKinematics kin = delta();
  const auto home_r = kin.forward(Eigen::Vector3d(20, 20, 20));
  REQUIRE(home_r.ok());
  AxisVec home{};
  for (std::size_t i = 0; i < 3; ++i)
    home[i] = home_r.value[static_cast<Eigen::Index>(i)];
  std::vector<planner::Move> moves = strokes(home);
  moves.pop_back();  // the two strokes, joined by a corner (G08: no stop between them)
  moves[0].transition = planner::Transition::accelerate_at_start;
  const std::array<planner::AxisLimits, 3> joints = {limits(40, 400, 8000), limits(40, 400, 8000),
                                                     limits(40, 400, 8000)};
  const Result r = run(moves, home, true, joints, kin);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.verdict.ok());
  // Under #TRAFO the joints' own steps are checked by formula instead of the path's Cartesian
  // ones (docs/ipo.md "Kinematics in run and time"): every listed step is a joint's, within
  // its bound, and the corner's VELOJUMP step of the joints is among them.
  REQUIRE(r.verdict.step_count > 0);
  for (const audit::Step& s : r.verdict.steps) {
    CHECK(s.joint);
    CHECK(s.value <= s.bound * (1 + 1e-9));
  }
  const audit::StepKind& jump = r.verdict.step_kinds[audit::step_kind(audit::Quantity::velojump)];
  REQUIRE(jump.count > 0);
  CHECK(jump.closest.bound == doctest::Approx(400.0 * 0.001));
  CHECK(jump.closest.value > 0.5 * jump.closest.bound);  // the step is used
  // Between two cycles a joint's velocity changes by at most A T (its acceleration) plus the
  // VELOJUMP step C0 A T (C0 = 1): 0.8 deg/s.
  CHECK(r.dv_max <= 2.0 * 400.0 * 0.001 * (1 + 1e-3));
  CHECK(r.dv_max > 400.0 * 0.001);  // the step is used, not replaced by a stop
}

TEST_CASE("a move out of the delta's workspace is a positioned planning error, not a crash") {
  const machines::DeltaKinematics kin = delta();
  const auto home_r = kin.forward(Eigen::Vector3d(20, 20, 20));
  REQUIRE(home_r.ok());
  AxisVec home{};
  for (std::size_t i = 0; i < 3; ++i)
    home[i] = home_r.value[static_cast<Eigen::Index>(i)];
  planner::Move m;
  m.axis_count = 3;
  m.feed = 100.0;
  m.transformed = true;
  m.line = 70;
  m.start = home;
  m.end = home;
  m.end[2] = 2000.0;  // far above the base
  const std::array<planner::AxisLimits, 3> joints = {limits(40, 400, 8000), limits(40, 400, 8000),
                                                     limits(40, 400, 8000)};
  const Result r = run({m}, home, true, joints, kin);
  CHECK(r.status == ipo::Status::error);
  CHECK(r.message.find("line 70") == 0);
  CHECK(r.message.find("[NC3201]") != std::string::npos);
}

TEST_CASE("the joint stage: positions are the inverse transform; v, a, j by the chain rule") {
  // A linear "transform" q = 2 x + 1 (per axis): q' = 2 v, q'' = 2 a, q''' = 2 j.
  const ipo::JointStage stage(
      [](const AxisVec& x, AxisVec& q) {
        for (std::size_t i = 0; i < 3; ++i)
          q[i] = 2 * x[i] + 1;
        return true;
      },
      3);
  AxisVec x{}, v{}, a{}, j{};
  x = {1, 2, 3};
  v = {10, -20, 0};
  a = {100, 0, -300};
  j = {1000, 5000, 0};
  ipo::JointSetpoint s;
  REQUIRE(stage.step(x, v, a, j, s));
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(s.q[i] == 2 * x[i] + 1);
    // Central differences of a cubic: v is off by the truncation j h^2 / 6 (3e-6 here).
    CHECK(s.v[i] == doctest::Approx(2 * v[i]).epsilon(1e-6).scale(1.0));
    CHECK(s.a[i] == doctest::Approx(2 * a[i]).epsilon(1e-6).scale(1.0));
    CHECK(s.j[i] == doctest::Approx(2 * j[i]).epsilon(1e-3).scale(10.0));
  }
  // A failing transform: false, the point kept, the setpoint unchanged.
  const ipo::JointStage failing([](const AxisVec&, AxisVec&) { return false; }, 3);
  ipo::JointSetpoint before = s;
  CHECK_FALSE(failing.step(x, v, a, j, s));
  CHECK(failing.failed_point()[0] == x[0]);
  CHECK(s.q[0] == before.q[0]);
  CHECK_THROWS_AS(ipo::JointStage(planner::JointMap{}, 3), std::invalid_argument);
}

TEST_CASE("the joint limits apply to transformed Moves only; a #TRAFO switch needs a stop") {
  const machines::DeltaKinematics kin = delta();
  const auto home_r = kin.forward(Eigen::Vector3d(20, 20, 20));
  REQUIRE(home_r.ok());
  AxisVec home{};
  for (std::size_t i = 0; i < 3; ++i)
    home[i] = home_r.value[static_cast<Eigen::Index>(i)];
  const std::vector<planner::AxisLimits> axes(3, limits(5000, 5e4, 5e6));
  planner::Preparer prep(axes, planner::ChannelLimits{});
  prep.set_joints(planner::JointLimits{
      joint_map(kin), {limits(40, 400, 8000), limits(40, 400, 8000), limits(40, 400, 8000)}, {}});
  const std::vector<planner::Move> moves = strokes(home);  // transformed
  planner::Move plain = moves[0];
  plain.transformed = false;  // the same numbers as axis values: the axes' limits alone
  std::vector<planner::PreparedSegment> out;
  prep.push(plain, out);
  prep.finish(out);
  REQUIRE(out.size() == 1);
  const double v_plain = out[0].limits.v_max;
  out.clear();
  prep.push(moves[0], out);
  prep.finish(out);
  REQUIRE(out.size() == 1);
  CHECK(out[0].limits.v_max < 0.5 * v_plain);  // the joints limit the TCP
  CHECK(out[0].limits.limit == planner::VelocityLimit::joint);
  out.clear();
  prep.push(plain, out);
  CHECK_THROWS_AS(prep.push(moves[1], out), std::invalid_argument);  // no stop between
  CHECK_THROWS_AS(prep.set_joints(planner::JointLimits{
                      joint_map(kin), {limits(40, 400, 8000)}, {limits(1, 1, 1)}}),
                  std::invalid_argument);  // one Cartesian limit for three axes
}
