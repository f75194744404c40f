// channel/channel_workspace: ConveyorTracking per cycle: the conveyor world's step, the conveyor
// workspace and the channel's side of the workspace hold against the conveying direction
// (tracking/workspace_hold.hpp; docs/conveyor.md "Workspace: the hold methods"): after each
// cycle the hold decides on the path state of that cycle, and its cap acts on the interpolator
// from the next one (PathOverride::set_velocity_cap, a jerk-limited replan). The hold looks
// across block ends: the active entry and the look-ahead window's next entries
// (PathInterpolator::queued_entry, at most kHoldAhead).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include "channel/conveyor_tracking.hpp"
#include "core/number_text.hpp"
#include "core/tolerance.hpp"
#include "tracking/sync_checks.hpp"

namespace ncsim::channel {

bool ConveyorTracking::world_step(const ipo::Cycle& c, scenario::Player* player) noexcept {
  if (!sync_) return true;
  if (auto e = sync_->step(c.t)) {
    raise(error_, e->id.c_str(), std::move(e->message), c, -1);
    return false;
  }
  // The V.E. values of the workpiece just measured go to the world's store, where the next
  // barrier reads them (docs/conveyor.md "Wiring").
  const conveyor::Port* port = sync_->port();
  if (port != nullptr && player != nullptr && port->last_latch().workpiece != ve_workpiece_) {
    const conveyor::LatchInfo& l = port->last_latch();
    ve_workpiece_ = l.workpiece;
    try {
      for (const auto& [name, value] : l.ve)
        player->ve().write(name, value);
    } catch (...) {
      std::abort();  // out of memory writing a V.E. value
    }
  }
  return true;
}

bool ConveyorTracking::workspace(const ipo::Cycle& c) noexcept {
  if (!sync_) return true;
  return check_workspace(c) && workspace_cap(c);
}

bool ConveyorTracking::workspace_cap(const ipo::Cycle& c) noexcept {
  tracking::HoldState st;
  std::array<tracking::HoldEntry, tracking::kHoldAhead>
      ahead{};  // the look-ahead window's next entries
  const planner::PlannedSegment* e = ipo_.active_entry();
  if (c.activity == ipo::Activity::motion && e != nullptr && c.programmed != nullptr) {
    st.path = &e->segment.path;
    st.s = c.path.s;
    st.v = c.path.v;
    st.a = c.path.a;
    st.feed = c.feed;
    st.line = c.line;
    st.d_max = e->d_max;
    st.j_max = e->j_max;
    st.stops = e->segment.stop != planner::StopReason::none;
    for (std::size_t k = 0; k < ahead.size(); ++k) {
      const planner::PreparedSegment* next = ipo_.queued_entry(k);
      if (next == nullptr) break;
      ahead[k] = tracking::HoldEntry{&next->path, next->limits.v_programmed,
                                     next->stop != planner::StopReason::none};
      st.ahead_count = k + 1;
    }
    st.ahead = ahead.data();
  }
  const double cap = sync_->workspace_cap(st);
  ipo_.path_override().set_velocity_cap(cap);
  sync_belt_cap(c);  // kept when it is lower than the hold's
  // A belt that stops while the hold caps the path: the cap follows it to 0 and the tool waits
  // with the belt (it stands in MCS and on the workpiece); the belt's restart releases it. A
  // belt that never restarts ends the run after ncsim's wait limit with NC9081.
  const tracking::WorkspaceHold* h = sync_->hold();
  if (h != nullptr && h->capped() && cap == 0.0 && c.path.v == 0.0) {
    if (++hold_stood_ > measure_wait_cycles_max_) {
      try {
        raise(error_, kHoldBeltStoodId,
              "the belt stood for " + core::human(measured_value_wait_max_) +
                  " s (ncsim's limit) while the workspace hold (P-AXIS-00555, "
                  "hold_limit_vel_factor P-CHAN-00366) kept the tool at the hold line " +
                  core::human(h->config().line) + " mm: the belt was not restarted",
              c, -1);
      } catch (...) {
        std::abort();
      }
      return false;
    }
  } else {
    hold_stood_ = 0;
  }
  return true;
}

// (004 l.317-319; docs/conveyor.md "velocity split"): a PCS1 line against the
// belt is planned with v_max + CONV_VEL on the axes it moves against the conveying direction
// (program/program_sync.cpp); in PCS0 an axis moves at v_path x' + w, w the belt's velocity on it,
// within v_max only while the belt runs at CONV_VEL or faster. A slower belt (a ramp, a stop)
// caps the path at min over the axes of (v_max - sign(x') w) / |x'| a little ahead, where that
// is below the segment's own velocity limit (so a plan that fits any belt up to 1.10 CONV_VEL,
// every block along the belt and every curve, is never touched). The cap is a jerk-limited
// replan (PathOverride::set_velocity_cap); a cap that falls at r [mm/s^2] is followed
// r^2 / (2 j) behind, so the belt is forecast r / (2 j) ahead with its acceleration (as the
// static unit's cap, channel_static.cpp). The belt's own deceleration beyond the path's d_max
// cannot be followed: the residual the tests measure.
void ConveyorTracking::sync_belt_cap(const ipo::Cycle& c) noexcept {
  constexpr double kSlack = kRelTol;   // [1] a cap within this of the segment's limit is none
  constexpr double kLeadMax = 0.05;    // [s] longest forecast
  constexpr double kCycleShare = 0.5;  // [1] the cap acts on the whole next cycle: its middle
  if (static_unit_ || sync_->phase() != tracking::SyncPhase::tracking) return;
  // Every block fits a belt between CONV_VEL (a line against it was planned for that) and
  // 1.10 CONV_VEL (the symmetric split's, 50653's bound): with the belt there over the longest
  // forecast, no cap can bind and the path is not evaluated (the per-cycle common case).
  const double u = sync_->belt_velocity();
  const double du = std::fabs(sync_->belt_acceleration()) * kLeadMax;
  const double conv_vel = sync_->conv_vel();
  // (A belt at CONV_VEL measured a rounding below it caps nothing either: kSlack below.)
  if (u - du >= conv_vel * (1.0 - tracking::kBeltVelocityRounding) &&
      u + du <= tracking::kBeltVelocityTolerance * conv_vel)
    return;
  const planner::PlannedSegment* e = ipo_.active_entry();
  if (c.activity != ipo::Activity::motion || e == nullptr || c.programmed == nullptr ||
      c.programmed->transformed)
    return;
  const planner::Chain& path = e->segment.path;
  const planner::PreparedSegment* next = ipo_.queued_entry(0);
  const double v = c.path.v;  // [mm/s]
  planner::PathPoint q;
  double level = 0.0;  // the velocity limit of the segment q is on [mm/s]
  const auto point = [&](double s) {
    if (s <= path.length()) {
      q = path.at(s);
      level = e->segment.limits.v_max;
      return true;
    }
    if (next == nullptr) return false;
    q = next->path.at(std::min(s - path.length(), next->path.length()));
    level = next->limits.v_max;
    return true;
  };
  const std::size_t n = std::min(axes_.size(), sync_->axis_count());
  // The cap at q for a belt forecast `lead` [s] ahead, and how fast it falls [mm/s^2].
  const auto cap_at = [&](double lead, double& rate) {
    double cap = std::numeric_limits<double>::infinity();
    rate = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double d1 = q.d1[i];
      const int k = sync_->xyz(i);  // an axis without a share of the belt keeps its plan
      if (d1 == 0.0 || k < 0 || k > 2 || sync_->frame().direction()[k] == 0.0) continue;
      const double w = sync_->offset_v(i);
      const double sgn = d1 > 0.0 ? 1.0 : -1.0;
      const double w_ahead = w + sync_->offset_a(i) * lead;
      const double ci = std::max(after_.limits(i).v_max - sgn * w_ahead, 0.0) / std::fabs(d1);
      if (ci < cap) {
        cap = ci;
        rate = std::max(0.0, sgn * sync_->offset_a(i)) / std::fabs(d1);
      }
    }
    return cap;
  };
  const double s0 = c.path.s + v * kCycleShare * t_cycle();
  double lead = 0.0, rate = 0.0;
  const bool jerk = std::isfinite(e->j_max) && e->j_max > 0.0;
  for (int k = 0; k < 2 && jerk; ++k) {
    if (!point(s0 + v * lead)) return;
    cap_at(lead, rate);
    lead = std::min(rate / (2.0 * e->j_max), kLeadMax);
  }
  if (!point(s0 + v * lead)) return;
  const double cap = cap_at(lead, rate);
  if (!(cap < level * (1.0 - kSlack))) return;
  ipo_.path_override().set_velocity_cap(std::min(ipo_.path_override().velocity_cap(), cap));
}

bool ConveyorTracking::hold_waits() const noexcept {
  const tracking::WorkspaceHold* h = sync_ ? sync_->hold() : nullptr;
  return h != nullptr && h->capped() && h->cap() == 0.0;
}

}  // namespace ncsim::channel
