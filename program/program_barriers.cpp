// program/program_barriers: position barriers answered from run time (ProgramSource, see
// program/program_source.hpp and docs/ipo.md "Position barriers").
//
// Purpose: after an INDP_ASYN motion the interpreter does not know where the
// axis is; a block that programs the axis again passes a position Barrier for it. The source
// then stops the path, waits for the axis's INDP motion (a #WAIT INDP of those axes, the
// kernel's implicit synchronisation P-CHAN-00451) and answers with the set position the channel
// reports, so the block starts where the axis stands, not where the decoder assumed it.
// Inputs: the barrier, the decode-only state, the channel's set positions (MCS, interpolated
// order). Outputs: the state's positions of the waited-for axes in the barrier's frame.
// Invariants: an axis whose set position equals the decode-time value (within 1e-9 relative)
// keeps the decode-time value bit for bit; a difference that cannot be carried into the frame
// (a rotated #CS on X/Y/Z, PCS1, #TRAFO ON) is `not supported` (NC6001), never ignored.

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "program/program_source.hpp"

namespace ncsim::ipo {

void ProgramSource::note_indp(const interp::CommandBody& body) noexcept {
  if (const auto* a = std::get_if<interp::AxisCommand>(&body)) {
    const interp::AxisMask bit = interp::AxisMask{1} << a->axis;
    if (a->kind == interp::IndpKind::asyn)
      indp_running_ |= bit;
    else  // INDP_SYN: the next block waits until the axis is in position, at its target
      indp_running_ &= ~bit;
  } else if (const auto* w = std::get_if<interp::WaitIndp>(&body)) {
    // #WAIT INDP: the command values reach their targets (isg-language.md 6.1), where the
    // decoder has them: nothing left to wait for.
    indp_running_ &= w->axes == 0 ? interp::AxisMask{0} : ~w->axes;
  }
}

void ProgramSource::answer_positions(const interp::Barrier& barrier, interp::RunState& state) {
  const interp::AxisMask axes = run_time_ & barrier.axes;
  run_time_ = 0;
  indp_running_ &= ~axes;
  if (positions_ == nullptr || axes == 0) return;
  const planner::AxisVec decoded = to_mcs(barrier.frame, state.position, line_);
  for (std::size_t m = 0; m < machine_.axes.size() && m < interp::kMaxAxes; ++m) {
    if (((axes >> m) & 1u) == 0 || slot_[m] < 0) continue;
    const auto k = static_cast<std::size_t>(slot_[m]);
    const double set = (*positions_)[k];
    const double delta = set - decoded[k];
    if (std::fabs(delta) <= 1e-9 * std::max(1.0, std::fabs(set))) continue;  // the target
    const bool xyz = std::find(xyz_.begin(), xyz_.end(), static_cast<int>(m)) != xyz_.end();
    if (barrier.frame.kinematics || barrier.frame.space == interp::Space::pcs1 ||
        (xyz && barrier.frame.space != interp::Space::mcs &&
         !frame_to_mcs(barrier.frame).rotation.isIdentity(0.0))) {
      fail(line_, "the position of axis " + machine_.axes[m].name + " in frame " +
                      interp::frame_name(barrier.frame) +
                      " after its INDP motion ended away from the decoded target");
    }
    state.position[m] += delta;  // MCS and the frame differ by a shift on this axis
  }
}

}  // namespace ncsim::ipo
