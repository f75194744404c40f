#pragma once
// interp/cs_select: #CS selections applied to a machines::CsStack, and commands taken from the
// stack's frame into the MCS (docs/interp.md "Check mode", docs/ipo.md "Frames at the adapter").
//
// The interpreter decodes #CS DEF / ON / OFF / OFF ALL into an interp::SelectCs and applies it
// to its own stack; the adapter (program/program_frames.cpp) and `check` (check_semantics)
// follow the same selections on stacks of their own. apply_selection() is that one rule.

#include <optional>

#include "interp/command.hpp"
#include "machines/cs_stack.hpp"
#include "machines/frame.hpp"
#include "machines/machine.hpp"

namespace ncsim::interp {

/// Applies `sel` (its op, id and values) to `cs`; the stack's error, if any.
std::optional<machines::CsError> apply_selection(machines::CsStack& cs, const SelectCs& sel);

/// `c`, a motion or spline point programmed under the #CS chain whose frame (PCS -> MCS) is
/// `pcs_to_mcs` (frame PCS, no kinematics, not synchronised), with its X, Y, Z points in MCS:
/// what add_soft_limit_errors judges, so `check` applies the soft limits in MCS as `time` does
/// (issue 33). A rotated chain drops an arc's extent (its plane turns; the channel's monitor
/// NC5501 / NC5502 watches the arc) and keeps its target. nullopt: `c` is neither, or in
/// another frame.
std::optional<Command> command_in_mcs(const Command& c, const machines::Frame& pcs_to_mcs,
                                      const machines::Machine& machine);

}  // namespace ncsim::interp
