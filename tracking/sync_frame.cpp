// tracking/sync_frame: the PCS1 frame and the conveyor display variables (see the header).

#include "tracking/sync_frame.hpp"

namespace ncsim::tracking {

SyncFrame::SyncFrame(const machines::ConveyorSyncChannel& channel)
    : t0_(channel.t0()),
      direction_(channel.t0().apply_vector(Eigen::Vector3d::UnitX())),
      sign_(channel.direction == machines::MoveDirection::negative_x ? -1.0 : 1.0) {}

Eigen::Vector3d SyncFrame::to_mcs(const Eigen::Vector3d& p_pcs1, double s) const noexcept {
  return t0_.apply(p_pcs1) + direction_ * s;
}

Eigen::Vector3d SyncFrame::to_pcs1(const Eigen::Vector3d& p_mcs, double s) const noexcept {
  return t0_.inverse().apply(p_mcs - direction_ * s);
}

MasterDisplay master_display(const SyncFrame& frame, const conveyor::BeltState& measured,
                             const conveyor::BeltState& master) noexcept {
  MasterDisplay d;
  if (!frame.latched()) return d;
  // "The actual position of the workpiece in the currently selected PCS ... including the
  // measurement and T0" (004 l.1508-1530): at the measurement it is T0's X shift
  // P-CHAN-00368 (004 l.663), then it grows with the belt travel.
  const double x0 = frame.t0().translation.x();
  d.valid = true;
  d.current_pos_master = x0 + frame.travel(measured.p);
  d.current_v_master = frame.along_x(measured.v);
  d.current_a_master = frame.along_x(measured.a);
  d.pos_master_comp = x0 + frame.travel(master.p);
  d.v_master_comp = frame.along_x(master.v);
  d.a_master_comp = frame.along_x(master.a);
  return d;
}

double synchro_lag(const SyncFrame& frame, const Eigen::Vector3d& x_actual_mcs,
                   const Eigen::Vector3d& p_pcs1, double s) noexcept {
  return frame.direction().dot(x_actual_mcs - frame.to_mcs(p_pcs1, s));
}

}  // namespace ncsim::tracking
