// tracking/sync_entry: the hand-over from a moving catch-up to the path (see the header).

#include "tracking/sync_entry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncsim::tracking {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

planner::PathPoint catch_up_end(const planner::AxisVec& u, const planner::PathPoint& at) {
  planner::PathPoint p;
  p.x = at.x;  // the meeting point is the block's start
  p.d1 = u;    // relative motion straight along u at constant velocity: no curvature
  return p;
}

}  // namespace

SyncEntry sync_entry(double asked, const planner::AxisVec& u, const planner::PreparedSegment* first,
                     double entry_cap, std::span<const planner::AxisLimits> axes,
                     double t_cycle) noexcept {
  SyncEntry e;
  if (first == nullptr || !(asked > 0.0) || u == planner::AxisVec{}) return e;
  const planner::PathPoint out = first->path.at(0.0);
  const planner::PathPoint in = catch_up_end(u, out);
  const std::size_t n = std::min(axes.size(), planner::kMaxAxes);
  e.cls = planner::classify(in, out, n, first->path.metric());
  e.v_corner = kInf;
  switch (e.cls) {
    case planner::TransitionClass::c0:
      e.v_corner = planner::velojump_velocity(in.d1, out.d1, axes.first(n), t_cycle);
      e.rule = planner::LinkRule::velojump;
      break;
    case planner::TransitionClass::c1:  // the slope is jerk-limited while synchronised
      e.v_corner = planner::c1_velocity(in.d2, out.d2, axes.first(n), t_cycle);
      e.rule = planner::LinkRule::c1_jerk;
      break;
    case planner::TransitionClass::c2:
      break;
  }
  e.v_entry_cap = std::max(0.0, entry_cap);
  e.v = asked;
  e.limit = EntryLimit::asked;
  if (e.v_corner < e.v) {
    e.v = e.v_corner;
    e.limit = EntryLimit::corner;
  }
  if (e.v_entry_cap < e.v) {
    e.v = e.v_entry_cap;
    e.limit = EntryLimit::entry_cap;
  }
  if (!std::isfinite(e.v)) e.v = 0.0;  // unreachable: the entry cap is finite
  return e;
}

ipo::Joint sync_entry_joint(const SyncEntry& entry, const planner::AxisVec& u,
                            const planner::PreparedSegment& first, double v, double t,
                            std::uint32_t line, std::size_t axis_count) noexcept {
  const planner::PathPoint out = first.path.at(0.0);
  ipo::Joint jt;
  jt.t = t;
  jt.line = line;
  jt.cls = entry.cls;
  jt.stop = planner::StopReason::none;
  jt.jerk_limited = true;
  jt.v = v;
  jt.rule =
      entry.cls == planner::TransitionClass::c2 ? planner::LinkRule::segment_caps : entry.rule;
  for (std::size_t i = 0; i < std::min(axis_count, planner::kMaxAxes); ++i) {
    jt.dv[i] = v * (out.d1[i] - u[i]);
    jt.da[i] = v * v * out.d2[i];
  }
  return jt;
}

}  // namespace ncsim::tracking
