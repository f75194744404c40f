// ipo/joint_report: joints and knees to the Sink (see the header and docs/ipo.md "The audit").

#include "ipo/joint_report.hpp"

#include <algorithm>
#include <cmath>

#include "planner/joint_limits.hpp"

namespace ncsim::ipo {

void JointReport::between(const planner::PlannedSegment& in, const planner::PlannedSegment& out,
                          double t, double v, double a) const noexcept {
  if (sink_ == nullptr) return;
  const planner::Chain& path_in = in.segment.path;
  const planner::PathPoint p_in = path_in.at(path_in.length());
  const planner::PathPoint p_out = out.segment.path.at(0.0);
  const planner::Move& prog_in = queue_.programmed(path_in.line_at(path_in.length()));
  const planner::Move& prog_out = queue_.programmed(out.segment.path.line_at(0.0));
  Joint jt;
  jt.t = t;
  jt.line = prog_in.line;
  jt.file = prog_in.file;
  jt.cls = in.segment.joint;
  jt.stop = in.segment.stop;
  jt.jerk_limited = planner::jerk_limited(prog_in.slope) && planner::jerk_limited(prog_out.slope);
  jt.rapid_in = prog_in.rapid;
  jt.rapid_out = prog_out.rapid;
  jt.c1_limited = c1_limited_;  // P-CHAN-00009
  // The velocity and acceleration are the ones the path arrives with (below the plan's under
  // an override); a != 0 only where a ramp is carried through a soft joint (a knee steps the
  // axis acceleration by a dx' too).
  jt.v = v;
  jt.rule = in.segment.rule;
  jt.transvelmin = planner::transvelmin_at_end(prog_in).value_or(0.0);
  for (std::size_t i = 0; i < axis_count_; ++i) {
    jt.dv[i] = v * (p_out.d1[i] - p_in.d1[i]);
    jt.da[i] = v * v * (p_out.d2[i] - p_in.d2[i]) + a * (p_out.d1[i] - p_in.d1[i]);
  }
  // Under #TRAFO ON the joints' own steps, for the audit's formulas on the joints. Not in PCS1
  // (belt_joints set): the path point is the programmed one, the joints follow it where the
  // belt has carried it (channel/channel_kinematics.cpp), a few per cent apart on the delta
  // picker; those joints stay unlisted and their stencils velocity-only.
  if (joints_ && prog_in.transformed && prog_out.transformed && !prog_in.belt_joints &&
      !prog_out.belt_joints && jt.stop == planner::StopReason::none) {
    const std::size_t nj = joints_->joints.size();
    const auto n =
        static_cast<std::size_t>(std::max(path_in.axis_count(), out.segment.path.axis_count()));
    AxisVec q1_in{}, q2_in{}, q1_out{}, q2_out{};
    if (planner::joint_derivatives(p_in, n, joints_->inverse, nj, q1_in, q2_in) &&
        planner::joint_derivatives(p_out, n, joints_->inverse, nj, q1_out, q2_out)) {
      jt.joint_steps = true;
      for (std::size_t i = 0; i < nj; ++i) {
        jt.dq[i] = v * (q1_out[i] - q1_in[i]);
        jt.dw[i] = v * v * (q2_out[i] - q2_in[i]) + a * (q1_out[i] - q1_in[i]);
      }
    }
  }
  sink_->on_joint(jt);
}

void JointReport::inner(const planner::PlannedSegment& entry, double s_from, double s_to, double t,
                        double v, double a) const noexcept {
  if (sink_ == nullptr) return;
  // Knees inside a chain (planner/corner.hpp knee_carries_acceleration) step the axis velocity
  // by v dx' and the acceleration by v^2 dx'' + a dx' with the path acceleration carried; the
  // audit needs both for its finite-difference allowances. The joint's own instant is not
  // resolved: v and a are bounded by the ceilings of the plan followed (the chain's caps at
  // 100 %, the raised ones under an override above 100 %: issue 36 item 6), which only widens
  // the allowances by what a knee can cause; the VELOJUMP check of v dx' at the cap is the
  // planner's own chaining condition (docs/ipo.md "The audit").
  const planner::Chain& path = entry.segment.path;
  for (std::size_t k = 0; k + 1 < path.parts(); ++k) {
    const double e = path.part_end(k);
    if (!(e > s_from && e <= s_to)) continue;
    const planner::Segment& in = path.part(k);
    const planner::PathPoint p_in = in.at(in.length());
    const planner::PathPoint p_out = path.part(k + 1).at(0.0);
    const planner::Move& prog_in = queue_.programmed(path.part_line(k));
    const planner::Move& prog_out = queue_.programmed(path.part_line(k + 1));
    Joint jt;
    jt.t = t;
    jt.line = prog_in.line;
    jt.file = prog_in.file;
    jt.cls = planner::TransitionClass::c2;
    jt.stop = planner::StopReason::none;
    jt.jerk_limited = planner::jerk_limited(prog_in.slope) && planner::jerk_limited(prog_out.slope);
    jt.rapid_in = prog_in.rapid;
    jt.rapid_out = prog_out.rapid;
    jt.c1_limited = c1_limited_;  // P-CHAN-00009
    jt.v = v;
    for (std::size_t i = 0; i < axis_count_; ++i) {
      const double dt = p_out.d1[i] - p_in.d1[i];
      jt.dv[i] = v * dt;
      jt.da[i] = v * v * std::abs(p_out.d2[i] - p_in.d2[i]) + a * std::abs(dt);
      if (dt != 0.0) jt.cls = planner::TransitionClass::c0;
    }
    sink_->on_joint(jt);
  }
}

}  // namespace ncsim::ipo
