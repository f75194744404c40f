#pragma once
// tracking/workspace: the conveyor workspace monitored while synchronised (seed 004 §2.1.3, §4.4;
// docs/conveyor.md "Workspace").
//
// Purpose: tell whether the commanded TCP (MCS X/Y/Z) has left the workspace cuboid, and
// through which face. The cuboid is P-CHAN-00859..00864, else the soft limits of the first
// three axes (machines/loader_checks.cpp fills ConveyorSyncChannel::workspace either way).
// Inputs: the cuboid [mm], the conveying direction in MCS (SyncFrame::direction()), the point.
// Outputs: nothing, or the violated face: in the conveying direction (the manual: the program
// is aborted; ncsim id NC9052), against it (the manual's simple / optimised hold methods,
// P-AXIS-00555), or a side face (Y/Z of an unrotated T0: ncsim decision, aborted with NC9053).
// Invariants: pure; never throws. A face's class is by the angle of its outward normal n with
// the conveying direction e: n.e > cos 60 deg conveying, n.e < -cos 60 deg against, else side.

#include <Eigen/Core>
#include <optional>

#include "machines/machine.hpp"

namespace ncsim::tracking {

/// NC9052: the TCP left the conveyor workspace in the conveying direction while synchronised
/// (004 §2.1.3: the program is aborted; the manual gives no id).
inline constexpr const char* kWorkspaceConveyingId = "NC9052";
/// NC9053: the TCP left the conveyor workspace through a side face (neither with nor against
/// the conveying direction) while synchronised (ncsim decision; the manual describes X only).
inline constexpr const char* kWorkspaceSideId = "NC9053";

enum class WorkspaceFace : std::uint8_t { conveying, against, side };

struct WorkspaceViolation {
  int coord = 0;       ///< 0, 1, 2: MCS X, Y, Z
  bool upper = false;  ///< the upper face (P-CHAN-00859/861/863), else the lower
  double value = 0.0;  ///< the point's coordinate [mm]
  double limit = 0.0;  ///< the face's coordinate [mm]
  WorkspaceFace face = WorkspaceFace::side;
};

/// The first face of `box` that `p_mcs` is beyond (X before Y before Z), if any.
std::optional<WorkspaceViolation> check_workspace(const machines::Workspace& box,
                                                  const Eigen::Vector3d& direction,
                                                  const Eigen::Vector3d& p_mcs) noexcept;

}  // namespace ncsim::tracking
