#pragma once
// program/belt_split: the PCS1 velocity split at the adapter (issue 14; seed 004 l.311-319;
// docs/conveyor.md "Machining in PCS1: the velocity split").
//
// Purpose: while synchronised, every PCS1 block without kinematics is planned with the axes'
// velocity limits lowered by what the conveyor takes of them (planner::Move::belt,
// planner::belt_limits).
// Inputs: the commands as they pass the adapter (#SYNC IN's CONV_VEL, #SYNC OUT), the
// machine's T0 (P-CHAN-00371..00373: the conveying direction in MCS) and X/Y/Z axes.
// Outputs: belt(): per interpolated axis |share| x 1.10 x CONV_VEL [mm/s] from #SYNC IN to
// #SYNC OUT, 0 elsewhere; split(): a line's Move::belt, -|share| x CONV_VEL on the axes it
// moves against the belt.
// Invariants: never allocates; x_virtual (P-CHAN-00364) lowers nothing (no real X follows the
// belt: the static unit's matter, program/path_output).

#include "interp/command.hpp"
#include "machines/machine.hpp"
#include "planner/move.hpp"
#include "program/machine_axes.hpp"

namespace ncsim::program {

class BeltSplit {
 public:
  /// `machine` and `layout` must outlive this.
  BeltSplit(const machines::Machine& machine, const AxisLayout& layout) noexcept
      : machine_(machine), layout_(layout) {}

  /// Sets the split at #SYNC IN, clears it at #SYNC OUT; other commands pass.
  void on_command(const interp::CommandBody& body);
  /// The velocity the belt takes of each interpolated axis while synchronised [mm/s]
  /// (tracking::pcs1_belt of the last #SYNC IN's CONV_VEL; planner::Move::belt of PCS1 blocks).
  const planner::AxisVec& belt() const noexcept { return belt_; }
  /// A PCS1 line's Move::belt: belt() on axes it moves along the conveying direction,
  /// -|belt_dir| (v_max + CONV_VEL) on axes it moves against it.
  void split(planner::Move& move) const noexcept;

 private:
  const machines::Machine& machine_;
  const AxisLayout& layout_;
  planner::AxisVec belt_{};
  /// Per interpolated axis, the belt's velocity on it at CONV_VEL, signed (conveying component
  /// x CONV_VEL [mm/s]); 0 off the conveyor.
  planner::AxisVec belt_dir_{};
};

}  // namespace ncsim::program
