#include "program/program_source.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "core/number_text.hpp"
#include "program/machine_data.hpp"

namespace ncsim::program {
namespace {

SourceConfig checked(const SourceConfig& config) {
  if (!(config.t_cycle > 0.0) || !std::isfinite(config.t_cycle))
    throw std::invalid_argument("program::ProgramSource: cycle must be > 0 s, got " +
                                core::human(config.t_cycle));
  return config;
}

}  // namespace

ProgramSource::ProgramSource(interp::Interpreter& interp, const machines::Machine& machine,
                             SourceConfig config)
    : interp_(interp),
      machine_(machine),
      config_(checked(config)),
      errors_(interp),
      layout_(machine),
      frames_(machine, layout_, errors_),
      belt_(machine, layout_),
      trafo_(machine, layout_, errors_, config_.t_cycle),
      moves_(MoveParts{machine, layout_, errors_, frames_, trafo_, belt_},
             config_.refuse_soft_limits),
      output_(machine, layout_, errors_, config_.t_cycle),
      ball_(trafo_, output_),
      spline_(layout_, errors_, frames_, moves_, output_),
      answers_(BarrierParts{interp, machine, layout_, errors_, frames_, events_}) {}

bool ProgramSource::next(ipo::Item& out) {
  if (errors_.error() != nullptr) return false;
  try {
    if (!pull(out)) return false;
    // Every item names the file of its line. Items other than queued ones and Moves go out
    // before the next command is pulled (the INDP_SYN wait leaves before the command after it is
    // taken), so errors_.file() is theirs. Moves and queued items carry their own (MoveBuilder,
    // SplineSection, PathOutput): a block held for its tolerance ball goes out after the next
    // command was read, maybe in another file. A Dwell or a ChannelWait stops the path: the
    // static unit's last part meets no next part there (PathOutput's joint check).
    if (!std::holds_alternative<planner::Move>(out)) output_.path_stopped();
    if (!out_queued_)
      std::visit(
          [this](auto& item) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(item)>, planner::Move>)
              item.file = errors_.file();
          },
          out);
    return true;
  } catch (const SourceErrors::Stop&) {
    return false;  // the error is set: the stream ends after the blocks before the faulty one
  }
}

bool ProgramSource::pull(ipo::Item& out) {
  out_queued_ = false;
  if (end_reached_) return false;
  for (;;) {
    if (output_.pop(out)) {  // queued items first: they come before the next command
      out_queued_ = true;
      return true;
    }
    errors_.raise_deferred();  // the error after the held block (release_held)
    // Barriers: the decode-only state (docs/ipo.md), or the scenario's V.E. store. After the
    // stop before a barrier every block before it ran: it is answered now.
    answers_.answer_open();
    std::optional<interp::Command> cmd = take_command();
    const Pulled held = release_held(cmd, out);
    if (held == Pulled::item) return true;
    if (held == Pulled::again) continue;
    if (!cmd) {
      if (const core::Diagnostic* e = interp_.error()) errors_.adopt(*e);
      return false;
    }
    if (events_.syn_open() && events_.close_syn(*cmd, errors_.file(), out)) {
      held_ = std::move(cmd);  // taken again at the next pull
      return true;
    }
    errors_.enter(cmd->file);
    const Pulled p = is_channel_event(cmd->body) || sync_motion_ ? route_event(*cmd, out)
                                                                 : run_command(*cmd, out);
    if (p == Pulled::item) return true;
    if (p == Pulled::end) return false;
  }
}

std::optional<interp::Command> ProgramSource::take_command() {
  std::optional<interp::Command> cmd;
  if (held_) {  // the command after a block's INDP_SYN commands, or after a held block
    cmd = std::move(held_);
    held_.reset();
  } else {
    cmd = answers_.next_command();
  }
  answers_.store_ve_writes();
  return cmd;
}

bool ProgramSource::rides_along(const interp::Command& cmd) const noexcept {
  // An event riding on the next block that will not fill the event queue, a message, M00 / M01.
  return events_.rides(cmd.body) || std::holds_alternative<interp::Message>(cmd.body) ||
         std::holds_alternative<interp::ProgramStop>(cmd.body);
}

ProgramSource::Pulled ProgramSource::release_held(std::optional<interp::Command>& cmd,
                                                  ipo::Item& out) {
  // The static unit's part held for its tolerance ball goes out before anything that is not
  // the next path block (PathOutput); that command is taken again at the next pull. Commands
  // that emit nothing and do not stop the path keep it held (rides_along, and #CAXTRACK: the
  // held part is tracked already).
  if (output_.holds_part()) {
    const bool passes =
        cmd && (rides_along(*cmd) || std::holds_alternative<interp::CaxTrack>(cmd->body));
    if (!passes && (!cmd || !std::holds_alternative<interp::Motion>(cmd->body))) {
      if (cmd) held_ = std::move(cmd);
      // Its joint with the next part is checked (joint_belt_check) unless the path stops
      // between them (next() forgets it at a Dwell or a ChannelWait).
      out = output_.release_part();
      return Pulled::item;
    }
  }
  // A PCS1 block held for its ball's share goes out before any other command than the next
  // Motion (that command is taken again at the next pull). Commands that emit nothing and do
  // not stop the path keep it held, as the static unit's part above: the planner blends across
  // them, so the ball still needs its share (rides_along, #FLUSH CONTINUE; a plain #FLUSH stops
  // the path, docs/ipo.md).
  if (ball_.holds()) {
    const auto* flush = std::get_if<interp::Flush>(cmd ? &cmd->body : nullptr);
    const bool passes =
        cmd && (std::holds_alternative<interp::Motion>(cmd->body) || rides_along(*cmd) ||
                (flush && flush->kind == interp::FlushKind::continue_));
    if (!passes) {
      if (cmd) held_ = std::move(cmd);
      ball_.release(nullptr);
      return Pulled::again;
    }
  }
  return Pulled::none;
}

ProgramSource::Pulled ProgramSource::route_event(interp::Command& cmd, ipo::Item& out) {
  const std::uint32_t line = cmd.line;
  // The first motion after #SYNC IN / #SYNC OUT is the catch-up / departure, a PTP motion the
  // channel runs while the path stands (tracking/conveyor_sync).
  if (sync_motion_ && std::holds_alternative<interp::Motion>(cmd.body)) {
    sync_motion_ = false;
    events_.push(line, cmd.file, frames_.sync_motion(cmd.body, line));
    out = events_.wait(line);
    return Pulled::item;
  }
  if (!is_channel_event(cmd.body)) return run_command(cmd, out);
  if (std::holds_alternative<interp::SyncIn>(cmd.body) ||
      std::holds_alternative<interp::SyncOut>(cmd.body)) {
    sync_motion_ = true;
    output_.on_command(cmd.body);  // the static unit's belt feed
  }
  belt_.on_command(cmd.body);   // the PCS1 velocity split
  trafo_.on_command(cmd.body);  // the belt's share under #TRAFO ON
  if (const auto* md = std::get_if<interp::MachineData>(&cmd.body))
    if (std::optional<std::string> why = machine_data_unsupported(*md, machine_))
      errors_.not_supported(line, *why);
  answers_.note(cmd.body);  // INDP_ASYN and homed axes are answered at run time
  return events_.queue(cmd, out) ? Pulled::item : Pulled::again;
}

void ProgramSource::motion(const interp::Motion& body, std::uint32_t line) {
  planner::Move mv;
  try {
    mv = moves_.to_move(body, line);
  } catch (const SourceErrors::Stop&) {
    if (!ball_.holds()) throw;
    // The held block runs to its end before the error stops the stream, as every block before
    // a faulty one does.
    errors_.defer();
    ball_.release(nullptr);
    return;
  }
  mv.event_tag = events_.give();
  ball_.release(&mv);  // the ball's share, then the held block out
  ball_.offer(std::move(mv), body.frame.space == interp::Space::pcs1);
}

ProgramSource::Pulled ProgramSource::run_command(interp::Command& cmd, ipo::Item& out) {
  const std::uint32_t line = cmd.line;
  bool produced = false;
  bool ended = false;
  std::visit(
      [&](const auto& body) {
        using T = std::decay_t<decltype(body)>;
        if constexpr (std::is_same_v<T, interp::Motion>) {
          motion(body, line);
        } else if constexpr (std::is_same_v<T, interp::Dwell>) {
          output_.check_stop(line,
                             body.tech ? "a technology function's acknowledgement" : "a dwell");
          out = ipo::Dwell{body.seconds, line, events_.give(), 0, body.tech, body.since_output};
          produced = true;
        } else if constexpr (std::is_same_v<T, interp::End>) {
          ended = true;
          if (body.endless) ended_endless_ = interp_.endless_from();
        } else if constexpr (std::is_same_v<T, interp::Message> ||
                             std::is_same_v<T, interp::ProgramStop>) {
          // pass: no motion (M00/M01 do not stop: there is no operator to press start)
        } else if constexpr (std::is_same_v<T, interp::Flush>) {
          // isg-language.md 5.1 [C]: #FLUSH empties the channel buffer, the path stops at the
          // end of the last motion block (the events before it done); #FLUSH WAIT lets the
          // decoder wait until the buffer ran empty: a stop too. #FLUSH CONTINUE does not stop
          // when the next motion block is already there, as it always is here.
          if (body.kind != interp::FlushKind::continue_) {
            output_.check_stop(line, "#FLUSH");
            out = events_.wait(line);
            produced = true;
          }
        } else if constexpr (std::is_same_v<T, interp::Barrier>) {
          produced = answers_.barrier(body, line, out);
        } else if constexpr (std::is_same_v<T, interp::SelectCs>) {
          frames_.select(body, line);
        } else if constexpr (std::is_same_v<T, interp::Kinematics>) {
          produced = trafo_.select(body, line, out);  // a switch of #TRAFO stops the path
        } else if constexpr (std::is_same_v<T, interp::CaxTrack>) {
          output_.caxtrack(body, line);
        } else if constexpr (std::is_same_v<T, interp::SplineBegin>) {
          spline_.begin(body, line);
        } else if constexpr (std::is_same_v<T, interp::SplinePoint>) {
          spline_.point(body, line);
        } else if constexpr (std::is_same_v<T, interp::SplineEnd>) {
          spline_.end(line);
        } else if constexpr (std::is_same_v<T, interp::Tech> ||
                             std::is_same_v<T, interp::WaitIndp> ||
                             std::is_same_v<T, interp::AxisCommand> ||
                             std::is_same_v<T, interp::MoveVelocity> ||
                             std::is_same_v<T, interp::ProbeArm> ||
                             std::is_same_v<T, interp::SyncIn> ||
                             std::is_same_v<T, interp::SyncOut> ||
                             std::is_same_v<T, interp::Homing> ||
                             std::is_same_v<T, interp::SignalWait> ||
                             std::is_same_v<T, interp::MachineData>) {
          // channel events: queued by route_event (is_channel_event), never here
        } else if constexpr (std::is_same_v<T, interp::Signal>) {
          // #SIGNAL at decoder level: sent when the decoder reaches it (docs/lines.md); #SIGNAL
          // SYN is a channel event.
          if (signals_ == nullptr) errors_.not_supported(line, "#SIGNAL outside a run");
          signals_->send(body);
        } else if constexpr (std::is_same_v<T, interp::SetPosition>) {
          errors_.not_supported(line, "G92 set position");
        } else {
          static_assert(!sizeof(T*), "every command kind is handled");
        }
      },
      cmd.body);
  if (ended) {
    if (events_.all_given()) return Pulled::end;
    // Events after the last motion: the channel executes them before the program ends.
    end_reached_ = true;
    out = events_.wait(line);
    return Pulled::item;
  }
  return produced ? Pulled::item : Pulled::again;
}

}  // namespace ncsim::program
