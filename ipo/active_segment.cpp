// ipo/active_segment: the active entry and its plan under override (see the header and
// docs/ipo.md "Override and feed hold").

#include "ipo/active_segment.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ncsim::ipo {

namespace {

/// A PCS1 block planned with the belt's share taken off its limits: the velocity split of the
/// axes (Move::belt, S-5) or the joints' shares under #TRAFO ON (Move::belt_joints). Raised
/// above 100 % with the axes' own limits, the belt would come on top (docs/conveyor.md
/// "Machining in PCS1", "An override above 100 %").
bool belt_capped(const planner::Move& m) noexcept {
  return m.belt_joints != nullptr ||
         std::any_of(m.belt.begin(), m.belt.end(), [](double v) { return v > 0.0; });
}

/// True when s [mm] lies inside a tolerance-ball blend of `path`.
bool in_ball(const planner::Chain& path, double s) noexcept {
  double end = 0.0;
  for (std::size_t p = 0; p < path.parts(); ++p) {
    const planner::Segment& part = path.part(p);
    const double start = end;
    end += part.length();
    if (s < start) return false;
    if (s <= end && part.kind() == planner::SegmentKind::blend) return true;
  }
  return false;
}

}  // namespace

bool ActiveSegment::begin(planner::PlannedSegment&& next, double f, double cap) noexcept {
  cur_ = std::move(next);
  prof_ = planner::profile(cur_);
  t_in_ = 0.0;
  s_sampled_ = 0.0;
  t100_prev_ = 0.0;
  active_ = true;
  raised_ready_ = false;
  has_ball_ = false;
  for (std::size_t p = 0; p < cur_.segment.path.parts(); ++p)
    has_ball_ = has_ball_ || cur_.segment.path.part(p).kind() == planner::SegmentKind::blend;
  const bool planned = plan_entry(f, cap);
  interval_jerk_limited_ = interval_jerk_limited_ && std::isfinite(cur_.segment.limits.j_max);
  return planned;
}

void ActiveSegment::start_cycle(double f, double cap) noexcept {
  interval_jerk_limited_ = std::isfinite(cur_.segment.limits.j_max);
  lost_ = 0.0;
  if (f == plan_factor_ && cap == plan_cap_) return;
  // A change of the override waits until the tolerance ball is left (000 l.366); a stop
  // (override 0, feed hold) has priority (002 l.391) and acts at once, and so does the
  // release of a stop (a path standing in a ball would never leave it); a cap acts at once,
  // as a stop does.
  const planner::PathState st = plan_at(plan_, t_in_);
  if (f == 0.0 || plan_factor_ == 0.0 || !has_ball_ || !in_ball(cur_.segment.path, st.s) ||
      cap != plan_cap_)
    replan(f, cap, st.s, st.v, st.a);
}

void ActiveSegment::advance_to(double t_new) noexcept {
  if (on_plan_) {
    t100_prev_ = t_new;
  } else {
    const double length = cur_.segment.path.length();
    const double s = t_new >= dur_ && !plan_.hold ? length : plan_at(plan_, t_new).s;
    const double t_ref = profile_time_at(prof_, s);  // the 100 % profile's time at s
    lost_ += (t_new - t_in_) - (t_ref - t100_prev_);
    t100_prev_ = t_ref;
  }
  t_in_ = t_new;
}

void ActiveSegment::arrive() noexcept {
  v_arrive_ = on_plan_ ? cur_.v_exit : plan_.v_exit();
  a_arrive_ = on_plan_ ? cur_.a_exit : 0.0;
}

void ActiveSegment::stop() noexcept {
  active_ = false;
  t_in_ = dur_;
  v_arrive_ = 0.0;
  a_arrive_ = 0.0;
}

planner::PathState ActiveSegment::state() const noexcept {
  const double length = cur_.segment.path.length();
  planner::PathState ps = on_plan_ ? planner::profile_at(prof_, t_in_) : plan_at(plan_, t_in_);
  ps.s = t_in_ >= dur_ && !plan_.hold ? length : std::clamp(ps.s, 0.0, length);
  return ps;
}

bool ActiveSegment::plan_entry(double f, double cap) noexcept {
  const bool as_planned = v_arrive_ == cur_.v_entry && a_arrive_ == cur_.a_entry;
  // At 100 % every type asks for the look-ahead's own profile: follow it unchanged.
  const auto follow = [&] {
    plan_ = PathPlan{prof_, 0.0, false, cur_.segment.path.length()};
    v_ceiling_ = cur_.segment.limits.v_max;
    a_ceiling_ = std::max(cur_.a_max, cur_.d_max);
    on_plan_ = true;
    plan_factor_ = 1.0;
    plan_cap_ = cap;
    dur_ = prof_.time();
    return true;
  };
  if (f == 1.0 && as_planned && !(cap < prof_.v_level)) return follow();
  if (replan(f, cap, 0.0, v_arrive_, a_arrive_)) return true;
  // Above 100 % the raised limits can be tighter than the planned ones: fall back to 100 %
  // (the change is retried every cycle).
  if (f > 1.0 && replan(1.0, cap, 0.0, v_arrive_, a_arrive_)) return true;
  // A ramp carried through the joint that no plan ending at a = 0 can take over within this
  // entry goes on as planned; the change is retried every cycle (docs/ipo.md "Override and
  // feed hold").
  return a_arrive_ != 0.0 && as_planned && follow();
}

bool ActiveSegment::replan(double f, double cap, double s, double v, double a) noexcept {
  const planner::PathLimits& lim = cur_.segment.limits;
  PlanRequest r;
  r.v0 = v;
  r.a0 = a;
  r.length = cur_.segment.path.length() - s;
  r.a = cur_.a_max;
  r.d = cur_.d_max;
  r.j = cur_.j_max;
  double v_cap = lim.v_max;
  // Above 100 %, and after it while the path still runs above the planned cap (an override
  // lowered from above 100 %), the limits at the raised velocity hold: the planned a, d, j
  // are those at the planned cap, and on a curve less is left at a higher velocity.
  const bool raised = f > 1.0 || v > lim.v_max;
  if (raised && type_ == OverrideType::reduced_above_100) {
    if (!raised_ready_) {
      // Under #TRAFO ON the joints' G00 rule (ipo/override_trafo.cpp). A PCS1 block keeps its
      // 100 % plan where the belt shares its joints' or axes' velocity (belt_capped).
      const planner::Move& prog = queue_.programmed(cur_.segment.path.line_at(0.0));
      if (belt_capped(prog))
        raised_ = RaisedLimits{lim.v_max, cur_.a_max, cur_.d_max, cur_.j_max};
      else
        raised_ = joints_ && prog.transformed ? raised_limits_joints(cur_, *joints_)
                                              : raised_limits(cur_, axes_);
      raised_ready_ = true;
    }
    if (f > 1.0) v_cap = raised_.v_max;
    r.a = raised_.a;
    r.d = raised_.d;
    r.j = raised_.j;
  }
  r.level = override_level(type_, f, prof_.v_level, lim.v_programmed, v_cap);
  // Below a carried brake a plan ending at a = 0 takes the exit the plan with a = 0 at the
  // joint had (the next entry brakes on from there: docs/ipo.md).
  const bool brake_on = cur_.shape == planner::ProfileShape::carry_down ||
                        cur_.shape == planner::ProfileShape::brake_through;
  const double exit_100 = brake_on ? cur_.v_exit_zero : cur_.v_exit;
  r.exit_wanted = override_exit(type_, f, exit_100, lim.v_programmed);
  r.exit_cap = exit_100;
  // The velocity cap from outside lowers the level and the exit (never below 0).
  r.level = std::min(r.level, cap);
  r.exit_wanted = std::min(r.exit_wanted, cap);
  PathPlan np;
  if (!make_plan(r, np)) return false;
  plan_cap_ = cap;
  v_ceiling_ = std::max({lim.v_max, r.level, v});
  a_ceiling_ = std::max({r.a, r.d, std::abs(a)});
  np.s0 = s;
  plan_ = np;
  t_in_ = 0.0;
  dur_ = plan_.time();
  on_plan_ = false;
  plan_factor_ = f;
  return true;
}

}  // namespace ncsim::ipo
