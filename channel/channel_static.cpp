// channel/channel_static: the static processing unit on the channel side (issue 14; seed 004
// §2.1.6; docs/conveyor.md "Static processing unit").
//
// The adapter plans every synchronised block of a static unit (P-CHAN-00364 = 1) with the feed
// whose X component is kXvPlanFactor * CONV_VEL (tracking/x_virtual.hpp). Each cycle while the
// channel tracks the belt, the path override is the belt's master velocity (filtered, delay
// compensated: what the PCS1 frame follows) over that planned velocity, so the path's X
// component equals the belt's and the virtual X stands still in MCS; "the feed rate ... cannot
// be influenced independently" (004 l.438): the operator's override is set aside until the
// tracking ends and then restored.

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "channel/conveyor_tracking.hpp"
#include "core/tolerance.hpp"
#include "tracking/x_virtual.hpp"

namespace ncsim::channel {

namespace {

/// Smallest override change passed on [1]: the belt's measurement noise must not replan the
/// path every cycle (2e-4 of 300 mm/s is 0.06 mm/s).
constexpr double kOverrideStep = 2e-4;
/// The plan's X component may exceed the belt's by this much before the cap acts [1]: a
/// straight block's belt feed gives exactly the belt's, to rounding.
constexpr double kCapSlack = kRelTol;
/// Longest look-ahead of the cap [s].
constexpr double kLeadMax = 0.05;
/// Share of the next cycle the cap looks ahead besides the replan's lag [1] (the cap acts on the
/// whole next cycle: its middle).
constexpr double kCycleShare = 0.5;

}  // namespace

void ConveyorTracking::static_override() noexcept {
  if (!sync_ || !static_unit_) return;
  if (sync_->phase() != tracking::SyncPhase::tracking) {
    if (operator_override_) {
      try {
        ipo_.path_override().set_override(*operator_override_);  // it was accepted before: in range
      } catch (...) {
        std::abort();
      }
      operator_override_.reset();
    }
    return;
  }
  if (!operator_override_) operator_override_ = ipo_.path_override().override_factor();
  const double belt = sync_->frame().sign() * sync_->display().v_master_comp;  // [mm/s]
  const double planned = tracking::kXvPlanFactor * sync_->conv_vel();
  const double f = planned > 0.0 ? std::clamp(belt / planned, 0.0, 1.0) : 0.0;
  if (std::fabs(f - ipo_.path_override().override_factor()) > kOverrideStep ||
      (f == 0.0) != (ipo_.path_override().override_factor() == 0.0)) {
    try {
      ipo_.path_override().set_override(f);
    } catch (...) {
      std::abort();  // every override type accepts 0 .. 1
    }
  }
  // where the plan's X component would be faster than the belt's (a tolerance
  // ball, whose X share varies, and the blocks beside it, whose feed was raised for it:
  // tracking/x_virtual.hpp blend_belt_feed), the path velocity is capped at belt / |dX/ds| a little
  // ahead of the path. The cap is a jerk-limited replan that acts inside
  // the ball too (PathOverride::set_velocity_cap); the workspace hold's cap, set after each
  // cycle (ConveyorTracking::workspace_cap), is kept when it is lower.
  const ipo::Cycle& c = ipo_.cycle();
  const planner::PlannedSegment* e = ipo_.active_entry();
  if (c.activity != ipo::Activity::motion || e == nullptr || c.programmed == nullptr ||
      planned <= 0.0)
    return;
  int x = -1;
  for (std::size_t i = 0; i < sync_->axis_count() && x < 0; ++i)
    if (sync_->xyz(i) == 0) x = static_cast<int>(i);
  if (x < 0) return;
  // the velocity the path must have is v_req(s) = belt / |dX/ds|. The cap is a
  // jerk-limited replan towards its level; a level that moves at r = dv_req/dt is followed
  // r^2 / (2 j) behind (the replan settles where the acceleration it has, r, takes r / j to
  // bring to 0). So the cap is v_req where the path will be r / (2 j) later than the middle of
  // the next cycle: the lag and the look-ahead cancel, whether v_req falls or rises (r from
  // the X share's derivative, sign(x') x'', at the path and once more at that point ahead).
  const planner::Chain& path = e->segment.path;
  const planner::PreparedSegment* next = ipo_.queued_entry(0);
  const auto xi = static_cast<std::size_t>(x);
  const double v = c.path.v;  // [mm/s]
  planner::PathPoint q;
  const auto point = [&](double s) {
    if (s <= path.length()) {
      q = path.at(s);
      return true;
    }
    if (next == nullptr) return false;
    q = next->path.at(s - path.length());
    return true;
  };
  // |dv_req/dt| = belt |x''| v / x'^2 at q [mm/s^2]
  const auto rate = [&] {
    const double share = std::fabs(q.d1[xi]);
    return share > 0.0 ? std::max(belt, 0.0) * std::fabs(q.d2[xi]) * v / (share * share) : 0.0;
  };
  const double s0 = c.path.s + v * kCycleShare * t_cycle();
  double lag = 0.0;  // [s]
  if (std::isfinite(e->j_max) && e->j_max > 0.0)
    for (int k = 0; k < 2; ++k) {
      if (!point(s0 + v * lag)) return;
      lag = std::min(rate() / (2.0 * e->j_max), kLeadMax);
    }
  if (!point(s0 + v * lag)) return;
  const double share = std::fabs(q.d1[xi]);
  const double feed = c.programmed->feed;  // [mm/s] the part's belt feed (raised at a ball)
  if (!(share > 0.0) || feed * share <= planned * (1.0 + kCapSlack)) return;
  ipo_.path_override().set_velocity_cap(
      std::min(ipo_.path_override().velocity_cap(), std::max(belt, 0.0) / share));
}

}  // namespace ncsim::channel
