#pragma once
// tracking/sync_error_trafo: the stop after an error while synchronised under #TRAFO ON (seed 004
// §2.3 l.492-498 with §2.2 l.609, l.687; docs/conveyor.md "Errors while synchronised",
// "Under #TRAFO ON").
//
// Purpose: after the error the TCP follows the belt (the path velocity in PCS1 goes to 0); the
// machine must come to rest before its limit. Under a kinematic transform the limit the TCP
// can see is the conveyor workspace (P-CHAN-00859..00864), which the manual requires whenever
// a kinematic transformation is used (l.687): the TCP brakes, as a Cartesian motion on its own
// line (Y and Z keep the path's point), before the workspace's face. This module gives the
// tracking::SyncErrorStop that brakes the TCP its per-axis limits.
// Inputs: the inverse transform, the interpolated indices of the Cartesian X, Y, Z, the joints'
// after-error limits (tracking::after_error_axis of each joint), the workspace box [mm], the belt's
// direction in MCS (unit), the TCP at the error [mm].
// Outputs: per interpolated axis an AfterErrorAxis: X, Y, Z get the box's faces as their
// "soft limits" and the TCP dynamics derived from the joints' (tracking::tcp_dynamics) at the
// points the following passes (the TCP, then along the belt up to the face ahead); the other
// axes keep their own. The TCP's velocity bound is kTcpFollowVelocity: a joint that following
// would take above its V is checked on the joints (SyncErrorStop on the joint setpoints).
// Invariants: pure, never throws; nullopt when the transform fails at the TCP itself or a
// joint's limits are unusable (the channel then ends the run at once, as before).

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <optional>
#include <span>

#include "ipo/joint_stage.hpp"
#include "machines/machine.hpp"
#include "tracking/sync_error.hpp"

namespace ncsim::tracking {

/// The TCP's velocity bound of the after-error stop [mm/s]: none (the joints' own is checked).
inline constexpr double kTcpFollowVelocity = 1e9;
/// Points sampled along the belt from the TCP to the workspace face ahead (tcp_dynamics).
inline constexpr std::size_t kTcpFollowSamples = 9;

/// The limits the TCP's stop after an error under #TRAFO ON brakes with, one per interpolated
/// axis (`n` of them; see the header). Never throws.
std::optional<std::array<AfterErrorAxis, planner::kMaxAxes>> tcp_after_error_axes(
    const planner::JointMap& inverse, std::array<int, 3> xyz,
    std::span<const AfterErrorAxis> joints, const machines::Workspace& box,
    const Eigen::Vector3d& direction, const planner::AxisVec& tcp) noexcept;

}  // namespace ncsim::tracking
