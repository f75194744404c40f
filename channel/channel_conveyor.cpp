// channel/channel_conveyor: the channel's conveyor tracking (issue 14; docs/conveyor.md
// "Synchronisation"): ConveyorTracking's conveyor events (see channel/conveyor_tracking.hpp).
//
// Event flow (program/channel_event.hpp): #SYNC IN stops the path; its handler blocks while the
// Port has no latch ("waiting for measured value"). The first motion after it reaches the
// channel as a Motion event (ProgramSource::sync_motion, end in MCS at belt travel 0): the
// catch-up PTP runs while the path stands, and its handler blocks until the profile has met
// the moving target. The path's PCS1 blocks then run with the frame's offset (AxisMapping).
// #SYNC OUT switches to `leaving` (the axes move on with the belt); the first motion after it
// is the departure PTP from that moving state.

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>

#include "channel/conveyor_tracking.hpp"
#include "core/number_text.hpp"
#include "core/tolerance.hpp"
#include "program/machine_data.hpp"
#include "program/program_source.hpp"

namespace ncsim::channel {

namespace {

constexpr const char* kNeedsWorld =
    " needs the conveyor world: run with a scenario that has a [conveyor] section (no conveyor "
    "is attached to the channel)";

}  // namespace

ConveyorTracking::ConveyorTracking(std::optional<tracking::ConveyorSync>& sync,
                                   ipo::PathInterpolator& ipo, AxisStage& axes, IndpStage& indp,
                                   KinematicStage& kin, const tracking::SyncErrorStop& after,
                                   std::optional<RunTimeError>& error, ipo::Sink* sink,
                                   double measured_value_wait_max,
                                   std::optional<machines::ConveyorAxisParams> conveyor_axis)
    : sync_(sync),
      ipo_(ipo),
      axes_(axes),
      indp_(indp),
      kin_(kin),
      after_(after),
      error_(error),
      sink_(sink),
      measured_value_wait_max_(measured_value_wait_max),
      conveyor_axis_(std::move(conveyor_axis)) {
  if (!(measured_value_wait_max_ > 0.0))
    throw std::invalid_argument("channel::Channel: measured_value_wait_max must be > 0 s, got " +
                                core::human(measured_value_wait_max_));
  // Same rounding as every wait (docs/ipo.md): the limit in whole cycles, never shorter.
  measure_wait_cycles_max_ = static_cast<std::uint64_t>(
      std::ceil(measured_value_wait_max_ / ipo_.t_cycle() - kCycleRounding));
}

bool ConveyorTracking::check_workspace(const ipo::Cycle& c) noexcept {
  if (!sync_->synchronised()) return true;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (const int k = sync_->xyz(i); k >= 0)
      p[k] = kin_.transformed()      ? kin_.tcp()[i].p             // the TCP under #TRAFO
             : indp_.axes().owned(i) ? indp_.axes().setpoint(i).p  // the INDP axis's own
                                     : axes_.setpoints()[i].p;
  try {
    if (auto e = sync_->workspace(p)) {
      raise(error_, e->id.c_str(), std::move(e->message), c, -1);
      return false;
    }
  } catch (...) {
    std::abort();  // out of memory while reporting a run-time error
  }
  return true;
}

EventOutcome ConveyorTracking::on_sync_in(const interp::SyncIn& command,
                                          const program::ChannelEvent& e) noexcept {
  try {
    if (!sync_ || sync_->port() == nullptr)
      return EventContext(e, ipo_, error_)
          .fail(program::kNotSupportedId, std::string("not supported: #SYNC IN") + kNeedsWorld);
    // FEED_CONT > 0 / FEED_CONT_AUTO run (S-1); on a static unit
    // they have nothing to act on (docs/conveyor.md S-1): NC9060
    if (static_unit_ && (command.feed_cont_auto || command.feed_cont.value_or(0.0) > 0.0))
      return EventContext(e, ipo_, error_)
          .fail(kStaticFeedContId,
                "#SYNC IN FEED_CONT > 0 or FEED_CONT_AUTO on the static processing unit "
                "(P-CHAN-00364 x_virtual): its feed is the belt's and \"cannot be "
                "influenced independently\" (004 l.438), the contour starts from the "
                "catch-up at rest (l.443); remove FEED_CONT");
    if (sync_tag_ != e.tag) {  // first dispatch: from now the path waits for the measured value
      sync_tag_ = e.tag;
      measure_waited_ = 0;
      if (auto err = sync_->sync_in(command, command.kinematics))
        return EventContext(e, ipo_, error_).fail(err->id.c_str(), std::move(err->message));
      return EventOutcome::blocking;
    }
    if (sync_->phase() != tracking::SyncPhase::waiting) return EventOutcome::done;
    // A measured value that never comes (no workpiece left, the belt stopped, the probe armed
    // for an edge that never passes) must not make the run endless: ncsim's limit (NC9054).
    if (++measure_waited_ > measure_wait_cycles_max_) {
      return EventContext(e, ipo_, error_)
          .fail(kMeasuredValueWaitId,
                "#SYNC IN: no measured value within " + core::human(measured_value_wait_max_) +
                    " s (ncsim's limit): no workpiece edge was latched while the probe was armed");
    }
    return EventOutcome::blocking;
  } catch (...) {
    std::abort();  // out of memory while reporting a run-time error
  }
}

EventOutcome ConveyorTracking::on_sync_out(const interp::SyncOut& command,
                                           const program::ChannelEvent& e) noexcept {
  try {
    if (!sync_ || sync_->port() == nullptr)
      return EventContext(e, ipo_, error_)
          .fail(program::kNotSupportedId, std::string("not supported: #SYNC OUT") + kNeedsWorld);
    // FEED_CONT / FEED_CONT_AUTO of #SYNC OUT, the velocity the
    // desynchronisation movement terminates at (004 l.529), is "reduced as required" (l.284) to
    // 0: that movement is INDP positioning (l.535-552) or the departure PTP, both ending in
    // position, and what follows them starts at rest (docs/conveyor.md S-2).
  } catch (...) {
    std::abort();
  }
  sync_->sync_out(command);
  return EventOutcome::done;
}

EventOutcome ConveyorTracking::on_sync_motion(const interp::Motion& motion,
                                              const program::ChannelEvent& e) noexcept {
  if (!sync_) {
    return EventContext(e, ipo_, error_)
        .fail(program::kNotSupportedId, "not supported: a synchronisation motion without FCT_DLM");
  }
  if (sync_tag_ == e.tag) {  // dispatched again: blocking while the profile runs
    if (const auto lag = sync_->handover_lag()) return sync_hand_over(*lag, e);
    return sync_->driving() ? EventOutcome::blocking : EventOutcome::done;
  }
  // the INDP axes go to the catch-up / departure (docs/conveyor.md S-4).
  if (!indp_.hand_over(axes_.size())) return EventOutcome::blocking;
  sync_tag_ = e.tag;
  const std::size_t n = axes_.size();
  std::array<axes::MotionState, planner::kMaxAxes> start{};
  std::array<double, planner::kMaxAxes> target{};
  for (std::size_t i = 0; i < n; ++i) {
    // The command state at the end of the last cycle (the catch-up starts in the next one).
    start[i] =
        axes::MotionState{axes_.state().command[i], axes_.setpoints()[i].v, axes_.setpoints()[i].a};
    // under #TRAFO ON the catch-up is a TCP motion (004 l.609)
    if (kin_.transformed())
      start[i] = axes::MotionState{kin_.tcp()[i].p, kin_.tcp()[i].v, kin_.tcp()[i].a};
    target[i] = motion.end[i];  // interpolated order, MCS at belt travel 0
  }
  const bool catch_up = sync_->phase() == tracking::SyncPhase::latched;
  // a catch-up meeting the workpiece moving (FEED_CONT > 0, FEED_CONT_AUTO);
  // under #TRAFO ON too, as a TCP motion (docs/conveyor.md S-1)
  const bool moving = catch_up && sync_->feed_cont_wanted() > 0.0;
  const double f =
      moving ? sync_entry_velocity(std::span(start.data(), n), std::span(target.data(), n)) : 0.0;
  axes::Result r = axes::Result::ok;
  if (kin_.transformed()) {
    kin_.plan_sync_motion(*sync_, catch_up, std::span(start.data(), n), std::span(target.data(), n),
                          f, r);
  } else {
    r = catch_up ? sync_->start_catch_up(std::span(start.data(), n), std::span(target.data(), n), f)
                 : sync_->start_departure(std::span(start.data(), n), std::span(target.data(), n));
  }
  if (r == axes::Result::ok) {
    planner::AxisVec
        hold{};  // the path's own coordinates: PCS1 at travel 0 (catch-up), MCS (departure)
    for (std::size_t i = 0; i < n; ++i)
      hold[i] = target[i];
    sync_hold_ = hold;
    // a moving catch-up shorter than a cycle hands over in this one
    if (const auto lag = sync_->handover_lag()) return sync_hand_over(*lag, e);
    return EventOutcome::blocking;
  }
  try {
    const int axis = sync_->catch_up().failed_axis();
    std::string what = catch_up ? "the catch-up after #SYNC IN" : "the departure after #SYNC OUT";
    if (axis >= 0) what += " of axis " + axes_.config(static_cast<std::size_t>(axis)).name;
    return EventContext(e, ipo_, error_)
        .fail(tracking::kCatchUpNotSynchronizableId, what + ": " + std::string(axes::describe(r)) +
                                                         " (" +
                                                         std::string(axes::diagnostic_id(r)) + ")");
  } catch (...) {
    std::abort();
  }
}

EventOutcome ConveyorTracking::on_probe_arm(const interp::ProbeArm& command,
                                            const program::ChannelEvent& e) noexcept {
  if (!sync_ || sync_->port() == nullptr) {
    try {
      return EventContext(e, ipo_, error_)
          .fail(program::kNotSupportedId,
                std::string("not supported: MC_TouchProbe") + kNeedsWorld);
    } catch (...) {
      std::abort();
    }
  }
  sync_->port()->arm_probe(command);
  return port_outcome(e);
}

EventOutcome ConveyorTracking::on_move_velocity(const interp::MoveVelocity& command,
                                                const program::ChannelEvent& e) noexcept {
  if (!sync_ || sync_->port() == nullptr) {
    try {
      return EventContext(e, ipo_, error_)
          .fail(program::kNotSupportedId,
                std::string("not supported: MC_MoveVelocity") + kNeedsWorld);
    } catch (...) {
      std::abort();
    }
  }
  // In encoder mode the scenario moves the belt and the Port ignores the command (its contract).
  sync_->port()->command_velocity(command);
  return port_outcome(e);
}

EventOutcome ConveyorTracking::port_outcome(const program::ChannelEvent& e) noexcept {
  const auto& err = sync_->port()->error();
  if (!err) return EventOutcome::done;
  try {
    return EventContext(e, ipo_, error_).fail(err->id.c_str(), std::string(err->message));
  } catch (...) {
    std::abort();  // out of memory building a message
  }
}

EventOutcome ConveyorTracking::on_machine_data(const interp::MachineData& command,
                                               const program::ChannelEvent& e) noexcept {
  try {
    // ProgramSource let only the conveyor axis's filter parameters through (machine_data.hpp).
    if (!sync_ || sync_->port() == nullptr || !conveyor_axis_)
      return EventContext(e, ipo_, error_)
          .fail(program::kNotSupportedId,
                std::string("not supported: #MACHINE DATA of the conveyor filters") + kNeedsWorld);
    if (tracking())
      return EventContext(e, ipo_, error_)
          .fail(kFilterWhileTrackingId,
                "#MACHINE DATA of the conveyor's filters or delay time while "
                "synchronised: the filters would restart under the tool and step PCS1 "
                "(change them before #SYNC IN or after #SYNC OUT)");
    const machines::ConveyorAxisParams changed =
        program::apply_machine_data(*conveyor_axis_, command);
    if (!sync_->port()->set_axis_params(changed))
      return EventContext(e, ipo_, error_)
          .fail(program::kNotSupportedId,
                "not supported: #MACHINE DATA of the conveyor filters on this conveyor "
                "world");
    conveyor_axis_ = changed;
    return EventOutcome::done;
  } catch (...) {
    std::abort();  // out of memory building a message: nothing sane is left
  }
}

}  // namespace ncsim::channel
