#pragma once
// program/trafo: the machine's kinematic transform (#TRAFO ON) as the path interpolator and the
// channel use it (docs/ipo.md "Kinematics in run and time").
//
// Purpose: under #TRAFO ON a program's X, Y, Z are the Cartesian TCP; the machine axes X, Y, Z
// are the joints of the kinematic (the three drives of a delta robot, #KIN ID[37]; with the six
// joints of an articulated arm, #KIN ID[45], the axes X, Y, Z, A, B, C, and A, B, C the tool
// orientation under #TRAFO ON). This unit
// builds, from a machine, the inverse map Cartesian point -> machine axis values and the limits
// the planner needs (planner::JointLimits).
// Inputs: machines::Machine (its first configured kinematic, trafo[0], P-CHAN-00262/00263), the
// interpolator Config of the machine (axis limits in interpolated-axis order).
// Outputs: MachineTrafo: the kinematic, its id, the JointLimits (joints = the machine axes in
// interpolated order with their own limits; the map replaces the kinematic's slots (X, Y, Z, or
// X, Y, Z, A, B, C) by the inverse transform and passes every other axis through; the Cartesian
// slots without limits of their own, kCartesianUnlimited*).
// Invariants: the map never throws (a failing inverse returns false); joint count = axis count.

#include <array>
#include <memory>
#include <optional>

#include "ipo/interpolator.hpp"
#include "machines/kinematics.hpp"
#include "machines/machine.hpp"

namespace ncsim::program {

/// The Cartesian X, Y, Z under #TRAFO have no limits of their own in ncsim (decision,
/// docs/planner.md "Kinematics"): the joints' v, a, j limit the path. These stand-ins are far
/// above any joint-derived limit, so they never decide a cap; v [mm/s], a [mm/s^2], j [mm/s^3].
inline constexpr double kCartesianUnlimitedV = 1e6;
inline constexpr double kCartesianUnlimitedA = 1e9;
inline constexpr double kCartesianUnlimitedJ = 1e12;

struct MachineTrafo {
  int kin_id = 0;                                          ///< P-CHAN-00262 trafo[0].id
  std::shared_ptr<const machines::Kinematics> kinematics;  ///< built from trafo[0]
  std::array<int, 3> xyz{-1, -1, -1};  ///< interpolated indices of X, Y, Z (-1: none)
  /// Interpolated indices of the kinematic's slots X, Y, Z, A, B, C (-1: none, or beyond the
  /// kinematic's axis_count()).
  std::array<int, machines::kKinAxes> slots{-1, -1, -1, -1, -1, -1};
  planner::JointLimits limits;  ///< map, joint limits, Cartesian limits
};

/// The machine's transform, or nullopt when it has none (no trafo[] entry) or its parameters
/// do not build (the interpreter reports that at #TRAFO ON with the kinematic's id).
/// `config` is the machine's interpolator Config (machine_config()).
std::optional<MachineTrafo> machine_trafo(const machines::Machine& machine,
                                          const ipo::Config& config);

/// The inverse map of `kinematics` over an interpolated-axis vector: the Cartesian slots (at
/// `slots`: X, Y, Z [, A, B, C]) become the joints' values, every other axis passes unchanged.
/// Never throws.
planner::JointMap joint_map(std::shared_ptr<const machines::Kinematics> kinematics,
                            std::array<int, machines::kKinAxes> slots);

/// The forward map of `kinematics`, the mirror of joint_map(): the joints' values at `slots`
/// become the TCP's X, Y, Z [, A, B, C], every other axis passes unchanged; false where the
/// transform does not map. Never throws.
planner::JointMap forward_map(std::shared_ptr<const machines::Kinematics> kinematics,
                              std::array<int, machines::kKinAxes> slots);

}  // namespace ncsim::program
