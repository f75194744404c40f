#pragma once
// channel/homing: G74 in the channel (docs/homing.md).
//
// Purpose: "the axis adopts the reference position P-AXIS-00152 (pos_refpkt) from the axis
// parameter list and stops" (ISG homing manual, "Commanding and execution"); the numbers after
// the axes give the order, equal numbers home together (isg-language.md l.148).
// What ncsim simulates (decision, docs/homing.md): the simulated axes have no cam and no zero
// pulse and their position is known from the start, so homing is a PTP motion of each axis
// from where it stands to P-AXIS-00152 at P-AXIS-00219 (vb_refmax, the homing travel's
// velocity; capped at P-AXIS-00212) with the axis's G01 slope (A+, A-, J), run by the INDP layer
// (channel/indp_axes.hpp); the group of the lowest order first, the next when every axis of the
// group is in position. The axis is then homed at exactly P-AXIS-00152 (a real axis stops
// beyond it by its braking distance: ncsim does not model the latch).
// Inputs: the G74 event (machine axes with order numbers), the channel's axes. Outputs: INDP
// motions; EventOutcome blocking until the last group is in position (the path stands, the
// cycles are counted on the G74 line). Errors: NC6001 for an axis that is not a channel axis;
// the INDP layer's NC5501 / NC5502 (P-AXIS-00152 beyond a soft limit) and NC6104.
// The interpreter has refused G74 with a coupling (20137), of the conveyor / an encoder axis
// (NC9104), of a spindle (NC9105) and bad order numbers (NC9106) before.
// Invariants: noexcept; no allocation per cycle (the event's axis list is the program's).

#include <optional>

#include "channel/axis_stage.hpp"
#include "channel/event_context.hpp"
#include "channel/indp_axes.hpp"
#include "interp/command.hpp"

namespace ncsim::channel {

class HomingSequence {
 public:
  /// One dispatch of the G74 event: starts the next group's motions on `indp` when the group
  /// running is in position; EventOutcome::done after the last group.
  EventOutcome step(const interp::Homing& command, const AxisStage& axes, IndpAxes& indp,
                    const EventContext& ctx) noexcept;

 private:
  std::optional<int> order_;  ///< the order number homing now; empty: none started
};

}  // namespace ncsim::channel
