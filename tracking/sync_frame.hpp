#pragma once
// tracking/sync_frame: the co-moving PCS1 frame of conveyor tracking and the conveyor display
// variables (seed 004 §2.1, §4.3, §5.2.2, §6; docs/conveyor.md "Synchronisation").
//
// Purpose: turn the conveyor's position into the frame the program is written in while
// synchronised. At the measurement (t0) PCS1 is PCS0; afterwards PCS1 is PCS0 moved by the
// belt travel since the latch along PCS0's X axis, which points in the positive conveying
// direction (004 l.227-235). T0 (P-CHAN-00368..00373) places PCS0 in MCS.
// Inputs: the channel's conveyor_sync parameters (T0, P-CHAN-00363 direction), the latched
// conveyor position, the conveyor's measured and master (filtered, delay-compensated) state.
// Outputs: the belt travel s [mm] along PCS0 X, PCS1 <-> MCS for X/Y/Z, the conveying
// direction in MCS, and the display variables of 004 §6 (current_*_master, *_master_comp,
// synchro_lag) in mm, mm/s, mm/s^2.
// Method: travel s = sign * (p_conveyor - p_latch), sign = +1 for P-CHAN-00363 = 0 (the
// conveyor moves at positive velocity in +X), -1 for P-CHAN-00363 = 1 (004 l.1267-1275).
// p_mcs = T0(p_pcs1 + s * e_x) = T0(p_pcs1) + s * R0 e_x: the offset is the travel along the
// conveying direction R0 e_x in MCS. "Synchronisation is always with the 1st axis in the
// channel" (004 l.227): with an unrotated T0 the offset is on X (machine axis of the channel's
// first main axis) only.
// Invariants: pure values; no function throws; R0 is orthonormal, so |direction()| = 1.

#include <Eigen/Core>

#include "conveyor/port.hpp"
#include "machines/machine.hpp"

namespace ncsim::tracking {

class SyncFrame {
 public:
  /// The frame of `channel` (T0, P-CHAN-00363); not latched.
  explicit SyncFrame(const machines::ConveyorSyncChannel& channel);

  /// A measurement: `p_latch` [mm] is the conveyor position latched at the trigger.
  void latch(double p_latch) noexcept {
    latch_ = p_latch;
    latched_ = true;
  }
  bool latched() const noexcept { return latched_; }
  double latch_position() const noexcept { return latch_; }  ///< [mm] conveyor position

  /// +1 (P-CHAN-00363 = 0) or -1 (= 1): the sign of the conveyor velocity in +X.
  double sign() const noexcept { return sign_; }
  /// The belt travel since the latch along PCS0 X for conveyor position `p` [mm].
  double travel(double p) const noexcept { return sign_ * (p - latch_); }
  /// The belt velocity along PCS0 X for the conveyor velocity `v` [mm/s] (also accelerations).
  double along_x(double v) const noexcept { return sign_ * v; }

  /// PCS0 +X (the positive conveying direction) in MCS: R0 e_x, a unit vector.
  const Eigen::Vector3d& direction() const noexcept { return direction_; }
  /// PCS1 point -> MCS at belt travel `s` [mm].
  Eigen::Vector3d to_mcs(const Eigen::Vector3d& p_pcs1, double s) const noexcept;
  /// MCS point -> PCS1 at belt travel `s` [mm].
  Eigen::Vector3d to_pcs1(const Eigen::Vector3d& p_mcs, double s) const noexcept;
  /// The MCS offset of PCS1 against PCS0 at travel `s`: s * direction() [mm].
  Eigen::Vector3d offset(double s) const noexcept { return direction_ * s; }
  /// T0: PCS0 -> MCS.
  const machines::Frame& t0() const noexcept { return t0_; }

 private:
  machines::Frame t0_;
  Eigen::Vector3d direction_ = Eigen::Vector3d::UnitX();
  double sign_ = 1.0;
  double latch_ = 0.0;
  bool latched_ = false;
};

/// The conveyor display variables of seed 004 §6 (l.1508-1610), in mm, mm/s, mm/s^2 (the
/// kernel shows them as DINT in 0.1 um, 0.1 um/s, 0.1 um/s^2).
struct MasterDisplay {
  /// false before the first measurement: the manual's values are "valid only after a
  /// measurement"; every field is 0 then.
  bool valid = false;
  /// The workpiece (its front edge at the measurement) in PCS0 X, unfiltered: P-CHAN-00368
  /// (T0's X shift) at the measurement, then growing with the measured belt travel [mm].
  double current_pos_master = 0.0;
  double current_v_master = 0.0;  ///< measured conveyor velocity along PCS0 X [mm/s]
  double current_a_master = 0.0;  ///< measured conveyor acceleration along PCS0 X [mm/s^2]
  /// As current_pos_master from the master value (filtered + delay compensation) [mm].
  double pos_master_comp = 0.0;
  double v_master_comp = 0.0;  ///< master velocity along PCS0 X [mm/s]
  double a_master_comp = 0.0;  ///< master acceleration along PCS0 X [mm/s^2]
  // Filled by Channel::master_display() (tracking/synchro_lag.hpp), 0 elsewhere
  /// Machine minus real workpiece along the conveying direction [mm] while the frame moves.
  double synchro_lag = 0.0;
};

/// The display variables of `frame` for the conveyor's measured and master states.
MasterDisplay master_display(const SyncFrame& frame, const conveyor::BeltState& measured,
                             const conveyor::BeltState& master) noexcept;

/// synchro_lag (004 l.1600-1606; the manual prints "> 0" for both signs, ncsim states it):
/// the actual machine position minus the workpiece position along the conveying direction
/// [mm]:  lag = direction() . (x_actual_mcs - to_mcs(p_pcs1, s)),
/// with p_pcs1 the commanded point in PCS1 and s the workpiece's travel. The channel passes
/// the real belt's travel (Port::actual(), which a simulation knows): the display exists to
/// tune the delay time P-AXIS-00626, and its static part is then v * (delay_time - dead
/// time) minus the axis's following error, zero at the right delay (004 l.737-747).
/// lag > 0: the machine is ahead of the workpiece in the conveying direction; lag < 0: behind.
double synchro_lag(const SyncFrame& frame, const Eigen::Vector3d& x_actual_mcs,
                   const Eigen::Vector3d& p_pcs1, double s) noexcept;

}  // namespace ncsim::tracking
