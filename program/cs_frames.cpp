#include "program/cs_frames.hpp"

#include <cmath>
#include <string>

#include "core/tolerance.hpp"
#include "interp/cs_select.hpp"

namespace ncsim::program {

CsFrames::CsFrames(const machines::Machine& machine, const AxisLayout& layout, SourceErrors& errors)
    : machine_(machine),
      layout_(layout),
      errors_(errors),
      cs_(machine.channel.cs_rotation_sequence) {}

void CsFrames::select(const interp::SelectCs& sel, std::uint32_t line) {
  const std::optional<machines::CsError> err = interp::apply_selection(cs_, sel);
  // The interpreter applied the same operation to the same stack and reported its errors; a
  // disagreement here is a broken invariant of the seam, reported rather than run.
  if (err || cs_.active_count() != sel.active_count)
    errors_.not_supported(
        line, "#CS selection the adapter cannot follow (" + (err ? err->message : "depth") + ")");
  active_ = cs_.active_frame();
}

machines::Frame CsFrames::to_mcs(const interp::CoordFrame& frame) const {
  // PCS1 at belt travel 0 is PCS0, placed in MCS by T0 (P-CHAN-00368..00373); the channel adds
  // the belt travel (tracking/conveyor_sync, docs/conveyor.md). #CS systems selected after the
  // catch-up sit on PCS1.
  if (frame.space == interp::Space::pcs1 && machine_.channel.conveyor)
    return machine_.channel.conveyor->t0() * active_;
  return active_;
}

interp::CommandBody CsFrames::sync_motion(const interp::CommandBody& motion,
                                          std::uint32_t line) const {
  interp::Motion m = std::get<interp::Motion>(motion);
  const planner::AxisVec end = to_mcs(m.frame, m.end, line);
  m.end = interp::AxisValues{};
  for (std::size_t k = 0; k < layout_.axes.size(); ++k)
    m.end[k] = end[k];
  m.frame = interp::CoordFrame{};
  return m;
}

planner::AxisVec CsFrames::to_mcs(const interp::CoordFrame& frame, const interp::AxisValues& p,
                                  std::uint32_t line) const {
  const std::array<int, 3>& xyz = layout_.xyz;
  interp::AxisValues m = p;
  if (frame.space != interp::Space::mcs) {
    if (frame.cs_depth != cs_.active_count())
      errors_.not_supported(line, "motion in frame " + interp::frame_name(frame) + " with " +
                                      std::to_string(cs_.active_count()) +
                                      " #CS systems known to the adapter");
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k)
      if (xyz[k] >= 0) q[static_cast<Eigen::Index>(k)] = p[static_cast<std::size_t>(xyz[k])];
    q = to_mcs(frame).apply(q);
    for (std::size_t k = 0; k < 3; ++k) {
      const double value = q[static_cast<Eigen::Index>(k)];
      if (xyz[k] >= 0) {
        m[static_cast<std::size_t>(xyz[k])] = value;
      } else if (std::abs(value) > kSamePoint) {
        errors_.not_supported(line, std::string("#CS frame moves the ") + "XYZ"[k] +
                                        " axis, which this machine does not have");
      }
    }
  }
  planner::AxisVec out{};
  for (std::size_t k = 0; k < layout_.axes.size(); ++k)
    out[k] = m[layout_.axes[k]];
  return out;
}

void CsFrames::arc_to_mcs(const interp::Motion& m, std::uint32_t line, planner::Move& move) const {
  const std::array<int, 3>& xyz = layout_.xyz;
  const interp::Arc& in = *m.arc;
  const int a1 = layout_.slot[in.axis_1];
  const int a2 = layout_.slot[in.axis_2];
  if (a1 < 0 || a2 < 0) errors_.not_supported(line, "arc in a plane with a non-interpolated axis");
  planner::Arc arc;
  arc.axis_1 = static_cast<std::uint8_t>(a1);
  arc.axis_2 = static_cast<std::uint8_t>(a2);
  arc.centre_1 = in.centre_1;
  arc.centre_2 = in.centre_2;
  arc.clockwise = m.kind == interp::MotionKind::arc_cw;
  arc.full_circle = in.full_circle;
  move.arc = arc;
  if (m.frame.space == interp::Space::mcs) return;
  const machines::Frame f = to_mcs(m.frame);

  int k1 = -1;
  int k2 = -1;
  for (int k = 0; k < 3; ++k) {
    if (xyz[static_cast<std::size_t>(k)] == in.axis_1) k1 = k;
    if (xyz[static_cast<std::size_t>(k)] == in.axis_2) k2 = k;
  }
  if (k1 < 0 || k2 < 0)
    errors_.not_supported(line, "arc under #CS in a plane that is not made of X, Y, Z");
  // The centre in PCS: the start's X, Y, Z with the plane coordinates of the centre.
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < 3; ++k)
    if (xyz[k] >= 0) c[static_cast<Eigen::Index>(k)] = m.start[static_cast<std::size_t>(xyz[k])];
  c[k1] = in.centre_1;
  c[k2] = in.centre_2;
  c = f.apply(c);
  const Eigen::Matrix3d& r = f.rotation;
  if (r == Eigen::Matrix3d::Identity()) {  // a shift only: the same principal plane
    move.arc->centre_1 = c[k1];
    move.arc->centre_2 = c[k2];
    return;
  }
  for (std::size_t k = 0; k < 3; ++k)
    if (layout_.xyz_slot(k) < 0)
      errors_.not_supported(line, "arc under a rotated #CS needs interpolated X, Y and Z axes");
  planner::ArcPlane g;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    g.axes[k] = static_cast<std::uint8_t>(layout_.xyz_slot(k));
    g.u[k] = r(row, k1);
    g.v[k] = r(row, k2);
    g.centre[k] = c[row];
  }
  move.arc_plane = g;
}

}  // namespace ncsim::program
