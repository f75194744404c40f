// channel/kinematic_stage: the channel's mapping under #TRAFO ON (docs/ipo.md
// "Kinematics in run and time").
//
// The path interpolator gives the TCP (X, Y, Z Cartesian, other axes as they are) with its
// closed-form v, a, j; the joint stage (ipo/joint_stage.hpp) turns them into the setpoints of
// the machine axes, which the position control and the monitors then act on: soft limits, lag
// and the exact-stop window are the joints'. A point the inverse transform cannot map (the
// adapter and the planner check every block before, so only a broken invariant of theirs gets
// here) stops the channel with the kinematic's workspace error NC3201 at the active block.

#include "channel/kinematic_stage.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <span>
#include <string>

#include "core/number_text.hpp"
#include "program/program_source.hpp"
#include "tracking/trafo_sync.hpp"

namespace ncsim::channel {

KinematicStage::KinematicStage(const std::optional<planner::JointLimits>& joints,
                               std::size_t axis_count, planner::JointMap forward, ipo::Sink* sink)
    : relay_(sink), forward_(std::move(forward)) {
  if (joints) stage_.emplace(joints->inverse, axis_count);
}

bool KinematicStage::map(const ipo::Cycle& c, const std::optional<planner::AxisVec>& hold,
                         const tracking::ConveyorSync* sync, double t_cycle, AxisStage& axes,
                         std::optional<RunTimeError>& error) noexcept {
  transformed_ = true;
  // The TCP of this cycle: the path's point, or where a catch-up / departure left it, or the
  // catch-up's own setpoint, or the path's PCS1 point moved by the belt (docs/conveyor.md
  // "Conveyor tracking under #TRAFO ON"): PCS1 -> MCS TCP -> joints.
  planner::AxisVec x = c.x;
  planner::AxisVec v = c.v;
  planner::AxisVec a = c.a;
  planner::AxisVec j = c.j;
  if (hold) {
    x = *hold;
    v = a = j = planner::AxisVec{};
  }
  if (sync && sync->driving()) {
    for (std::size_t i = 0; i < axes.size(); ++i) {
      const axes::Setpoint sp = sync->catch_up_setpoint(i);
      x[i] = sp.p;
      v[i] = sp.v;
      a[i] = sp.a;
      j[i] = sp.j;
    }
  } else if (sync && sync->moving_frame()) {
    for (std::size_t i = 0; i < axes.size(); ++i) {
      x[i] += sync->offset(i);
      v[i] += sync->offset_v(i);
      a[i] += sync->offset_a(i);
    }
  }
  for (std::size_t i = 0; i < axes.size(); ++i)
    tcp_[i] = axes::Setpoint{x[i], v[i], a[i], j[i]};
  ipo::JointSetpoint s;
  if (!stage_->step(x, v, a, j, s)) {
    const planner::AxisVec& p = stage_->failed_point();
    raise(error, "NC3201",
          "TCP point (" + core::human(p[0]) + ", " + core::human(p[1]) + ", " + core::human(p[2]) +
              ") mm outside the workspace of the kinematic transform",
          c, -1);
    return false;
  }
  // the jerk stencil holds this cycle and the two before.
  const bool consecutive = c.index == q_index_ + 1;
  q_plain_ = {c.interval_jerk_limited && !relay_.take_seen(), consecutive && q_plain_[0],
              consecutive && q_plain_[1]};
  if (sync && (sync->driving() || sync->moving_frame())) check_sync(c, s, *sync, t_cycle, axes);
  q_known_ = consecutive ? std::min(q_known_ + 1, 3) : 1;
  q_index_ = c.index;
  q_back3_ = q_back2_;
  q_back2_ = q_back1_;
  q_back1_ = s.q;
  joints_ = s;
  for (std::size_t i = 0; i < axes.size(); ++i)
    axes.setpoints()[i] = axes::Setpoint{s.q[i], s.v[i], s.a[i], s.j[i]};
  return true;
}

void KinematicStage::check_sync(const ipo::Cycle& c, const ipo::JointSetpoint& s,
                                const tracking::ConveyorSync& sync, double t_cycle,
                                const AxisStage& axes) noexcept {
  if (warning_) return;  // the first overrun of the run; the audit lists every one
  std::array<axes::Dynamics, planner::kMaxAxes> dyn{};
  const std::size_t n = std::min(axes.size(), sync.axis_count());
  for (std::size_t i = 0; i < n; ++i)
    dyn[i] = sync.dynamics(i);
  // The closed-form v, a and j of the joints, then their setpoints' differences: a belt that
  // changes faster than its measured acceleration tells (a step, noise without filters) moves
  // the PCS1 offset and with it the joints between cycles beyond what the closed form shows.
  // the jerk as the audit checks it: the closed form on a jerk-limited slope,
  // the third difference where its stencil is jerk-limited and holds no documented path step.
  auto o = tracking::joint_overrun(s, std::span(dyn.data(), n), c.jerk_limited);
  ipo::JointSetpoint diff;
  bool jerk = false;
  if (!o && differences(c, s, axes.size(), t_cycle, diff, jerk))
    o = tracking::joint_overrun(diff, std::span(dyn.data(), n), jerk);
  if (!o) return;
  const char* phase = sync.phase() == tracking::SyncPhase::catching_up ? "the catch-up"
                      : sync.phase() == tracking::SyncPhase::departing ? "the departure"
                                                                       : "synchronised motion";
  const char* quantity = o->quantity == 'v' ? "v" : o->quantity == 'a' ? "a" : "j";
  const char* limit = o->quantity == 'v'   ? "P-AXIS-00212"
                      : o->quantity == 'a' ? "P-AXIS-00008"
                                           : "the jerk of P-AXIS-00195..00198";
  try {
    RunTimeError w;
    w.id = tracking::kTrafoSyncOverrunId;
    w.message = "joint " + axes.config(o->joint).name + ": |" + quantity + "| " +
                core::human(o->value) + " above its " + core::human(o->limit) + " (" + limit +
                ") in " + phase +
                " under #TRAFO ON (004 l.609: the joint dynamics are not ensured there; reduce "
                "the belt velocity or the feed)";
    w.line = c.line;
    w.file = c.file;
    w.t = c.t;
    w.axis = static_cast<int>(o->joint);
    warning_ = std::move(w);
  } catch (...) {
    std::abort();  // out of memory while reporting a warning
  }
}

bool KinematicStage::differences(const ipo::Cycle& c, const ipo::JointSetpoint& s, std::size_t n,
                                 double t_cycle, ipo::JointSetpoint& out,
                                 bool& jerk) const noexcept {
  if (q_known_ < 2 || c.index != q_index_ + 1) return false;
  const double t = t_cycle;
  jerk = q_known_ >= 3 && q_plain_[0] && q_plain_[1] && q_plain_[2];
  for (std::size_t i = 0; i < n; ++i) {
    out.q[i] = s.q[i];
    out.v[i] = (s.q[i] - q_back1_[i]) / t;
    out.a[i] = (s.q[i] - 2.0 * q_back1_[i] + q_back2_[i]) / (t * t);
    out.j[i] =
        jerk ? (s.q[i] - 3.0 * q_back1_[i] + 3.0 * q_back2_[i] - q_back3_[i]) / (t * t * t) : 0.0;
  }
  return true;
}

bool KinematicStage::map_tcp(AxisStage& axes) noexcept {
  const std::size_t n = axes.size();
  planner::AxisVec x{}, v{}, a{}, j{};
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = tcp_[i].p;
    v[i] = tcp_[i].v;
    a[i] = tcp_[i].a;
    j[i] = tcp_[i].j;
  }
  ipo::JointSetpoint s;
  if (!stage_->step(x, v, a, j, s)) return false;
  joints_ = s;
  for (std::size_t i = 0; i < n; ++i)
    axes.setpoints()[i] = axes::Setpoint{s.q[i], s.v[i], s.a[i], s.j[i]};
  return true;
}

bool KinematicStage::plan_sync_motion(tracking::ConveyorSync& sync, bool catch_up,
                                      std::span<const axes::MotionState> start,
                                      std::span<const double> target, double feed_cont,
                                      axes::Result& r) const noexcept {
  const std::size_t n = start.size();
  std::array<axes::Dynamics, planner::kMaxAxes> joints{};
  std::array<axes::Dynamics, planner::kMaxAxes> tcp{};
  for (std::size_t i = 0; i < n; ++i)
    joints[i] = tcp[i] = sync.dynamics(i);
  const planner::JointMap& inverse = stage_->inverse();
  std::array<int, 3> xyz{-1, -1, -1};
  for (std::size_t i = 0; i < n; ++i)
    if (const int k = sync.xyz(i); k >= 0) xyz[static_cast<std::size_t>(k)] = static_cast<int>(i);
  // The points the TCP passes: the start, the target (at the start), and for a catch-up the
  // meeting point and the middle between start and meeting.
  std::array<planner::AxisVec, 4> points{};
  for (std::size_t i = 0; i < n; ++i) {
    points[0][i] = start[i].p;
    points[1][i] = target[i];
    points[2][i] = (start[i].p + target[i]) / 2.0;
  }
  std::size_t count = 3;
  for (int pass = 0; pass < 2; ++pass) {
    const auto d = tracking::tcp_dynamics(inverse, xyz, std::span(joints.data(), n),
                                          std::span(points.data(), count));
    if (!d) {
      r = axes::Result::error_invalid_input;
      return false;
    }
    for (const int k : xyz)
      if (k >= 0) tcp[static_cast<std::size_t>(k)] = *d;
    // FEED_CONT > 0 meets the workpiece moving; the meeting point, its
    // velocity belt + f u inside the TCP's V, is covered by the second pass (S-1).
    r = catch_up ? sync.start_catch_up(start, target, feed_cont, std::span(tcp.data(), n))
                 : sync.start_departure(start, target, std::span(tcp.data(), n));
    if (r != axes::Result::ok || !catch_up) return r == axes::Result::ok;
    // The meeting point is known now: cover it and the way there, then plan again.
    const tracking::CatchUp& cu = sync.catch_up();
    const double vb = cu.belt_velocity();
    const double s_meet = sync.travel() + vb * cu.duration();  // the forecast belt
    for (std::size_t i = 0; i < n; ++i) {
      const axes::Setpoint end = cu.setpoint(i, cu.duration(), s_meet, vb, 0.0);
      points[2][i] = end.p;
      points[3][i] = (start[i].p + end.p) / 2.0;
    }
    count = 4;
  }
  return r == axes::Result::ok;
}

}  // namespace ncsim::channel
