// ipo/channel_static: the static processing unit on the channel side (issue 14; seed 004
// §2.1.6; docs/conveyor.md "Static processing unit").
//
// The adapter plans every synchronised block of a static unit (P-CHAN-00364 = 1) with the feed
// whose X component is kXvPlanFactor * CONV_VEL (ipo/x_virtual.hpp). Each cycle while the
// channel tracks the belt, the path override is the belt's master velocity (filtered, delay
// compensated: what the PCS1 frame follows) over that planned velocity, so the path's X
// component equals the belt's and the virtual X stands still in MCS; "the feed rate ... cannot
// be influenced independently" (004 l.438): the operator's override is set aside until the
// tracking ends and then restored.

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "ipo/channel.hpp"
#include "ipo/x_virtual.hpp"

namespace ncsim::ipo {

namespace {

/// Smallest override change passed on [1]: the belt's measurement noise must not replan the
/// path every cycle (2e-4 of 300 mm/s is 0.06 mm/s).
constexpr double kOverrideStep = 2e-4;
/// The plan's X component may exceed the belt's by this much before the cap acts [1]: a
/// straight block's belt feed gives exactly the belt's, to rounding.
constexpr double kCapSlack = 1e-9;
/// Longest look-ahead of the cap [s].
constexpr double kLeadMax = 0.05;
/// Share of the entry's d / j the cap looks ahead (decision, docs/conveyor.md "Blends on a
/// static unit": measured on the test contours, 0 -> 0.064 mm of virtual X, 0.15 -> 0.023 mm,
/// 0.25 -> 0.058 mm).
constexpr double kLeadShare = 0.15;

}  // namespace

void Channel::static_override() noexcept {
  if (!sync_ || !static_unit_) return;
  if (sync_->phase() != SyncPhase::tracking) {
    if (operator_override_) {
      try {
        ipo_.set_override(*operator_override_);  // it was accepted before: in range
      } catch (...) {
        std::abort();
      }
      operator_override_.reset();
    }
    return;
  }
  if (!operator_override_) operator_override_ = ipo_.override_factor();
  const double belt = sync_->frame().sign() * sync_->display().v_master_comp;  // [mm/s]
  const double planned = kXvPlanFactor * sync_->conv_vel();
  const double f = planned > 0.0 ? std::clamp(belt / planned, 0.0, 1.0) : 0.0;
  if (std::fabs(f - ipo_.override_factor()) > kOverrideStep ||
      (f == 0.0) != (ipo_.override_factor() == 0.0)) {
    try {
      ipo_.set_override(f);
    } catch (...) {
      std::abort();  // every override type accepts 0 .. 1
    }
  }
  // --- static-blend: where the plan's X component would be faster than the belt's (a tolerance
  // ball, whose X share varies, and the blocks beside it, whose feed was raised for it:
  // ipo/x_virtual.hpp blend_belt_feed), the path velocity is capped at belt / |dX/ds| a little
  // ahead of the path. The cap is a jerk-limited replan that acts inside
  // the ball too (PathInterpolator::set_velocity_cap); the workspace hold's cap, set after each
  // cycle (Channel::sync_workspace_cap), is kept when it is lower.
  const Cycle& c = ipo_.cycle();
  const planner::PlannedSegment* e = ipo_.active_entry();
  if (c.activity != Activity::motion || e == nullptr || c.programmed == nullptr || planned <= 0.0)
    return;
  int x = -1;
  for (std::size_t i = 0; i < sync_->axis_count() && x < 0; ++i)
    if (sync_->xyz(i) == 0) x = static_cast<int>(i);
  if (x < 0) return;
  // The X share a little ahead, so that the jerk-limited slow-down starts in time: at
  // kLeadShare of the time the entry's jerk needs to build its deceleration (d / j), at least
  // the next cycle's point.
  const planner::Chain& path = e->segment.path;
  const planner::PreparedSegment* next = ipo_.queued_entry(0);
  const double t = t_cycle();
  const double lead = std::clamp(e->d_max / e->j_max, t, kLeadMax);  // [s]
  double s1 = c.path.s + c.path.v * std::max(t, kLeadShare * lead);
  const planner::Chain* on = &path;
  if (s1 > path.length()) {
    if (next == nullptr) return;
    s1 -= path.length();
    on = &next->path;
  }
  const double share = std::fabs(on->at(s1).d1[static_cast<std::size_t>(x)]);
  const double feed = c.programmed->feed;  // [mm/s] the part's belt feed (raised at a ball)
  if (!(share > 0.0) || feed * share <= planned * (1.0 + kCapSlack)) return;
  ipo_.set_velocity_cap(std::min(ipo_.velocity_cap(), std::max(belt, 0.0) / share));
}

}  // namespace ncsim::ipo
