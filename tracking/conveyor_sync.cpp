// tracking/conveyor_sync: the channel's conveyor tracking (see the header).

#include "tracking/conveyor_sync.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::tracking {

ConveyorSync::ConveyorSync(const machines::ConveyorSyncChannel& channel,
                           std::span<const SyncAxis> axes, double t_cycle)
    : frame_(channel),
      box_(channel.workspace),
      tolerance_(channel.sync_in_tolerance),
      reserve_(channel.dynamics_reserve),
      t_cycle_(t_cycle) {
  if (axes.size() > planner::kMaxAxes)
    throw std::invalid_argument("tracking::ConveyorSync: " + std::to_string(axes.size()) + " axes");
  if (!(t_cycle > 0.0))
    throw std::invalid_argument("tracking::ConveyorSync: cycle time " + core::human(t_cycle));
  n_ = axes.size();
  for (std::size_t i = 0; i < n_; ++i) {
    axes_[i] = axes[i];
    if (!axes::valid(axes[i].dynamics))
      throw std::invalid_argument("tracking::ConveyorSync: axis " + axes[i].name +
                                  ": PTP dynamics not usable (V " +
                                  core::human(axes[i].dynamics.v_max) + ")");
    share_[i] = axes[i].xyz >= 0 && axes[i].xyz < 3 ? frame_.direction()[axes[i].xyz] : 0.0;
    if (std::fabs(share_[i]) < kTiny) share_[i] = 0.0;  // rounding of an unrotated T0
  }
  // The hold line against the conveying direction
  std::array<int, planner::kMaxAxes> xyz{};
  for (std::size_t i = 0; i < n_; ++i)
    xyz[i] = axes_[i].xyz;
  // None on a static unit (P-CHAN-00364 = 1): its path's X component is the belt's
  // (channel/channel_static.cpp), so X never moves against the conveying direction in MCS.
  if (auto h =
          hold_config(channel, frame_.direction(), channel.optimised_monitoring, xyz.data(), n_);
      h && !channel.x_virtual)
    hold_.emplace(*h);
}

std::optional<SyncError> ConveyorSync::sync_in(const interp::SyncIn& command, bool joints) {
  for (std::size_t i = 0; i < n_ && !joints; ++i) {
    planner::AxisLimits l;
    l.v_max = axes_[i].dynamics.v_max;
    if (auto e = check_conv_vel(l, share_[i], command.conv_vel, axes_[i].name)) return e;
  }
  conv_vel_ = command.conv_vel;
  // FEED_CONT (mm/s here) or FEED_CONT_AUTO, reduced at the catch-up
  feed_cont_ = command.feed_cont_auto ? std::numeric_limits<double>::infinity()
                                      : std::max(0.0, command.feed_cont.value_or(0.0));
  phase_ = SyncPhase::waiting;
  synchronised_ = false;
  waited_ = 0.0;
  return std::nullopt;
}

void ConveyorSync::sync_out(const interp::SyncOut&) noexcept {
  synchronised_ = false;
  phase_ = phase_ == SyncPhase::tracking ? SyncPhase::leaving : SyncPhase::off;
}

std::optional<SyncError> ConveyorSync::step(double t) noexcept {
  if (port_ == nullptr) return std::nullopt;
  if (t <= stepped_t_) return std::nullopt;  // once per cycle (channel_sync_error)
  const bool first = stepped_t_ < 0.0;       // no master position of a step before
  const double dt = t - stepped_t_;
  stepped_t_ = t;
  // A profile that ended in the previous cycle hands over now (its last setpoint was exact).
  // One meeting the target moving hands over in the cycle it meets it: the
  // path starts at the meeting inside this cycle (Channel::on_sync_motion, docs/conveyor.md S-1).
  if (handover_due()) synchronised_ = true;
  if (driving() && (t_catch_ >= catch_up_.duration() || handover_due())) {
    phase_ = phase_ == SyncPhase::catching_up ? SyncPhase::tracking : SyncPhase::off;
  }
  port_->step(t);
  if (const auto& e = port_->error()) {
    try {
      return SyncError{e->id, e->message};
    } catch (...) {
      std::abort();  // out of memory while reporting a run-time error
    }
  }
  if (phase_ == SyncPhase::waiting) {
    if (const auto latch = port_->take_latch()) {
      frame_.latch(*latch);
      phase_ = SyncPhase::latched;
    } else {
      waited_ += t_cycle_;
    }
  }
  const conveyor::BeltState& m = port_->master();
  if (frame_.latched() && phase_ != SyncPhase::off && phase_ != SyncPhase::waiting) {
    s_ = frame_.travel(m.p);
    v_ = frame_.along_x(m.v);
    a_ = frame_.along_x(m.a);
    v_slope_ = first ? v_ : frame_.along_x((m.p - p_last_) / dt);
    // The slope is the mean velocity over the cycle, half a cycle behind its end (F-8).
    v_frame_ = first ? v_ : v_slope_ + 0.5 * a_ * dt;
  }
  p_last_ = m.p;
  const bool checked = phase_ == SyncPhase::waiting || phase_ == SyncPhase::latched ||
                       phase_ == SyncPhase::catching_up || phase_ == SyncPhase::tracking;
  if (checked) {
    try {
      if (auto e = check_belt_velocity(m.v, conv_vel_)) return e;
    } catch (...) {
      std::abort();  // out of memory while reporting a run-time error
    }
  }
  if (driving()) {
    t_catch_ += t_cycle_;
    bool within = true;
    for (std::size_t i = 0; i < n_; ++i) {
      catch_sp_[i] = catch_up_.setpoint(i, t_catch_, s_, v_frame_, a_);
      if (std::fabs(catch_sp_[i].p - catch_up_.target_at(i, s_)) > tolerance_ &&
          t_catch_ < catch_up_.duration())
        within = false;
    }
    if (phase_ == SyncPhase::catching_up && within) synchronised_ = true;
  }
  return std::nullopt;
}

axes::Result ConveyorSync::start_catch_up(std::span<const axes::MotionState> start,
                                          std::span<const double> target, double feed_cont,
                                          std::span<const axes::Dynamics> dynamics) noexcept {
  // A catch-up not stepped yet may be re-planned (t_catch_ 0).
  const bool again = phase_ == SyncPhase::catching_up && t_catch_ == 0.0;
  if ((phase_ != SyncPhase::latched && !again) || start.size() != n_ || target.size() != n_ ||
      (!dynamics.empty() && dynamics.size() != n_))
    return axes::Result::error_invalid_input;
  std::array<CatchUpAxis, planner::kMaxAxes> in{};
  // FEED_CONT's direction: the catch-up's own, start to target over X/Y/Z (docs/conveyor.md).
  const planner::AxisVec u = catch_up_direction(start, target);
  for (std::size_t i = 0; i < n_; ++i) {
    in[i].start = start[i];
    in[i].target = target[i] + share_[i] * s_;
    in[i].conveying = share_[i];
    in[i].dynamics = dynamics.empty() ? axes_[i].dynamics : dynamics[i];
    // An axis the belt moves keeps NCSIM-CHAN-640 of A and J for the belt's own
    // changes, which ride on the catch-up as its deviation from the forecast (004 l.454).
    if (dynamics.empty() && share_[i] != 0.0 && reserve_ > 0.0) {
      in[i].dynamics.a_max *= 1.0 - reserve_;
      in[i].dynamics.d_max *= 1.0 - reserve_;
      in[i].dynamics.j_max *= 1.0 - reserve_;
    }
  }
  auto plan = [&](double f) {
    for (std::size_t i = 0; i < n_; ++i)
      in[i].v_relative = f * u[i];
    // The forecast belt moves at the master position's slope: the deviation from it then
    // starts without a velocity step (the reported v_ lags it while a compensated belt ramps).
    return catch_up_.plan(std::span(in.data(), n_), s_, v_slope_);
  };
  if (!(feed_cont > 0.0) || u == planner::AxisVec{}) feed_cont = 0.0;
  axes::Result r = plan(feed_cont);
  // "reduced as required" (004 l.284): no catch-up meets the target at
  // feed_cont (an axis would need more than its V): the largest relative velocity that plans.
  if (r != axes::Result::ok && feed_cont > 0.0 && plan(0.0) == axes::Result::ok) {
    double lo = 0.0;
    double hi = feed_cont;
    for (int iter = 0; iter < 40 && hi - lo > kRelTol * std::max(1.0, hi); ++iter) {
      const double mid = 0.5 * (lo + hi);
      (plan(mid) == axes::Result::ok ? lo : hi) = mid;
    }
    feed_cont = lo;
    r = plan(feed_cont);
  }
  if (r != axes::Result::ok) return r;
  v_relative_ = feed_cont;
  phase_ = SyncPhase::catching_up;
  t_catch_ = 0.0;
  for (std::size_t i = 0; i < n_; ++i)
    catch_sp_[i] = catch_up_.setpoint(i, 0.0, s_, v_frame_, a_);
  return r;
}

axes::Result ConveyorSync::start_departure(std::span<const axes::MotionState> start,
                                           std::span<const double> target,
                                           std::span<const axes::Dynamics> dynamics) noexcept {
  if ((phase_ != SyncPhase::leaving && phase_ != SyncPhase::off) || start.size() != n_ ||
      target.size() != n_ || (!dynamics.empty() && dynamics.size() != n_))
    return axes::Result::error_invalid_input;
  std::array<CatchUpAxis, planner::kMaxAxes> in{};
  for (std::size_t i = 0; i < n_; ++i) {
    in[i].start = start[i];
    in[i].target = target[i];
    // conveying 0: fixed targets in MCS; --- trafo: the TCP's dynamics under #TRAFO ON
    in[i].dynamics = dynamics.empty() ? axes_[i].dynamics : dynamics[i];
  }
  const axes::Result r = catch_up_.plan(std::span(in.data(), n_), 0.0, 0.0);
  if (r != axes::Result::ok) return r;
  v_relative_ = 0.0;  // the departure ends at rest (S-2)
  phase_ = SyncPhase::departing;
  t_catch_ = 0.0;
  for (std::size_t i = 0; i < n_; ++i)
    catch_sp_[i] = catch_up_.setpoint(i, 0.0, 0.0, 0.0, 0.0);
  return r;
}

planner::AxisVec ConveyorSync::catch_up_direction(std::span<const axes::MotionState> start,
                                                  std::span<const double> target) const noexcept {
  planner::AxisVec u{};
  double norm2 = 0.0;
  for (std::size_t i = 0; i < n_ && i < start.size() && i < target.size(); ++i) {
    if (axes_[i].xyz < 0) continue;
    u[i] = target[i] + share_[i] * s_ - start[i].p;
    norm2 += u[i] * u[i];
  }
  if (!(norm2 > 0.0)) return planner::AxisVec{};
  const double k = 1.0 / std::sqrt(norm2);
  for (double& c : u)
    c *= k;
  return u;
}

std::optional<double> ConveyorSync::handover_lag() const noexcept {
  if (!handover_due()) return std::nullopt;
  return std::clamp(catch_up_.duration() - t_catch_, 0.0, t_cycle_);
}

axes::Setpoint ConveyorSync::catch_up_setpoint(std::size_t i) const noexcept {
  return catch_sp_[i];
}

std::optional<SyncError> ConveyorSync::workspace(const Eigen::Vector3d& p_mcs) const {
  if (!synchronised_) return std::nullopt;
  if (hold_) {  // the hold line + P-CHAN-00367
    if (auto m = hold_->check(p_mcs[hold_->config().coord]))
      return SyncError{kWorkspaceHoldId, std::move(*m)};
  }
  const auto v = check_workspace(box_, frame_.direction(), p_mcs);
  if (!v) return std::nullopt;
  static constexpr const char* kNames[3] = {"X", "Y", "Z"};
  const std::string what = kNames[v->coord] + (" " + core::human(v->value)) +
                           " mm beyond the conveyor workspace's " + (v->upper ? "upper" : "lower") +
                           " face " + core::human(v->limit) + " mm";
  switch (v->face) {
    case WorkspaceFace::conveying:
      return SyncError{kWorkspaceConveyingId,
                       what + " in the conveying direction while synchronised"};
    case WorkspaceFace::side:
      return SyncError{kWorkspaceSideId, what + " (a side face) while synchronised"};
    case WorkspaceFace::against:
      break;
  }
  return SyncError{kWorkspaceHoldId, what + " against the conveying direction while synchronised"};
}

double ConveyorSync::workspace_cap(HoldState st) noexcept {
  if (!hold_) return WorkspaceHold::kNone;
  if (!synchronised_ || phase_ != SyncPhase::tracking) {
    hold_->reset();
    return WorkspaceHold::kNone;
  }
  st.travel = s_;
  st.belt_v = v_;
  st.t_cycle = t_cycle_;
  return hold_->decide(st);
}

MasterDisplay ConveyorSync::display() const noexcept {
  if (port_ == nullptr) return MasterDisplay{};
  return master_display(frame_, port_->measured(), port_->master());
}

}  // namespace ncsim::tracking
