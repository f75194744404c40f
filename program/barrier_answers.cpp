#include "program/barrier_answers.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "core/tolerance.hpp"

namespace ncsim::program {

void BarrierAnswers::answer_from(scenario::VeStore* store, bool flush) {
  store_ = store;
  flush_ = flush;
  parts_.interp.record_ve_writes(store != nullptr);
}

std::optional<interp::Command> BarrierAnswers::next_command() {
  return store_ != nullptr || positions_ != nullptr || signals_ != nullptr
             ? parts_.interp.next()
             : parts_.interp.next_decode_only();
}

void BarrierAnswers::store_ve_writes() {
  if (store_ != nullptr)
    for (const auto& [name, value] : parts_.interp.take_ve_writes())
      store_->write(name, value);
}

void BarrierAnswers::note(const interp::CommandBody& body) noexcept {
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
  // G74: the homed axes stand wherever the channel left them (at P-AXIS-00152), so the next
  // position barrier wanting them is answered from the set positions (docs/homing.md).
  if (const auto* h = std::get_if<interp::Homing>(&body))
    for (const auto& [axis, order] : h->axes)
      indp_running_ |= interp::AxisMask{1} << axis;
}

bool BarrierAnswers::barrier(const interp::Barrier& body, std::uint32_t line, ipo::Item& out) {
  // P-CHAN-00451 implicit synchronisation (docs/ipo.md "Position barriers"): the block programs
  // again an axis whose INDP motion may still run.
  const interp::AxisMask sync = positions_ != nullptr && body.wants(interp::BarrierNeed::position)
                                    ? body.axes & indp_running_
                                    : 0;
  if (store_ == nullptr && positions_ == nullptr && signals_ == nullptr)
    return false;  // next_decode_only() answers
  if (signals_ != nullptr && body.wants(interp::BarrierNeed::signal) && body.signal &&
      signal_barrier(body, line, out))
    return true;
  if (sync != 0) {
    parts_.events.push(line, parts_.errors.file(), interp::WaitIndp{sync});
    open_ = body;  // answered at the next pull, with the path standing
    open_line_ = line;
    run_time_ = sync;
    out = parts_.events.wait(line);
    return true;
  }
  if (flush_ && body.wants(interp::BarrierNeed::external)) {
    open_ = body;  // the path stops first: answered at the next pull
    open_line_ = line;
    out = ipo::Dwell{0.0, line};
    return true;
  }
  answer(body, line);
  return false;
}

bool BarrierAnswers::signal_barrier(const interp::Barrier& body, std::uint32_t line,
                                    ipo::Item& out) {
  // Decoder level (docs/lines.md): the decoder reaches the #WAIT when this pull asks for it;
  // a signal already there is used at once and the path runs on. Else the decoder stops: the
  // blocks decoded before run to their end, the path stops there (a ChannelWait with a
  // SignalWait event) and the channel takes the signal when it comes; the block decodes after.
  // The decoder's look does not block the channel (its path still runs the blocks before).
  std::string order;
  signal_ = signals_->read(*body.signal, order);
  if (!order.empty()) parts_.errors.raise(line, "250002", order);
  if (!signal_ && body.signal->read) signal_ = interp::SignalAnswer{};  // #SIGNAL READ: none
  if (signal_) return false;
  parts_.events.push(line, parts_.errors.file(), *body.signal);
  open_ = body;  // answered at the next pull, with the signal the channel took
  open_line_ = line;
  out = parts_.events.wait(line);
  return true;
}

void BarrierAnswers::answer_open() {
  if (!open_) return;
  answer(*open_, open_line_);
  open_.reset();
}

void BarrierAnswers::answer(const interp::Barrier& barrier, std::uint32_t line) {
  interp::RunState state = parts_.interp.decode_only_state(barrier);
  if (store_ != nullptr && barrier.wants(interp::BarrierNeed::external))
    store_->answer(barrier.external, state.external);
  if (run_time_ != 0) answer_positions(barrier, line, state);
  if (signals_ != nullptr && barrier.wants(interp::BarrierNeed::signal)) {
    if (!signal_) signal_ = signals_->collect();  // taken by the channel's SignalWait event
    state.signal = signal_.value_or(interp::SignalAnswer{});
    state.signal_decode_only = false;
    signal_.reset();
  }
  parts_.interp.resume(state);
}

void BarrierAnswers::answer_positions(const interp::Barrier& barrier, std::uint32_t line,
                                      interp::RunState& state) {
  const machines::Machine& machine = parts_.machine;
  const AxisLayout& layout = parts_.layout;
  const interp::AxisMask axes = run_time_ & barrier.axes;
  run_time_ = 0;
  indp_running_ &= ~axes;
  if (positions_ == nullptr || axes == 0) return;
  const planner::AxisVec decoded = parts_.frames.to_mcs(barrier.frame, state.position, line);
  for (std::size_t m = 0; m < machine.axes.size() && m < interp::kMaxAxes; ++m) {
    if (((axes >> m) & 1u) == 0 || layout.slot[m] < 0) continue;
    const auto k = static_cast<std::size_t>(layout.slot[m]);
    const double set = (*positions_)[k];
    const double delta = set - decoded[k];
    if (std::fabs(delta) <= kRelTol * std::max(1.0, std::fabs(set))) continue;  // the target
    const bool xyz =
        std::find(layout.xyz.begin(), layout.xyz.end(), static_cast<int>(m)) != layout.xyz.end();
    if (barrier.frame.kinematics || barrier.frame.space == interp::Space::pcs1 ||
        (xyz && barrier.frame.space != interp::Space::mcs &&
         !parts_.frames.to_mcs(barrier.frame).rotation.isIdentity(0.0))) {
      parts_.errors.not_supported(line, "the position of axis " + machine.axes[m].name +
                                            " in frame " + interp::frame_name(barrier.frame) +
                                            " after its INDP motion ended away from the decoded "
                                            "target");
    }
    state.position[m] += delta;  // MCS and the frame differ by a shift on this axis
  }
}

}  // namespace ncsim::program
