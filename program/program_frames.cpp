// program/program_frames: #CS frames at the adapter (docs/ipo.md "Frames at the adapter").
//
// A motion programmed in PCS under a #CS chain (static frames) is planned in MCS: its start,
// end and arc centre go through the chain's frame F (machines::CsStack, the interpreter's rules
// and the channel's rotation sequence P-CHAN-00394), applied to the X, Y, Z axis values; other
// axes pass unchanged. F is rigid, so a line stays a line; an arc stays an arc of the same
// radius in the rotated plane spanned by F's images of its two plane axes (planner::ArcPlane),
// turning the same way about the image of the third axis; the helix rise is rotated with it.
// Under #SYNC (PCS1) the points go through T0 after the chain: the MCS point at belt travel 0;
// the channel adds the travel (tracking/conveyor_sync). Under #TRAFO ON the result is the Cartesian
// TCP in MCS (the transform acts below the #CS chain, as in the interpreter).

#include <cmath>
#include <string>

#include "interp/cs_select.hpp"
#include "program/program_source.hpp"

namespace ncsim::ipo {

void ProgramSource::select_cs(const interp::SelectCs& sel, std::uint32_t line) {
  const std::optional<machines::CsError> err = interp::apply_selection(cs_, sel);
  // The interpreter applied the same operation to the same stack and reported its errors; a
  // disagreement here is a broken invariant of the seam, reported rather than run.
  if (err || cs_.active_count() != sel.active_count)
    fail(line, "#CS selection the adapter cannot follow (" + (err ? err->message : "depth") + ")");
  cs_frame_ = cs_.active_frame();
}

machines::Frame ProgramSource::frame_to_mcs(const interp::CoordFrame& frame) const {
  // --- conveyor-sync: PCS1 at belt travel 0 is PCS0, placed in MCS by T0 (P-CHAN-00368..00373);
  // the channel adds the belt travel (tracking/conveyor_sync, docs/conveyor.md). #CS systems
  // selected after the catch-up sit on PCS1.
  if (frame.space == interp::Space::pcs1 && machine_.channel.conveyor)
    return machine_.channel.conveyor->t0() * cs_frame_;
  return cs_frame_;
}

interp::CommandBody ProgramSource::sync_motion(const interp::CommandBody& motion,
                                               std::uint32_t line) {
  interp::Motion m = std::get<interp::Motion>(motion);
  const planner::AxisVec end = to_mcs(m.frame, m.end, line);
  m.end = interp::AxisValues{};
  for (std::size_t k = 0; k < axes_.size(); ++k)
    m.end[k] = end[k];
  m.frame = interp::CoordFrame{};
  return m;
}

planner::AxisVec ProgramSource::to_mcs(const interp::CoordFrame& frame, const interp::AxisValues& p,
                                       std::uint32_t line) {
  interp::AxisValues m = p;
  if (frame.space != interp::Space::mcs) {
    if (frame.cs_depth != cs_.active_count())
      fail(line, "motion in frame " + interp::frame_name(frame) + " with " +
                     std::to_string(cs_.active_count()) + " #CS systems known to the adapter");
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k)
      if (xyz_[k] >= 0) q[static_cast<Eigen::Index>(k)] = p[static_cast<std::size_t>(xyz_[k])];
    q = frame_to_mcs(frame).apply(q);
    for (std::size_t k = 0; k < 3; ++k) {
      const double value = q[static_cast<Eigen::Index>(k)];
      if (xyz_[k] >= 0) {
        m[static_cast<std::size_t>(xyz_[k])] = value;
      } else if (std::abs(value) > 1e-9) {
        fail(line, std::string("#CS frame moves the ") + "XYZ"[k] +
                       " axis, which this machine does not have");
      }
    }
  }
  planner::AxisVec out{};
  for (std::size_t k = 0; k < axes_.size(); ++k)
    out[k] = m[axes_[k]];
  return out;
}

void ProgramSource::arc_to_mcs(const interp::Motion& m, std::uint32_t line, planner::Move& move) {
  const interp::Arc& in = *m.arc;
  const int a1 = slot_[in.axis_1];
  const int a2 = slot_[in.axis_2];
  if (a1 < 0 || a2 < 0) fail(line, "arc in a plane with a non-interpolated axis");
  planner::Arc arc;
  arc.axis_1 = static_cast<std::uint8_t>(a1);
  arc.axis_2 = static_cast<std::uint8_t>(a2);
  arc.centre_1 = in.centre_1;
  arc.centre_2 = in.centre_2;
  arc.clockwise = m.kind == interp::MotionKind::arc_cw;
  arc.full_circle = in.full_circle;
  move.arc = arc;
  if (m.frame.space == interp::Space::mcs) return;
  const machines::Frame f = frame_to_mcs(m.frame);

  int k1 = -1;
  int k2 = -1;
  for (int k = 0; k < 3; ++k) {
    if (xyz_[static_cast<std::size_t>(k)] == in.axis_1) k1 = k;
    if (xyz_[static_cast<std::size_t>(k)] == in.axis_2) k2 = k;
  }
  if (k1 < 0 || k2 < 0) fail(line, "arc under #CS in a plane that is not made of X, Y, Z");
  // The centre in PCS: the start's X, Y, Z with the plane coordinates of the centre.
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < 3; ++k)
    if (xyz_[k] >= 0) c[static_cast<Eigen::Index>(k)] = m.start[static_cast<std::size_t>(xyz_[k])];
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
    if (xyz_[k] < 0 || slot_[static_cast<std::size_t>(xyz_[k])] < 0)
      fail(line, "arc under a rotated #CS needs interpolated X, Y and Z axes");
  planner::ArcPlane g;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    g.axes[k] = static_cast<std::uint8_t>(slot_[static_cast<std::size_t>(xyz_[k])]);
    g.u[k] = r(row, k1);
    g.v[k] = r(row, k2);
    g.centre[k] = c[row];
  }
  move.arc_plane = g;
}

}  // namespace ncsim::ipo
