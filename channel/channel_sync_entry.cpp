// channel/channel_sync_entry: the channel's part of #SYNC IN FEED_CONT > 0 / FEED_CONT_AUTO
// (sync-feed, issue 14; docs/conveyor.md S-1): the relative velocity the catch-up meets its
// workpiece with, decided against the path's first PCS1 block (tracking/sync_entry), and the
// hand-over inside the cycle in which the catch-up meets its target.
//
// Flow: at the catch-up's first dispatch (ConveyorTracking::on_sync_motion) the path holds at the
// catch-up's ChannelWait; the interpolator prepares what follows it into its look-ahead window
// (PathInterpolator::prefill), sync_entry() reduces FEED_CONT to what the link and the first
// block's entry allow, and ConveyorSync plans the catch-up for it (reducing it further if an
// axis cannot meet the target at it). In the cycle in which the catch-up meets its target
// (ConveyorSync::handover_lag) the path is released to start its first segment at that
// velocity, at the meeting instant inside the cycle; the joint goes to the sink (the audit
// allows the corner's VELOJUMP step there).

#include <cstdlib>

#include "channel/conveyor_tracking.hpp"

namespace ncsim::channel {

double ConveyorTracking::sync_entry_velocity(std::span<const axes::MotionState> start,
                                             std::span<const double> target) noexcept {
  sync_entry_ = tracking::SyncEntry{};
  sync_u_ = sync_->catch_up_direction(start, target);
  if (!ipo_.prefill()) return 0.0;  // the source failed: the next step reports it
  sync_entry_ = tracking::sync_entry(sync_->feed_cont_wanted(), sync_u_, ipo_.next_segment(),
                                     ipo_.next_entry_cap(), ipo_.axes(), ipo_.t_cycle());
  return sync_entry_.v;
}

EventOutcome ConveyorTracking::sync_hand_over(double lag, const program::ChannelEvent& e) noexcept {
  const planner::PreparedSegment* first = ipo_.next_segment();
  if (first == nullptr) return EventOutcome::done;  // v_relative() > 0 only with a block ahead
  const double v = ipo_.start_moving(sync_->v_relative(), lag);
  // through the relay, which notes it for NC6210's jerk stencil.
  if (sink_ != nullptr || kin_.configured()) {
    try {
      kin_.pass_joint(tracking::sync_entry_joint(sync_entry_, sync_u_, *first, v,
                                                 ipo_.cycle().t + lag, e.line, axes_.size()));
    } catch (...) {
      std::abort();  // out of memory in the sink
    }
  }
  return EventOutcome::done;
}

}  // namespace ncsim::channel
