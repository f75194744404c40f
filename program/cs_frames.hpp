#pragma once
// program/cs_frames: #CS frames at the adapter (docs/ipo.md "Frames at the adapter").
//
// Purpose: a motion programmed in PCS under a #CS chain (static frames) is planned in MCS. Its
// start, end and arc centre go through the chain's frame F (machines::CsStack, the
// interpreter's rules interp::apply_selection and the channel's rotation sequence
// P-CHAN-00394), applied to the X, Y, Z axis values; other axes pass unchanged. F is rigid, so a
// line stays a line; an arc stays an arc of the same radius in the rotated plane spanned by F's
// images of its two plane axes (planner::ArcPlane), turning the same way about the image of the
// third axis; the helix rise is rotated with it. Under #SYNC (PCS1) the points go through T0
// after the chain: the MCS point at belt travel 0; the channel adds the travel
// (tracking/conveyor_sync). Under #TRAFO ON the result is the Cartesian TCP in MCS (the
// transform acts below the #CS chain, as in the interpreter).
// Inputs: the #CS selections in program order, points and arcs with the frame they are in.
// Outputs: interpolated-axis values and planner arcs in MCS.
// Invariants: the adapter's stack follows the interpreter's (a disagreement is NC6001, never
// run); a point whose frame names another #CS depth than the stack's is NC6001.

#include <cstdint>

#include "interp/command.hpp"
#include "machines/cs_stack.hpp"
#include "machines/machine.hpp"
#include "planner/move.hpp"
#include "program/machine_axes.hpp"
#include "program/source_errors.hpp"

namespace ncsim::program {

class CsFrames {
 public:
  /// `machine`, `layout` and `errors` must outlive this.
  CsFrames(const machines::Machine& machine, const AxisLayout& layout, SourceErrors& errors);

  /// #CS DEF / ON / OFF / OFF ALL on the adapter's stack.
  void select(const interp::SelectCs& sel, std::uint32_t line);
  /// The active #CS chain's frame, PCS -> MCS (identity without a #CS).
  const machines::Frame& active() const noexcept { return active_; }
  /// The frame `frame` -> MCS: the #CS chain, then T0 under PCS1.
  machines::Frame to_mcs(const interp::CoordFrame& frame) const;
  /// Interpolated-axis values of machine values `p` given in `frame`, in MCS.
  planner::AxisVec to_mcs(const interp::CoordFrame& frame, const interp::AxisValues& p,
                          std::uint32_t line) const;
  /// Sets move.arc (and move.arc_plane under a rotated #CS) from the motion's arc, in MCS.
  void arc_to_mcs(const interp::Motion& m, std::uint32_t line, planner::Move& move) const;
  /// The catch-up / departure Motion after #SYNC IN / OUT as a channel event body: `end` holds
  /// the interpolated axes' values in MCS at belt travel 0 (interpolated order, frame MCS).
  interp::CommandBody sync_motion(const interp::CommandBody& motion, std::uint32_t line) const;

 private:
  const machines::Machine& machine_;
  const AxisLayout& layout_;
  SourceErrors& errors_;
  machines::CsStack cs_;
  machines::Frame active_;  ///< cs_.active_frame(): PCS -> MCS
};

}  // namespace ncsim::program
