#pragma once
// program/trafo_path: #KIN ID / #TRAFO ON / OFF at the adapter (docs/ipo.md "Kinematics in run
// and time") and the belt's share of the joints in PCS1 (docs/conveyor.md "Machining in PCS1").
//
// Purpose: under #TRAFO ON the interpreter gives X, Y, Z as the Cartesian TCP (re-based at the
// switch by the kinematic's forward / inverse transform); the Moves carry Move::transformed and
// the planner limits them by the joints (planner::Preparer::set_joints). Here:
// - a switch of #TRAFO (ON after OFF or OFF after ON) hands out a 0 s Dwell first: the path
//   stops at the block end before the switch, the rest of that cycle is dropped, and the next
//   Move starts from the transformed position (decision: the kernel's axes and TCP views cannot
//   both be interpolated across one cycle; 0 s costs no time beyond the stop itself);
// - only the machine's first kinematic (trafo[0]) is wired into the channel: #TRAFO ON with
//   another #KIN ID is NC6001 `not supported`;
// - a transformed Move is sampled along its path (the planner's spacing, planner::kJointSpacing)
//   through the inverse transform: a point outside the workspace, beyond a drive limit or
//   singular is the kinematic's error (NC3201 / NC3202 / NC3204, machines/delta_kinematics.hpp,
//   machines/arm_kinematics.hpp) at the block's line, and so is a joint jumping across its
//   +-180 deg range end between two samples (NC3202), so the program stops at the last good
//   block with a positioned diagnostic;
// - a transformed Move in PCS1 gets the belt's share of the joints (reserve_belt_share), and so
//   does the tolerance ball between two such blocks (reserve_ball_share; program/ball_hold).
// Inputs: #KIN ID / #TRAFO commands, #SYNC IN's CONV_VEL, transformed Moves.
// Outputs: the switch's Dwell, the Moves' capped feeds and joint shares, NC3201 / NC3202 /
// NC6211 / NC6001 through SourceErrors.
// Invariants: the kinematic is built once, at the first #TRAFO ON.

#include <cstdint>
#include <optional>
#include <span>

#include "interp/command.hpp"
#include "ipo/interpolator.hpp"
#include "machines/machine.hpp"
#include "planner/move.hpp"
#include "planner/path.hpp"
#include "program/machine_axes.hpp"
#include "program/source_errors.hpp"
#include "program/trafo.hpp"
#include "tracking/trafo_sync.hpp"

namespace ncsim::program {

class TrafoPath {
 public:
  /// `machine`, `layout` and `errors` must outlive this; `t_cycle` [s] is the run's cycle.
  TrafoPath(const machines::Machine& machine, const AxisLayout& layout, SourceErrors& errors,
            double t_cycle) noexcept
      : machine_(machine), layout_(layout), errors_(errors), t_cycle_(t_cycle) {}

  /// #KIN ID / #TRAFO: at a switch of #TRAFO a 0 s Dwell goes out first (the path stands at
  /// the switch; true: `out` holds it); #TRAFO ON with another kinematic than the machine's
  /// first is NC6001.
  bool select(const interp::Kinematics& k, std::uint32_t line, ipo::Item& out);
  /// #SYNC IN's CONV_VEL, for the belt's share; other commands pass.
  void on_command(const interp::CommandBody& body) noexcept;
  /// A transformed Move whose path leaves the kinematic's workspace: the kinematic's error
  /// (NC3201 / NC3202) at its line.
  void check_workspace(const planner::Move& move, std::uint32_t line) const;
  /// A transformed G00 / G01 / G02 / G03 Move or spline piece in PCS1: the belt's share (1.1 x
  /// CONV_VEL, the 50653 margin) of the joints wherever the belt can carry the block (forward
  /// from the latch, inside the conveyor workspace): its F capped for the joints' V (and by the
  /// acceleration and jerk shares' bisection; a G00's of its joints' rapid limits, the cap in
  /// Move::feed for planner::path_limits), the a and j shares in Move::belt_joints
  /// (tracking::belt_share); NC6211 when the belt alone needs a joint's V or its share with the
  /// path at rest leaves a joint less than 1 % of its A or J.
  void reserve_belt_share(planner::Move& move) const;
  /// A transformed G01 / G02 / G03 Move in PCS1 (`pcs1`) that ends in a contoured corner: its
  /// ball needs the belt's share too.
  bool holds_for_ball(const planner::Move& move, bool pcs1) const;
  /// The ball between `in` and `out` (planner::corner_blend, DEV or DIST): its belt share
  /// (tracking::belt_share at the slower feed of the two) raises in's acceleration and jerk shares
  /// where larger and caps in's feed where lower (the planner runs the ball with in's limits).
  void reserve_ball_share(planner::Move& in, const planner::Move& out) const;

 private:
  /// The belt's carry for belt_share (1.1 x CONV_VEL, the conveying direction, the conveyor
  /// workspace); false without a kinematic, a conveyor or a CONV_VEL.
  bool belt_carry(tracking::BeltCarry& carry) const;
  /// tracking::belt_share of `path` at `feed` under the carry with the joints' limits `joints`; an
  /// overload is NC6211 at block `at` (its line and file).
  tracking::BeltShare belt_share_at(const planner::Segment& path, double feed,
                                    const planner::Move& at,
                                    std::span<const planner::AxisLimits> joints) const;

  const machines::Machine& machine_;
  const AxisLayout& layout_;
  SourceErrors& errors_;
  double t_cycle_;                     ///< the run's interpolation cycle [s]
  std::optional<MachineTrafo> trafo_;  ///< the machine's kinematic, built at the first #TRAFO
  bool trafo_on_ = false;              ///< #TRAFO ON as handed out
  double belt_conv_vel_ = 0.0;         ///< CONV_VEL of the last #SYNC IN [mm/s]
};

}  // namespace ncsim::program
