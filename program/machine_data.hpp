#pragma once
// program/machine_data: `#MACHINE DATA` at run time (isg-language.md §5.10; seed 004 §2.1.4).
//
// Purpose: the one place that says which parameters a program may change while ncsim runs it,
// and how such a change lands in the parameters. Seed 004 l.391: "while the conveyor axis is
// in operation, the filter parameters can be adapted using the #MACHINE DATA command" (and
// l.641: varied in an NC program to find the right filter values). ncsim runs exactly that:
// the conveyor axis's actual-value filters and delay time (P-AXIS-00620, NCSIM-AXIS-005/006,
// P-AXIS-00623..00626). Every other parameter is NC6001 `not supported` at its line (the
// planner's limits are fixed for a run), never ignored.
// Inputs: the decoded command (values in internal units, interp/interpreter_machine_data.cpp),
// the machine. Outputs: an explanation of what is not supported, or the changed parameters.
// Invariants: pure functions; nothing changes on a refused command.

#include <optional>
#include <string>

#include "interp/command.hpp"
#include "machines/machine.hpp"

namespace ncsim::program {

/// Why `command` cannot run on `machine` (the text after "not supported: "), or nullopt when
/// every setting is a filter or delay-time parameter of the conveyor axis.
std::optional<std::string> machine_data_unsupported(const interp::MachineData& command,
                                                    const machines::Machine& machine);

/// The conveyor axis's parameters `current` with `command`'s settings applied (call only when
/// machine_data_unsupported() gave nullopt).
machines::ConveyorAxisParams apply_machine_data(machines::ConveyorAxisParams current,
                                                const interp::MachineData& command);

}  // namespace ncsim::program
