// planner/joint_limits: joint derivative bounds along a Cartesian segment (joint_limits.hpp).

#include "planner/joint_limits.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ncsim::planner {

std::optional<DerivativeBounds> joint_bounds(const Segment& segment, const JointMap& inverse,
                                             std::size_t joint_count) {
  const std::size_t n = segment.axis_count();
  const double length = segment.length();
  // Clamped as a double before the conversion: a huge length would overflow the int.
  const int samples = static_cast<int>(
      std::fmin(std::fmax(std::ceil(length / kJointSpacing), double{kJointMinSamples}),
                double{kJointMaxSamples}));
  const double ds = length / samples;
  const double d = kJointStep;
  DerivativeBounds b;
  std::array<AxisVec, 5> q{};
  for (int k = 0; k <= samples; ++k) {
    const PathPoint p = segment.at(ds * k);
    for (int m = 0; m < 5; ++m) {
      const double h = (m - 2) * d;
      AxisVec x = p.x;
      for (std::size_t i = 0; i < n; ++i)
        x[i] += h * p.d1[i] + 0.5 * h * h * p.d2[i] + h * h * h / 6.0 * p.d3[i];
      if (!inverse(x, q[m])) return std::nullopt;
    }
    for (std::size_t i = 0; i < joint_count; ++i) {
      const double q1 = (q[3][i] - q[1][i]) / (2.0 * d);
      const double q2 = (q[3][i] - 2.0 * q[2][i] + q[1][i]) / (d * d);
      const double q3 = (q[4][i] - 2.0 * q[3][i] + 2.0 * q[1][i] - q[0][i]) / (2.0 * d * d * d);
      b.d1[i] = std::max(b.d1[i], std::abs(q1));
      b.d2[i] = std::max(b.d2[i], std::abs(q2));
      b.d3[i] = std::max(b.d3[i], std::abs(q3));
    }
  }
  for (std::size_t i = 0; i < joint_count; ++i) {
    b.d3[i] *= 1.0 + kJointMargin;
    b.d2[i] += 0.5 * ds * b.d3[i];
    b.d1[i] += 0.5 * ds * b.d2[i];
  }
  return b;
}

bool joint_derivatives(const PathPoint& p, std::size_t axis_count, const JointMap& inverse,
                       std::size_t joint_count, AxisVec& d1, AxisVec& d2) {
  const double d = kJointStep;
  std::array<AxisVec, 3> q{};
  for (int m = 0; m < 3; ++m) {
    const double h = (m - 1) * d;
    AxisVec x = p.x;
    for (std::size_t i = 0; i < axis_count; ++i)
      x[i] += h * p.d1[i] + 0.5 * h * h * p.d2[i] + h * h * h / 6.0 * p.d3[i];
    if (!inverse(x, q[m])) return false;
  }
  d1 = AxisVec{};
  d2 = AxisVec{};
  for (std::size_t i = 0; i < joint_count; ++i) {
    d1[i] = (q[2][i] - q[0][i]) / (2.0 * d);
    d2[i] = (q[2][i] - 2.0 * q[1][i] + q[0][i]) / (d * d);
  }
  return true;
}

AxisLimits joint_rapid_limits(const AxisLimits& joint) noexcept {
  AxisLimits r = rapid_limits(joint);
  r.v_max = std::min({joint.v_rapid, joint.v_reference, joint.v_max});
  return r;
}

std::optional<PathLimits> path_limits(const Segment& segment, const Move& move,
                                      std::span<const AxisLimits> axes, const JointMap& inverse,
                                      std::span<const AxisLimits> joints) {
  PathLimits out = path_limits(segment, move, axes);
  if (segment.length() <= 0.0) return out;
  const auto b = joint_bounds(segment, inverse, joints.size());
  if (!b) return std::nullopt;
  // The joints' own limits at most at the axis cap. Each of v, a, d, j is the smaller of the two
  // sets; the joint set's a and j were derived at a velocity (and acceleration) no smaller than
  // the combined ones, so they stay valid (the budgets used by v and a only shrink).
  // G00 under a transform (issue 12): each joint at its own rapid rule,
  // MIN(rapid P-AXIS-00209, reference, maximum) (000 l.360), with its G00 slope (P-AXIS-00004
  // acceleration, P-AXIS-00200 ramp time; planner::rapid_limits); the slowest joint sets the
  // time. Feed blocks keep the joints' feed limits.
  // A G00 in PCS1 (Move::belt_joints set by the adapter, tracking::belt_share of
  // these rapid limits): `joints` come lowered by the belt's acceleration and jerk shares
  // (Preparer::limits); where the G00 slope replaces them (a_rapid, j_rapid) the shares are
  // taken off the slope too, and the velocity share caps the path at Move::feed, the adapter's
  // cap (docs/conveyor.md "Machining in PCS1").
  const JointShare* share = move.rapid ? move.belt_joints.get() : nullptr;
  std::array<AxisLimits, kMaxAxes> rapid{};
  std::span<const AxisLimits> used = joints;
  if (move.rapid && joints.size() <= kMaxAxes) {
    for (std::size_t i = 0; i < joints.size(); ++i) {
      rapid[i] = joint_rapid_limits(joints[i]);
      if (share == nullptr) continue;
      const AxisLimits lowered = belt_joint_limits(rapid[i], share->a[i], share->j[i]);
      if (joints[i].a_rapid > 0.0) rapid[i].a_max = rapid[i].d_max = lowered.a_max;
      if (joints[i].j_rapid > 0.0) rapid[i].j_max = lowered.j_max;
    }
    used = std::span<const AxisLimits>(rapid.data(), joints.size());
  }
  double cap = out.v_max;
  if (share != nullptr && move.feed > 0.0) cap = std::min(cap, move.feed);
  const PathLimits jl = limits_from_bounds(*b, used, cap, jerk_limited(move.slope));
  if (jl.v_max < out.v_max) {
    out.v_max = jl.v_max;
    out.limit = VelocityLimit::joint;
    out.limiting_axis = jl.limiting_axis;
  }
  out.v_end = std::min(out.v_end, out.v_max);
  out.a_max = std::min(out.a_max, jl.a_max);
  out.d_max = std::min(out.d_max, jl.d_max);
  out.j_max = std::min(out.j_max, jl.j_max);
  return out;
}

}  // namespace ncsim::planner
