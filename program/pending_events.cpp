#include "program/pending_events.hpp"

#include <utility>
#include <variant>

namespace ncsim::program {

void PendingEvents::push(std::uint32_t line, std::uint16_t file, interp::CommandBody body) {
  events_.push_back(ChannelEvent{++tag_, line, file, std::move(body)});
}

ipo::ChannelWait PendingEvents::wait(std::uint32_t line) noexcept {
  given_ = tag_;
  return ipo::ChannelWait{line, tag_};
}

bool PendingEvents::take(std::uint32_t up_to, ChannelEvent& out) {
  if (events_.empty() || events_.front().tag > up_to) return false;
  out = std::move(events_.front());
  events_.pop_front();
  return true;
}

bool PendingEvents::rides(const interp::CommandBody& body) const noexcept {
  return is_channel_event(body) && !stops_path(body) && !syn_wait_ &&
         tag_ + 1 - given_ < kMaxPendingEvents;
}

bool PendingEvents::close_syn(const interp::Command& cmd, std::uint16_t file, ipo::Item& out) {
  const auto* a = std::get_if<interp::AxisCommand>(&cmd.body);
  const bool same_block = cmd.line == syn_wait_->line && cmd.file == file &&
                          is_channel_event(cmd.body) && (!stops_path(cmd.body) || a != nullptr);
  if (same_block) return false;
  // An INTERRUPTIBLE block before the next synchronisation (docs/conveyor.md S-4).
  syn_wait_->interruptible =
      syn_interruptible_ && (std::holds_alternative<interp::ProbeArm>(cmd.body) ||
                             std::holds_alternative<interp::SyncIn>(cmd.body));
  out = *syn_wait_;
  given_ = syn_wait_->tag;
  syn_wait_.reset();
  return true;
}

bool PendingEvents::queue(interp::Command& cmd, ipo::Item& out) {
  const std::uint32_t line = cmd.line;
  const bool stops = stops_path(cmd.body);
  const bool syn = std::holds_alternative<interp::AxisCommand>(cmd.body) && stops;
  if (syn) {  // every INDP_SYN motion of the block INTERRUPTIBLE (docs/conveyor.md S-4)
    const bool interruptible = std::get<interp::AxisCommand>(cmd.body).interruptible;
    syn_interruptible_ = (syn_wait_ ? syn_interruptible_ : true) && interruptible;
  }
  push(line, cmd.file, std::move(cmd.body));
  if ((syn || syn_wait_) && tag_ - given_ < kMaxPendingEvents) {
    syn_wait_ = ipo::ChannelWait{line, tag_};  // the block's later events are due with it
    return false;
  }
  syn_wait_.reset();
  if (stops || tag_ - given_ >= kMaxPendingEvents) {
    out = wait(line);
    return true;
  }
  return false;
}

}  // namespace ncsim::program
