#include "program/program_source.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "interp/cs_select.hpp"
#include "interp/trace.hpp"
#include "program/machine_data.hpp"

namespace ncsim::ipo {
namespace {

using machines::AxisKind;

planner::Transition to_planner(interp::Transition t) {
  switch (t) {
    case interp::Transition::accelerate_at_start:
      return planner::Transition::accelerate_at_start;
    case interp::Transition::stop_at_end:
      return planner::Transition::stop_at_end;
    case interp::Transition::decel_at_end:
      return planner::Transition::decel_at_end;
    case interp::Transition::decel_after_end:
      return planner::Transition::decel_after_end;
  }
  return planner::Transition::accelerate_at_start;
}

planner::SlopeType to_planner(interp::SlopeType s) {
  switch (s) {
    case interp::SlopeType::step:
      return planner::SlopeType::step;
    case interp::SlopeType::trapez:
      return planner::SlopeType::trapez;
    case interp::SlopeType::sin2:
      return planner::SlopeType::sin2;
    case interp::SlopeType::hsc:
      return planner::SlopeType::hsc;
  }
  return planner::SlopeType::step;
}

const char* contour_name(interp::ContourKind k) {
  switch (k) {
    case interp::ContourKind::dev:
      return "DEV";
    case interp::ContourKind::dist:
      return "DIST";
    case interp::ContourKind::dist_soft:
      return "DIST_SOFT";
    case interp::ContourKind::dist_master:
      return "DIST_MASTER";
    case interp::ContourKind::pos:
      return "POS";
    case interp::ContourKind::ptp:
      return "PTP";
  }
  return "?";
}

}  // namespace

std::vector<std::uint8_t> interpolated_axes(const machines::Machine& machine) {
  std::vector<std::uint8_t> out;
  const machines::AxisParams* conveyor = machine.conveyor_axis();
  for (std::size_t i = 0; i < machine.axes.size(); ++i) {
    const machines::AxisParams& a = machine.axes[i];
    if (a.kind == AxisKind::spindle || a.encoder_only || &a == conveyor) continue;
    out.push_back(static_cast<std::uint8_t>(i));
  }
  return out;
}

Config machine_config(const machines::Machine& machine, double t_cycle) {
  Config c;
  for (const std::uint8_t i : interpolated_axes(machine)) {
    const machines::Dynamics& d = machine.axes[i].dynamics;
    planner::AxisLimits l;
    l.v_max = d.v_max;                          // P-AXIS-00212
    l.v_reference = d.v_max;                    // ISG has no reference-velocity key
    l.v_rapid = d.v_rapid;                      // P-AXIS-00209
    l.a_max = std::min(d.acc_feed, d.acc_max);  // P-AXIS-00001 capped by P-AXIS-00008
    l.d_max = std::min(d.dec_feed, d.acc_max);  // P-AXIS-00002 capped by P-AXIS-00008
    l.j_max = d.jerk_feed();
    l.c0 = d.velo_jump_factor;  // NCSIM-AXIS-020
    // G00 slope: P-AXIS-00004 capped by P-AXIS-00008; jerk P-AXIS-00004 / P-AXIS-00200.
    l.a_rapid = std::min(d.acc_rapid, d.acc_max);
    l.j_rapid = d.ramp_rapid > 0.0 ? d.jerk_rapid() : 0.0;
    c.axes.push_back(l);
    const machines::Monitoring& m = machine.axes[i].monitoring;
    c.exact_stop.push_back({m.exact_stop_window, m.settling_time.value_or(0.0)});
  }
  c.channel.t_cycle = t_cycle;
  if (machine.channel.conveyor)  // --- conveyor: NCSIM-CHAN-640
    c.channel.belt_reserve = machine.channel.conveyor->dynamics_reserve;
  // P-CHAN-00009 corr_v_trans_jerk: the C1 rule on or off (docs/planner.md "Corners").
  c.channel.limit_c1_by_jerk = machine.channel.corr_v_trans_jerk;
  c.window = static_cast<std::size_t>(machine.channel.interpolator.look_ahead_blocks);
  switch (machine.channel.path_override_type) {  // NCSIM-CHAN-630 (000 §7.5.6)
    case machines::PathOverrideType::reduced:
      c.override_type = OverrideType::reduced;
      break;
    case machines::PathOverrideType::original:
      c.override_type = OverrideType::original;
      break;
    case machines::PathOverrideType::reduced_above_100:
      c.override_type = OverrideType::reduced_above_100;
      break;
  }
  return c;
}

ProgramSource::ProgramSource(interp::Interpreter& interp, const machines::Machine& machine,
                             double t_cycle)
    : interp_(interp),
      machine_(machine),
      t_cycle_(t_cycle),
      axes_(interpolated_axes(machine)),
      slot_(machine.axes.size(), -1),
      cs_(machine.channel.cs_rotation_sequence) {
  if (!(t_cycle > 0.0) || !std::isfinite(t_cycle))
    throw std::invalid_argument("ipo::ProgramSource: cycle must be > 0 s, got " +
                                std::to_string(t_cycle));
  if (axes_.empty() || axes_.size() > planner::kMaxAxes) {
    throw std::invalid_argument(
        "machine '" + machine.name + "' has " + std::to_string(axes_.size()) +
        " interpolated axes; the path interpolator needs 1.." + std::to_string(planner::kMaxAxes));
  }
  for (std::size_t k = 0; k < axes_.size(); ++k) {
    slot_[axes_[k]] = static_cast<int>(k);
    if (machine.axes[axes_[k]].kind == AxisKind::linear) path_axes_ |= planner::AxisMask{1} << k;
  }
  if (path_axes_ == 0) path_axes_ = (planner::AxisMask{1} << axes_.size()) - 1;
  const char* names[3] = {"X", "Y", "Z"};
  for (std::size_t k = 0; k < 3; ++k) {
    const machines::AxisParams* a = machine.find_axis(names[k]);
    if (a != nullptr) xyz_[k] = static_cast<int>(a - machine.axes.data());
  }
}

void ProgramSource::fail(std::uint32_t line, const std::string& what) {
  fail_in(file_, line, kNotSupportedId, "not supported: " + what);
}

void ProgramSource::fail_in(std::uint16_t file, std::uint32_t line, const std::string& id,
                            const std::string& what) {
  core::Diagnostic d;
  d.file = interp_.file_name(file);
  d.loc = {line, 1};
  d.id = id;
  d.message = what;
  error_ = d;
  throw Stop{};
}

void ProgramSource::check_soft_limits(const interp::Command& c) {
  core::DiagnosticList limits;
  interp::add_soft_limit_errors(c, machine_, interp_.file_name(c.file), limits);
  if (!limits.items().empty()) {
    const core::Diagnostic& d = limits.items().front();
    fail_in(c.file, c.line, d.id, d.message);
  }
}

std::shared_ptr<const planner::AxisWeights> axis_weights(const interp::DynamicsWeights& w,
                                                         std::span<const std::uint8_t> axes,
                                                         bool rapid) {
  planner::AxisWeights out;
  bool any = false;
  for (std::size_t k = 0; k < axes.size() && k < planner::kMaxAxes; ++k) {
    const std::uint8_t m = axes[k];
    out.v[k] = rapid ? w.v_rapid : w.v_feed[m];
    out.a[k] = rapid ? w.a_rapid[m] : w.a_feed[m];
    out.j[k] = out.a[k] / (rapid ? w.ramp_rapid : w.ramp_feed[m]);
    any = any || out.v[k] != 1.0 || out.a[k] != 1.0 || out.j[k] != 1.0;
  }
  return any ? std::make_shared<const planner::AxisWeights>(out) : nullptr;
}

planner::Move ProgramSource::to_move(const interp::Motion& m, std::uint32_t line) {
  // --- issue 34 item 22: check's NC4601, refused here before the block moves (one rule)
  if (refuse_soft_limits_ && m.frame == interp::CoordFrame{}) {
    check_soft_limits(interp::Command{line, file_, m});
  } else if (refuse_soft_limits_) {  // under a #CS chain: in MCS, as check does (issue 33)
    if (const auto in_mcs =
            interp::command_in_mcs(interp::Command{line, file_, m}, cs_frame_, machine_))
      check_soft_limits(*in_mcs);
  }
  for (std::size_t i = 0; i < machine_.axes.size(); ++i) {
    if (slot_[i] < 0 && (((m.programmed >> i) & 1u) != 0 || m.end[i] != m.start[i])) {
      fail(line, "motion of axis " + machine_.axes[i].name +
                     " (spindle / conveyor axes are not path-interpolated)");
    }
  }
  planner::Move mv;
  mv.axis_count = static_cast<std::uint8_t>(axes_.size());
  mv.path_axes = path_axes_;
  mv.start = to_mcs(m.frame, m.start, line);
  mv.end = to_mcs(m.frame, m.end, line);
  mv.rapid = m.kind == interp::MotionKind::rapid;
  mv.feed = m.feed;
  mv.block_time = m.block_time;
  mv.end_feed = m.end_feed;
  if (m.arc) arc_to_mcs(m, line, mv);
  set_modal(m.modal, mv, line);
  mv.line = line;
  mv.file = file_;  // a block held for its ball goes out after later commands: it keeps its own
  if (mv.transformed) check_workspace(mv, line);  // --- trafo
  if (m.frame.space == interp::Space::pcs1) {
    // The belt's share: under #TRAFO ON reserved on the joints (trafo), else the PCS1
    // velocity split on the axes (sync-feed, docs/conveyor.md S-5).
    if (mv.transformed)
      reserve_belt_share(mv);
    else if (mv.arc || mv.spline)
      mv.belt = belt_;  // --- belt-split: their tangent turns: the symmetric limit both ways
    else
      split_belt(mv);  // --- belt-split
  }
  return mv;
}

void ProgramSource::set_modal(const interp::ModalSnapshot& s, planner::Move& mv,
                              std::uint32_t line) {
  mv.transition = to_planner(s.transition);
  mv.exact_stop = s.exact_stop;
  if (s.contouring) {
    switch (s.contour.kind) {
      case interp::ContourKind::dev:
        mv.contour = planner::Contour::tolerance;
        mv.path_dev = s.contour.path_dev;
        break;
      case interp::ContourKind::dist:  // isg-language.md §5.3 (PROG-475180811)
        mv.contour = planner::Contour::distance;
        mv.pre_dist = s.contour.pre_dist;
        mv.post_dist = s.contour.post_dist;
        break;
      default:
        fail(line, std::string("#CONTOUR MODE ") + contour_name(s.contour.kind) +
                       " (only DEV and DIST are interpolated)");
    }
  }
  mv.transvelmin = s.transvelmin;
  mv.slope = to_planner(s.slope);
  if (s.weights != weights_src_) {  // G127..G233: converted once per change (program_source.hpp)
    weights_src_ = s.weights;
    weights_feed_ = s.weights ? axis_weights(*s.weights, axes_, false) : nullptr;
    weights_rapid_ = s.weights ? axis_weights(*s.weights, axes_, true) : nullptr;
  }
  mv.weights = mv.rapid ? weights_rapid_ : weights_feed_;
  mv.transformed = s.kinematics_on;  // --- trafo: X, Y, Z are the TCP (program_kinematics.cpp)
}

bool ProgramSource::next(Item& out) {
  if (error_) return false;
  try {
    if (!pull(out)) return false;
    // --- planner: every item names the file of its line. Items other than queued ones and
    // Moves go out before the next command is pulled (the INDP_SYN wait leaves before the
    // command after it is taken), so file_ is theirs. --- conveyor-tail: Moves and queued items
    // carry their own (to_move, queue_pieces, emit_path): a block held for its tolerance ball
    // (ball_held_, xv_held_) goes out after the next command was read, maybe in another file.
    // --- conveyor-tail: a Dwell or a ChannelWait stops the path: the static unit's last part
    // meets no next part there (emit_path's joint check).
    if (!std::holds_alternative<planner::Move>(out)) xv_last_.reset();
    if (!out_queued_)
      std::visit(
          [this](auto& item) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(item)>, planner::Move>)
              item.file = file_;
          },
          out);
    return true;
  } catch (const Stop&) {
    return false;  // error_ is set: the stream ends after the blocks before the faulty one
  }
}

void ProgramSource::answer(const interp::Barrier& barrier) {
  interp::RunState state = interp_.decode_only_state(barrier);
  if (store_ != nullptr && barrier.wants(interp::BarrierNeed::external))
    store_->answer(barrier.external, state.external);
  if (run_time_ != 0) answer_positions(barrier, state);  // --- planner
  interp_.resume(state);
}

bool ProgramSource::take_event(std::uint32_t up_to, ChannelEvent& out) {
  if (events_.empty() || events_.front().tag > up_to) return false;
  out = std::move(events_.front());
  events_.pop_front();
  return true;
}

bool ProgramSource::pull(Item& out) {
  out_queued_ = false;
  if (end_reached_) return false;
  for (;;) {
    if (!queue_.empty()) {  // queued items first: they come before the next command
      out = std::move(queue_.front());
      queue_.pop_front();
      out_queued_ = true;
      return true;
    }
    if (held_error_) {  // the error after the held block (release_held)
      error_ = std::move(held_error_);
      held_error_.reset();
      throw Stop{};
    }
    // Barriers: the decode-only state (docs/ipo.md), or the scenario's V.E. store.
    if (open_) {  // the flush's Dwell has passed: every block before the barrier ran
      answer(*open_);
      open_.reset();
    }
    std::optional<interp::Command> cmd = take_command();
    const Pulled held = release_held(cmd, out);
    if (held == Pulled::item) return true;
    if (held == Pulled::again) continue;
    if (!cmd) {
      if (const core::Diagnostic* e = interp_.error()) error_ = *e;
      return false;
    }
    if (syn_wait_ && close_syn_wait(cmd, out)) return true;
    line_ = cmd->line;
    file_ = cmd->file;
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
    cmd = store_ != nullptr || positions_ != nullptr ? interp_.next() : interp_.next_decode_only();
  }
  // The program's V.E. assignments decoded so far reach the shared store before any barrier
  // after them is answered.
  if (store_ != nullptr)
    for (const auto& [name, value] : interp_.take_ve_writes())
      store_->write(name, value);
  return cmd;
}

bool ProgramSource::rides_along(const interp::Command& cmd) const noexcept {
  // An event riding on the next block that will not fill the event queue, a message, M00 / M01.
  return (is_channel_event(cmd.body) && !stops_path(cmd.body) && !syn_wait_ &&
          tag_ + 1 - given_ < kMaxPendingEvents) ||
         std::holds_alternative<interp::Message>(cmd.body) ||
         std::holds_alternative<interp::ProgramStop>(cmd.body);
}

ProgramSource::Pulled ProgramSource::release_held(std::optional<interp::Command>& cmd, Item& out) {
  // The static unit's part held for its tolerance ball goes out before anything that is not
  // the next path block (program_static.cpp); that command is taken again at the next pull.
  // Commands that emit nothing and do not stop the path keep it held (rides_along, and
  // #CAXTRACK: the held part is tracked already).
  if (xv_held_) {
    const bool passes =
        cmd && (rides_along(*cmd) || std::holds_alternative<interp::CaxTrack>(cmd->body));
    if (!passes && (!cmd || !std::holds_alternative<interp::Motion>(cmd->body))) {
      if (cmd) held_ = std::move(cmd);
      // Its joint with the next part is checked (joint_belt_check) unless the path stops
      // between them (next() forgets it at a Dwell or a ChannelWait).
      xv_last_ = *xv_held_;
      out = std::move(*xv_held_);
      xv_held_.reset();
      return Pulled::item;
    }
  }
  // A PCS1 block held for its ball's share goes out before any other command than the next
  // Motion (that command is taken again at the next pull). Commands that emit nothing and do
  // not stop the path keep it held, as the static unit's part above: the planner blends across
  // them, so the ball still needs its share (rides_along, #FLUSH CONTINUE; a plain #FLUSH stops
  // the path, docs/ipo.md).
  if (ball_held_) {
    const auto* flush = std::get_if<interp::Flush>(cmd ? &cmd->body : nullptr);
    const bool passes =
        cmd && (std::holds_alternative<interp::Motion>(cmd->body) || rides_along(*cmd) ||
                (flush && flush->kind == interp::FlushKind::continue_));
    if (!passes) {
      if (cmd) held_ = std::move(cmd);
      ball_release(nullptr);
      return Pulled::again;
    }
  }
  return Pulled::none;
}

bool ProgramSource::close_syn_wait(std::optional<interp::Command>& cmd, Item& out) {
  // The INDP_SYN commands of one block share one ChannelWait after the last of them, so their
  // axes start together and the next block waits for all (isg-language.md 6.1).
  const auto* a = std::get_if<interp::AxisCommand>(&cmd->body);
  const bool same_block = cmd->line == syn_wait_->line && cmd->file == file_ &&
                          is_channel_event(cmd->body) && (!stops_path(cmd->body) || a != nullptr);
  if (same_block) return false;
  // An INTERRUPTIBLE block before the next synchronisation (docs/conveyor.md S-4).
  syn_wait_->interruptible =
      syn_interruptible_ && (std::holds_alternative<interp::ProbeArm>(cmd->body) ||
                             std::holds_alternative<interp::SyncIn>(cmd->body));
  held_ = std::move(cmd);
  out = *syn_wait_;
  given_ = syn_wait_->tag;
  syn_wait_.reset();
  return true;
}

ProgramSource::Pulled ProgramSource::route_event(interp::Command& cmd, Item& out) {
  const std::uint32_t line = cmd.line;
  // The first motion after #SYNC IN / #SYNC OUT is the catch-up / departure, a PTP motion the
  // channel runs while the path stands (tracking/conveyor_sync).
  if (sync_motion_ && std::holds_alternative<interp::Motion>(cmd.body)) {
    sync_motion_ = false;
    events_.push_back(ChannelEvent{++tag_, line, cmd.file, sync_motion(cmd.body, line)});
    out = ChannelWait{line, tag_};
    given_ = tag_;
    return Pulled::item;
  }
  if (!is_channel_event(cmd.body)) return run_command(cmd, out);
  if (std::holds_alternative<interp::SyncIn>(cmd.body) ||
      std::holds_alternative<interp::SyncOut>(cmd.body)) {
    sync_motion_ = true;
    static_sync(cmd.body);  // the static unit's belt feed
  }
  sync_belt(cmd.body);  // the PCS1 velocity split
  if (const auto* in = std::get_if<interp::SyncIn>(&cmd.body))
    belt_conv_vel_ = in->conv_vel;  // the belt's share under #TRAFO ON
  if (const auto* md = std::get_if<interp::MachineData>(&cmd.body))
    if (std::optional<std::string> why = machine_data_unsupported(*md, machine_)) fail(line, *why);
  note_indp(cmd.body);
  note_homing(cmd.body);  // homed axes are answered at run time
  const bool stops = stops_path(cmd.body);
  const bool syn = std::holds_alternative<interp::AxisCommand>(cmd.body) && stops;
  if (syn) {  // every INDP_SYN motion of the block INTERRUPTIBLE (docs/conveyor.md S-4)
    const bool interruptible = std::get<interp::AxisCommand>(cmd.body).interruptible;
    syn_interruptible_ = (syn_wait_ ? syn_interruptible_ : true) && interruptible;
  }
  events_.push_back(ChannelEvent{++tag_, line, cmd.file, std::move(cmd.body)});
  if ((syn || syn_wait_) && tag_ - given_ < kMaxPendingEvents) {
    syn_wait_ = ChannelWait{line, tag_};  // the block's later events are due with it
    return Pulled::again;
  }
  syn_wait_.reset();
  if (stops || tag_ - given_ >= kMaxPendingEvents) {
    out = ChannelWait{line, tag_};
    given_ = tag_;
    return Pulled::item;
  }
  return Pulled::again;
}

void ProgramSource::motion(const interp::Motion& body, std::uint32_t line) {
  planner::Move mv;
  try {
    mv = to_move(body, line);
  } catch (const Stop&) {
    if (!ball_held_) throw;
    // The held block runs to its end before the error stops the stream, as every block before
    // a faulty one does.
    held_error_ = std::move(error_);
    error_.reset();
    ball_release(nullptr);
    return;
  }
  mv.event_tag = tag_;
  given_ = tag_;
  ball_release(&mv);  // the ball's share, then the held block out
  if (holds_for_ball(mv, body.frame.space == interp::Space::pcs1))
    ball_held_ = std::move(mv);
  else
    emit_path(std::move(mv));  // queued, handed out at the loop's top
}

bool ProgramSource::barrier(const interp::Barrier& body, std::uint32_t line, Item& out) {
  // P-CHAN-00451 implicit synchronisation (docs/ipo.md "Position barriers"): the block programs
  // again an axis whose INDP motion may still run.
  const interp::AxisMask sync = positions_ != nullptr && body.wants(interp::BarrierNeed::position)
                                    ? body.axes & indp_running_
                                    : 0;
  if (store_ == nullptr && positions_ == nullptr) return false;  // next_decode_only() answers
  if (sync != 0) {
    events_.push_back(ChannelEvent{++tag_, line, file_, interp::WaitIndp{sync}});
    open_ = body;  // answered at the next pull, with the path standing
    run_time_ = sync;
    out = ChannelWait{line, tag_};
    given_ = tag_;
    return true;
  }
  if (flush_ && body.wants(interp::BarrierNeed::external)) {
    open_ = body;  // the path stops first: answered at the next pull
    out = Dwell{0.0, line};
    return true;
  }
  answer(body);
  return false;
}

ProgramSource::Pulled ProgramSource::run_command(interp::Command& cmd, Item& out) {
  const std::uint32_t line = cmd.line;
  bool produced = false;
  bool ended = false;
  std::visit(
      [&](const auto& body) {
        using T = std::decay_t<decltype(body)>;
        if constexpr (std::is_same_v<T, interp::Motion>) {
          motion(body, line);
        } else if constexpr (std::is_same_v<T, interp::Dwell>) {
          static_stop(line, body.tech ? "a technology function's acknowledgement" : "a dwell");
          out = Dwell{body.seconds, line, tag_, 0, body.tech, body.since_output};
          given_ = tag_;
          produced = true;
        } else if constexpr (std::is_same_v<T, interp::End>) {
          ended = true;
        } else if constexpr (std::is_same_v<T, interp::Message> ||
                             std::is_same_v<T, interp::ProgramStop>) {
          // pass: no motion (M00/M01 do not stop: there is no operator to press start)
        } else if constexpr (std::is_same_v<T, interp::Flush>) {
          // isg-language.md 5.1 [C]: #FLUSH empties the channel buffer, the path stops at the
          // end of the last motion block (the events before it done); #FLUSH WAIT lets the
          // decoder wait until the buffer ran empty: a stop too. #FLUSH CONTINUE does not stop
          // when the next motion block is already there, as it always is here.
          if (body.kind != interp::FlushKind::continue_) {
            static_stop(line, "#FLUSH");
            out = ChannelWait{line, tag_};
            given_ = tag_;
            produced = true;
          }
        } else if constexpr (std::is_same_v<T, interp::Barrier>) {
          produced = barrier(body, line, out);
        } else if constexpr (std::is_same_v<T, interp::SelectCs>) {
          select_cs(body, line);
        } else if constexpr (std::is_same_v<T, interp::Kinematics>) {
          produced = kinematics(body, line, out);  // a switch of #TRAFO stops the path
        } else if constexpr (std::is_same_v<T, interp::CaxTrack>) {
          caxtrack(body, line);
        } else if constexpr (std::is_same_v<T, interp::SplineBegin>) {
          spline_begin(body, line);
        } else if constexpr (std::is_same_v<T, interp::SplinePoint>) {
          spline_point(body, line);
        } else if constexpr (std::is_same_v<T, interp::SplineEnd>) {
          spline_end(line);
        } else if constexpr (std::is_same_v<T, interp::Tech> ||
                             std::is_same_v<T, interp::WaitIndp> ||
                             std::is_same_v<T, interp::AxisCommand> ||
                             std::is_same_v<T, interp::MoveVelocity> ||
                             std::is_same_v<T, interp::ProbeArm> ||
                             std::is_same_v<T, interp::SyncIn> ||
                             std::is_same_v<T, interp::SyncOut> ||
                             std::is_same_v<T, interp::Homing> ||
                             std::is_same_v<T, interp::MachineData>) {
          // channel events: queued by route_event (is_channel_event), never here
        } else if constexpr (std::is_same_v<T, interp::SetPosition>) {
          fail(line, "G92 set position");
        } else {
          static_assert(!sizeof(T*), "every command kind is handled");
        }
      },
      cmd.body);
  if (ended) {
    if (tag_ == given_) return Pulled::end;
    // Events after the last motion: the channel executes them before the program ends.
    end_reached_ = true;
    out = ChannelWait{line, tag_};
    given_ = tag_;
    return Pulled::item;
  }
  return produced ? Pulled::item : Pulled::again;
}

bool is_channel_event(const interp::CommandBody& body) noexcept {
  return std::holds_alternative<interp::Tech>(body) ||
         std::holds_alternative<interp::WaitIndp>(body) ||
         std::holds_alternative<interp::AxisCommand>(body) ||
         std::holds_alternative<interp::MoveVelocity>(body) ||
         std::holds_alternative<interp::ProbeArm>(body) ||
         std::holds_alternative<interp::SyncIn>(body) ||
         std::holds_alternative<interp::SyncOut>(body) ||
         std::holds_alternative<interp::Homing>(body) ||  // --- static-saw: G74
         std::holds_alternative<interp::MachineData>(body);
}

bool stops_path(const interp::CommandBody& body) noexcept {
  if (const auto* a = std::get_if<interp::AxisCommand>(&body))
    return a->kind == interp::IndpKind::syn;
  return std::holds_alternative<interp::WaitIndp>(body) ||
         std::holds_alternative<interp::SyncIn>(body) ||
         std::holds_alternative<interp::SyncOut>(body) ||
         std::holds_alternative<interp::Homing>(body) ||     // --- static-saw: G74
         std::holds_alternative<interp::MachineData>(body);  // the path stops (§5.10)
}

}  // namespace ncsim::ipo
