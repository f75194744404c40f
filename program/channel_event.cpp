#include "program/channel_event.hpp"

#include <variant>

namespace ncsim::program {

bool is_channel_event(const interp::CommandBody& body) noexcept {
  if (const auto* s = std::get_if<interp::Signal>(&body)) return s->syn;  // #SIGNAL SYN
  return std::holds_alternative<interp::SignalWait>(body) ||              // #WAIT SYN
         std::holds_alternative<interp::Tech>(body) ||
         std::holds_alternative<interp::WaitIndp>(body) ||
         std::holds_alternative<interp::AxisCommand>(body) ||
         std::holds_alternative<interp::MoveVelocity>(body) ||
         std::holds_alternative<interp::ProbeArm>(body) ||
         std::holds_alternative<interp::SyncIn>(body) ||
         std::holds_alternative<interp::SyncOut>(body) ||
         std::holds_alternative<interp::Homing>(body) ||  // G74
         std::holds_alternative<interp::MachineData>(body);
}

bool stops_path(const interp::CommandBody& body) noexcept {
  if (const auto* a = std::get_if<interp::AxisCommand>(&body))
    return a->kind == interp::IndpKind::syn;
  return std::holds_alternative<interp::WaitIndp>(body) ||
         std::holds_alternative<interp::SyncIn>(body) ||
         std::holds_alternative<interp::SyncOut>(body) ||
         std::holds_alternative<interp::Homing>(body) ||      // G74
         std::holds_alternative<interp::SignalWait>(body) ||  // #WAIT SYN, a #WAIT not answered
         std::holds_alternative<interp::MachineData>(body);   // the path stops (§5.10)
}

}  // namespace ncsim::program
