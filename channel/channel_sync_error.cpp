// channel/channel_sync_error: the channel after a run-time error raised while synchronised (seed
// 004 §2.3 l.492-498; tracking/sync_error.hpp; docs/conveyor.md "Errors while synchronised").
//
// Flow: Channel::step() runs the program's cycle (step_program); when that raises a run-time
// error in the tracking phase, synchronised, the error is held back (sync_error_), the path
// gets the feed hold (a jerk-limited stop on its contour in PCS1) and the cycle is completed
// here: the belt's Port is stepped, the PCS1 offset added, the axes driven (no monitor: the
// channel is in its error state) and the cycle shown. Every later cycle does the same with a
// fresh interpolator cycle (or, once the interpolator has ended, a copy of its last one at
// rest) until SyncErrorStop says the axes must brake before a soft limit; their braking
// ramps then replace the setpoints, and when every axis is at rest (or the belt and the path
// stand) the run ends with the original error: its id, line and time.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

#include "channel/channel.hpp"

namespace ncsim::ipo {

namespace {

const char* end_text(AfterErrorEnd why) noexcept {
  switch (why) {
    case AfterErrorEnd::soft_limit:
      return "braked before its soft limit";
    case AfterErrorEnd::velocity:
      return "braked: following the belt would exceed its maximum velocity";
    case AfterErrorEnd::belt_stop:
      return "stood with the belt";
    case AfterErrorEnd::time_limit:
      return "braked after ncsim's longest following";
  }
  return "";
}

}  // namespace

bool Channel::sync_error_begin() noexcept {
  if (!error_ || after_begun_ || !sync_ || !after_.usable()) return false;  // once a run
  if (sync_->phase() != SyncPhase::tracking || !sync_->synchronised()) return false;
  // Not built (docs/conveyor.md): a static unit (no real X follows the belt).
  if (tracking_.static_unit()) return false;
  if (!SyncErrorStop::keeps_synchronisation(error_->id)) return false;
  if (!sync_error_indp_begin()) return false;  // --- trafo-feed: the INDP axes brake
  // --- sync-trafo: under #TRAFO ON the TCP's stop (channel_sync_error_trafo.cpp)
  after_trafo_ = false;
  if (kin_.transformed() && !sync_error_trafo_begin()) return false;
  after_begun_ = true;
  sync_error_ = std::move(error_);
  play_.abort_program();  // its blocks only brake now
  error_.reset();
  after_.begin();
  after_path_ended_ = false;
  ipo_.set_feed_hold(true);  // the path velocity in PCS1 goes to 0 (l.494)
  ipo_.set_velocity_cap(WorkspaceHold::kNone);
  return true;
}

Status Channel::sync_error_cycle(bool fresh) noexcept {
  const double t_cycle = ipo_.t_cycle();
  if (fresh && !after_path_ended_) {
    if (ipo_.step() != Status::running) {  // the path ended (or its source failed) meanwhile
      after_path_ended_ = true;
      after_cycle_ = ipo_.cycle();
      after_cycle_.index -= 1;  // advanced below
    }
  }
  if (!after_path_ended_) {
    after_cycle_ = ipo_.cycle();
  } else if (fresh) {  // the path stands at its last point: the cycles go on at rest
    after_cycle_.index += 1;
    after_cycle_.t = static_cast<double>(after_cycle_.index) * t_cycle;
    after_cycle_.path.v = after_cycle_.path.a = after_cycle_.path.j = 0.0;
    after_cycle_.v = after_cycle_.a = after_cycle_.j = AxisVec{};
    after_cycle_.distance = 0.0;
    after_cycle_.held = true;
    after_cycle_.factor = 0.0;
    after_cycle_.lost = t_cycle;
  }
  shown_ = &after_cycle_;
  const Cycle& c = after_cycle_;
  // The belt's world goes on (its errors are not raised again: the channel is in error).
  (void)sync_->step(c.t);
  if (!after_trafo_) mapping_.map(c);
  sync_error_indp_step(c);  // --- trafo-feed
  std::span<axes::Setpoint> sp(axes_.setpoints().data(), axes_.size());
  bool end = false;
  if (after_trafo_) {  // --- sync-trafo: the TCP's stop and the joints from it
    if (!sync_error_trafo_step(c, end)) {
      after_passed_ = "; the TCP would have left the kinematic's reach: the run ended there";
      after_end_t_ = c.t - t_cycle;
      error_ = sync_error_;
      return Status::error;
    }
  } else if (after_.stopping()) {
    after_.step(sp);
    sync_error_indp_apply();  // --- trafo-feed
    end = after_.stood() && sync_error_indp_stood();
  } else {
    AfterErrorEnd why = AfterErrorEnd::soft_limit;
    int axis = -1;
    const bool path_stands = c.path.v == 0.0 && c.path.a == 0.0;
    const bool belt_stands = std::fabs(sync_->belt_velocity()) <= SyncErrorStop::kStandstill;
    // --- trafo-feed: the path axes decide; the INDP axes brake on their own
    const auto path_axes = sync_error_path_axes();
    const std::span<const axes::Setpoint> seen(path_axes.data(), axes_.size());
    if (path_stands && belt_stands) {
      after_.start_stopping(seen, AfterErrorEnd::belt_stop, -1);
      end = sync_error_indp_stood();
    } else if (after_.must_stop(seen, why, axis)) {
      after_.start_stopping(seen, why, axis);  // this cycle as computed, braking from the next
    }
    after_.follow_cycle();
  }
  // No axis receives a set position beyond its soft limit (as AxisStage::drive). The stop is
  // planned not to get there; a machine already at its limit when the error came cannot follow at
  // all.
  const std::size_t first = fresh ? 0 : driven_;
  for (std::size_t i = first; i < axes_.size(); ++i) {
    const auto alarm = axes::check_soft_limits(axes_.config(i).monitor.soft_limits,
                                               axes_.setpoints()[i].p, static_cast<int>(i), c.t);
    if (!alarm) continue;
    if (!fresh) {  // the error's own cycle: it ends the run as every error does (no note)
      error_ = std::move(sync_error_);
      sync_error_.reset();
      return Status::error;
    }
    try {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "; axis %s would have passed its soft limit %.6g mm at t=%.6g s: the run "
                    "ended there",
                    axes_.config(i).name.c_str(), alarm->limit, c.t);
      after_passed_ = buf;
    } catch (...) {
      std::abort();
    }
    after_end_t_ = c.t - t_cycle;
    error_ = sync_error_;
    return Status::error;
  }
  for (std::size_t i = first; i < axes_.size(); ++i)
    axes_.follow(i);
  if (sink_) sink_->on_cycle(cycle());
  if (end) {
    after_end_t_ = c.t;
    error_ = sync_error_;  // the next step() ends the run with the original error
  }
  return Status::running;
}

std::string Channel::after_error_note() const {
  if (!sync_error_) return {};
  if (after_trafo_) return after_error_trafo_note();  // --- sync-trafo
  char buf[512];
  std::string axis;
  std::string limit;
  if (after_.axis() >= 0) {
    const auto i = static_cast<std::size_t>(after_.axis());
    axis = " axis " + axes_.config(i).name;
    const AfterErrorAxis& l = after_.limits(i);
    if (after_.why() == AfterErrorEnd::soft_limit) {
      const double p = axes_.setpoints()[i].p;
      const bool up = l.soft.max_enabled &&
                      (!l.soft.min_enabled ||
                       std::fabs(l.soft.max_position - p) < std::fabs(p - l.soft.min_position));
      std::snprintf(buf, sizeof buf, " %.6g mm (%s), standing at %.6g mm",
                    up ? l.soft.max_position : l.soft.min_position,
                    up ? "P-AXIS-00178" : "P-AXIS-00177", axes_.setpoints()[i].p);
      limit = buf;
    }
  }
  std::snprintf(buf, sizeof buf,
                "synchronisation kept after %s (004 §2.3): the path braked to 0 in PCS1, the "
                "machine followed the belt for %.6g s;%s %s%s; it stood at t=%.6g s",
                sync_error_->id.c_str(), after_.followed(), axis.c_str(), end_text(after_.why()),
                limit.c_str(), after_end_t_);
  std::string indp;  // --- trafo-feed
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if ((after_indp_ >> i) & 1u) indp += (indp.empty() ? "" : ", ") + axes_.config(i).name;
  if (!indp.empty()) indp = "; INDP axis " + indp + " braked on its own ramp";
  return std::string(buf) + indp + after_passed_;
}

}  // namespace ncsim::ipo
