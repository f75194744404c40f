#pragma once
// tracking/synchro_lag: the display variable synchro_lag of the cycle (seed 004 §6, l.1594-1606;
// docs/conveyor.md "synchro_lag sign").
//
// Purpose: what the manual calls "the current difference between the actual position of the
// machine axis and the feedforward controlled actual position of the workpiece", measured
// against the workpiece as it really moves (a simulation knows the real belt), so that its
// mean tells how far the delay time P-AXIS-00626 is off (004 l.1601-1605).
// Inputs: the channel's ConveyorSync (its frame, master travel and Port: the real belt
// Port::actual() and the real front edge Port::last_latch()), the cycle's MCS command and
// actual X/Y/Z of the machine.
// Output: synchro_lag [mm] along the conveying direction, only while the path point is in
// PCS1 on the moving frame (tracking, leaving); nullopt otherwise ("valid only after a
// measurement"; during a catch-up or departure the command is not a PCS1 point).
// Sign (the manual prints "> 0" twice): lag = e . (x_actual - x_workpiece), e the conveying
// direction in MCS, x_workpiece the commanded PCS1 point on the real workpiece. lag > 0: the
// machine is ahead of the workpiece in the conveying direction (the frame runs ahead: the delay
// time is too high); lag < 0: behind (too low).
// Method: the commanded PCS1 point p = to_pcs1(x_command, s_master); the real workpiece's
// travel s_real = sign * (p_belt_real - p_belt_real_at_edge) plus the sensor's offset against
// T0 (LatchInfo::sensor_x - P-CHAN-00368) along the conveying direction; then
// tracking::synchro_lag(frame, x_actual, p, s_real). A Port without workpieces (a test double,
// LatchInfo::workpiece == 0) takes its latched value as the truth.
// Under #TRAFO ON the axes are joints: tcp_lag() takes the commanded TCP and the forward
// transform of the joints' actual positions instead (the caller holds the transform).
// Invariants: pure; never throws.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <span>

#include "planner/joint_limits.hpp"
#include "tracking/conveyor_sync.hpp"

namespace ncsim::tracking {

/// synchro_lag [mm] for the MCS command `x_command` and actual `x_actual` (X, Y, Z [mm]) of the
/// cycle `sync` last stepped; nullopt unless sync.moving_frame() and a Port is attached.
std::optional<double> tracking_lag(const ConveyorSync& sync, const Eigen::Vector3d& x_command,
                                   const Eigen::Vector3d& x_actual) noexcept;

/// synchro_lag from the channel's per-axis set (`command`) and actual positions [mm | deg],
/// gathered into X/Y/Z by sync.xyz(i); nullopt as tracking_lag() and under #TRAFO ON
/// (`transformed`: the axes are joints, not X/Y/Z). The one place the channel's display
/// (Channel::master_display) and the report take it from.
std::optional<double> axes_lag(const ConveyorSync& sync, std::span<const double> command,
                               std::span<const double> actual, bool transformed) noexcept;

/// synchro_lag under #TRAFO ON: the commanded TCP `tcp` (Channel::tcp()'s positions, the
/// channel's interpolated order: PCS1 point plus the belt offset, MCS) against the actual TCP,
/// the forward transform `forward` (program::forward_map) of the joints' actual positions `joints`
/// (Channel::axes().actual). nullopt as tracking_lag() and where `forward` is empty or fails.
std::optional<double> tcp_lag(const ConveyorSync& sync, std::span<const double> tcp,
                              const planner::AxisVec& joints,
                              const planner::JointMap& forward) noexcept;

/// synchro_lag of a channel cycle, the one choice the channel's display (Channel::master_display),
/// the report and tune-delay take it from: axes_lag() of the axes' `command` and `actual`
/// positions; under #TRAFO ON (`transformed`) tcp_lag() of the commanded TCP `tcp`
/// (Channel::tcp()) and the joints' actual positions `actual` with `forward` (nullopt where
/// `tcp` is null or `forward` empty: a caller without the TCP or the machine's transform).
std::optional<double> cycle_lag(const ConveyorSync& sync, std::span<const double> command,
                                std::span<const double> actual, bool transformed,
                                const std::array<axes::Setpoint, planner::kMaxAxes>* tcp,
                                const planner::JointMap& forward) noexcept;

/// The real workpiece's travel [mm] equivalent to the frame's travel (the frame's s when the NC
/// were exact): the real belt since the real front edge passed the sensor, plus the sensor's
/// offset against T0 along the conveying direction. Needs sync.port() != nullptr.
double real_travel(const ConveyorSync& sync) noexcept;

}  // namespace ncsim::tracking
