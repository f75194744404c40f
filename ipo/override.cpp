// ipo/override: override levels and run-time velocity plans (see the header, docs/ipo.md).

#include "ipo/override.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/tolerance.hpp"
#include "planner/limits.hpp"
#include "planner/path.hpp"

namespace ncsim::ipo {

namespace {

/// Grid points of the searches over exit velocities and levels (then bisection).
constexpr int kGrid = 24;
/// Bisection steps after the grid (2^-50 of a grid interval).
constexpr int kBisect = 50;
/// Relative width [1] (at least as much absolute) at which those bisections stop.
constexpr double kBisectWidthRel = 1e-13;

/// Distance of the time-optimal change (v0, a0) -> (v1, 0).
double ramp_distance(double v0, double a0, double v1, const PlanRequest& r) noexcept {
  const jerk::Ramp ramp = jerk::velocity_ramp(v0, a0, v1, r.a, r.d, r.j);
  return jerk::distance(v0, a0, ramp);
}

/// The kernel's ramps agree with the lengths to rounding, not exactly (as in the look-ahead):
/// relative kRelRounding, and as much in mm, so that a length of 0 has a tolerance too.
bool within(double distance, double length) noexcept {
  return distance <= length * (1.0 + kRelRounding) + kRelRounding;
}

/// Lowest x in [lo, hi] with fits(x), assuming fits(hi) may or may not hold; the fitting set
/// may be two intervals (a jerk-limited slow-down's distance first grows, then shrinks as the
/// end velocity rises), so a grid finds the first fitting point and bisection its lower edge.
template <class Fits>
bool lowest_fitting(double lo, double hi, const Fits& fits, double& out) noexcept {
  if (fits(lo)) {
    out = lo;
    return true;
  }
  double prev = lo;
  for (int k = 1; k <= kGrid; ++k) {
    const double x = k == kGrid ? hi : lo + (hi - lo) * k / kGrid;
    if (!fits(x)) {
      prev = x;
      continue;
    }
    double bad = prev;
    double good = x;
    for (int i = 0; i < kBisect && good - bad > kBisectWidthRel * std::max(1.0, good); ++i) {
      const double mid = 0.5 * (bad + good);
      (fits(mid) ? good : bad) = mid;
    }
    out = good;
    return true;
  }
  return false;
}

/// Highest x in [lo, hi] with fits(x); fits(lo) must hold.
template <class Fits>
double highest_fitting(double lo, double hi, const Fits& fits) noexcept {
  if (fits(hi)) return hi;
  double prev = hi;
  for (int k = 1; k <= kGrid; ++k) {
    const double x = k == kGrid ? lo : hi - (hi - lo) * k / kGrid;
    if (!fits(x)) {
      prev = x;
      continue;
    }
    double good = x;
    double bad = prev;
    for (int i = 0; i < kBisect && bad - good > kBisectWidthRel * std::max(1.0, bad); ++i) {
      const double mid = 0.5 * (bad + good);
      (fits(mid) ? good : bad) = mid;
    }
    return good;
  }
  return lo;
}

}  // namespace

double max_override(OverrideType type) noexcept {
  return type == OverrideType::reduced_above_100 ? kMaxOverride : 1.0;
}

const char* override_type_name(OverrideType type) noexcept {
  switch (type) {
    case OverrideType::reduced:
      return "REDUCED";
    case OverrideType::original:
      return "ORIGINAL";
    case OverrideType::reduced_above_100:
      return "REDUCED_ABOVE_100";
  }
  return "?";
}

double override_level(OverrideType type, double factor, double level_100, double v_programmed,
                      double raised_cap) noexcept {
  switch (type) {
    case OverrideType::reduced:
      return std::min(factor, 1.0) * level_100;
    case OverrideType::original:
      // 000 l.357: based on the programmed velocity; the segment maximum only limits.
      return std::min(std::min(factor, 1.0) * v_programmed, level_100);
    case OverrideType::reduced_above_100:
      if (factor <= 1.0) return factor * level_100;
      return std::max(level_100, std::min(factor * level_100, raised_cap));
  }
  return level_100;
}

double override_exit(OverrideType type, double factor, double exit_100,
                     double v_programmed) noexcept {
  if (type == OverrideType::original) return std::min(exit_100, factor * v_programmed);
  return std::min(exit_100, factor * exit_100);
}

RaisedLimits raised_limits(const planner::PlannedSegment& entry,
                           std::span<const planner::AxisLimits> axes) noexcept {
  RaisedLimits out{entry.segment.limits.v_max, entry.a_max, entry.d_max, entry.j_max};
  const planner::Chain& path = entry.segment.path;
  const std::size_t n = std::min<std::size_t>(path.axis_count(), axes.size());
  planner::DerivativeBounds b;
  b.curvature = 0.0;
  b.metric = ~planner::AxisMask{0};
  for (std::size_t p = 0; p < path.parts(); ++p) {
    const planner::DerivativeBounds pb = path.part(p).bounds();
    for (std::size_t i = 0; i < n; ++i) {
      b.d1[i] = std::max(b.d1[i], pb.d1[i]);
      b.d2[i] = std::max(b.d2[i], pb.d2[i]);
      b.d3[i] = std::max(b.d3[i], pb.d3[i]);
    }
    b.curvature = std::max(b.curvature, pb.curvature);  // the orthogonal budget of every part
    b.metric &= pb.metric;
  }
  // G00 rule (000 l.360): each axis at MIN(rapid, reference, maximum) along its share.
  double rapid = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const planner::AxisLimits& ax = axes[i];
    if (b.d1[i] > kTiny)
      rapid = std::min(rapid, std::min({ax.v_rapid, ax.v_reference, ax.v_max}) / b.d1[i]);
  }
  if (!std::isfinite(rapid)) return out;
  const bool jerk = std::isfinite(entry.segment.limits.j_max);
  const planner::PathLimits lim = planner::limits_from_bounds(b, axes.first(n), rapid, jerk);
  if (!(lim.v_max > out.v_max)) return out;  // nothing to gain
  out.v_max = lim.v_max;
  out.a = std::min(out.a, lim.a_max);
  out.d = std::min(out.d, lim.d_max);
  if (std::isfinite(lim.j_max)) out.j = std::min(out.j, lim.j_max);
  if (!(out.a > 0.0) || !(out.d > 0.0) || !(out.j > 0.0))
    return RaisedLimits{entry.segment.limits.v_max, entry.a_max, entry.d_max, entry.j_max};
  return out;
}

double PathPlan::v_exit() const noexcept {
  if (hold) return 0.0;
  if (profile.t_first < profile.first.time() || profile.t_second < profile.second.time())
    return planner::profile_at(profile, profile.time()).v;  // a carried ramp, cut at the end
  return profile.second.v_end;
}

planner::PathState plan_at(const PathPlan& plan, double t) noexcept {
  if (plan.hold && t >= plan.time())  // standing: exactly v = 0 where the ramp ends
    return planner::PathState{plan.s0 + plan.length, 0.0, 0.0, 0.0};
  t = std::clamp(t, 0.0, plan.time());
  planner::PathState ps = planner::profile_at(plan.profile, t);
  if (t >= plan.time()) ps.s = plan.length;  // the end of the entry, not its rounding
  ps.s = plan.s0 + std::clamp(ps.s, 0.0, plan.length);
  return ps;
}

bool make_plan(const PlanRequest& r, PathPlan& out) noexcept {
  const double v0 = std::max(r.v0, 0.0);
  const double a0 = r.a0;
  const double length = std::max(r.length, 0.0);
  // A slow-down under way must end at v >= 0 with the jerk at hand (a smaller j than the
  // plan's, above 100 %, takes longer to release it): else the path would move backwards.
  if (a0 < 0.0 && v0 - 0.5 * a0 * a0 / r.j < -kRelRounding * std::max(1.0, v0)) return false;
  // Exit: at most the 100 % plan's and what a speed-up can reach within the length.
  const double reach = jerk::reachable_velocity(v0, a0, length, r.a, r.j);
  const double exit_hi = std::max(0.0, std::min(r.exit_cap, reach));
  const double exit_lo = std::clamp(r.exit_wanted, 0.0, exit_hi);
  auto exit_fits = [&](double x) { return within(ramp_distance(v0, a0, x, r), length); };
  double exit = 0.0;
  if (!lowest_fitting(exit_lo, exit_hi, exit_fits, exit)) return false;
  const double target = std::max(r.level, 0.0);
  double level = exit;
  if (target > exit) {
    auto level_fits = [&](double l) {
      return within(ramp_distance(v0, a0, l, r) + ramp_distance(l, 0.0, exit, r), length);
    };
    level = highest_fitting(exit, target, level_fits);
  }
  out = PathPlan{};
  out.hold = target == 0.0 && exit == 0.0;
  planner::SegmentProfile& m = out.profile;
  m.v0 = v0;
  m.a0 = a0;
  m.v_level = level;
  m.first = jerk::velocity_ramp(v0, a0, level, r.a, r.d, r.j);
  m.t_first = m.first.time();
  const double d1 = jerk::distance(v0, a0, m.first);
  if (out.hold) {
    out.length = std::clamp(d1, 0.0, length);
    return true;
  }
  m.second = jerk::velocity_ramp(level, 0.0, exit, r.a, r.d, r.j);
  m.t_second = m.second.time();
  const double rest = length - d1 - jerk::distance(level, 0.0, m.second);
  m.t_cruise = level > 0.0 ? std::max(0.0, rest) / level : 0.0;
  out.length = length;
  return true;
}

double profile_time_at(const planner::SegmentProfile& profile, double s) noexcept {
  const double total = profile.time();
  if (s <= 0.0) return 0.0;
  double lo = 0.0;
  double hi = total;
  if (planner::profile_at(profile, hi).s <= s) return total;
  // Relative to the time, at least to 1 ms [s].
  for (int i = 0; i < 100 && hi - lo > kRelRounding * std::max(1e-3, hi); ++i) {
    const double mid = 0.5 * (lo + hi);
    (planner::profile_at(profile, mid).s < s ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace ncsim::ipo
