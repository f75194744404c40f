// planner/limits: the projections documented in limits.hpp.

#include "planner/limits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/tolerance.hpp"

namespace ncsim::planner {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Lower `cap` to `value` and remember why.
void lower(double value, VelocityLimit why, std::uint8_t axis, double& cap, VelocityLimit& limit,
           std::uint8_t& limiting_axis) {
  if (value < cap) {
    cap = value;
    limit = why;
    limiting_axis = axis;
  }
}

/// Expected time [s] of an arc of `length` with velocity cap v, acceleration a and jerk j
/// (+inf: none), the model that picks its centripetal share: the mean of a traverse at the cap
/// (an arc entered and left at speed, e.g. between tangent neighbours) and a rest-to-rest one
/// (an arc between sharp knees). Either alone was slower on bench/blend_set.py.
double arc_time_model(double length, double v, double a, double j) {
  const double ramp = std::isfinite(j) ? a / j : 0.0;  // the jerk's extra per ramp pair
  const double cruise = length / v;
  const double rest_to_rest = length >= v * v / a + v * ramp ? length / v + v / a + ramp
                                                             : 2.0 * std::sqrt(length / a) + ramp;
  return 0.5 * (cruise + rest_to_rest);
}

/// On a plane circle (x''' = -K^2 x', DerivativeBounds::circle) the axis jerk is
/// x'_i (j - K^2 v^3) + x''_i / K (3 K v a) with x' orthogonal to x'', so a metric axis sees at
/// most sqrt((|j| + K^2 v^3)^2 + (3 K v a)^2): the path jerk that keeps it within j_i [mm/s^3]
/// (-inf when none does).
double circle_jerk(const DerivativeBounds& b, const AxisLimits& ax, double v, double a) {
  const double kv = b.curvature * v;
  const double cross = 3.0 * kv * a;
  if (!(cross < ax.j_max)) return -kInf;
  return std::sqrt(ax.j_max * ax.j_max - cross * cross) - kv * kv * v;
}

}  // namespace

bool jerk_limited(SlopeType slope) noexcept {
  return slope != SlopeType::step;
}

PathLimits path_limits(const Segment& segment, const Move& move, std::span<const AxisLimits> axes) {
  const std::size_t n = segment.axis_count();
  if (axes.size() < n)
    throw std::invalid_argument("planner: " + std::to_string(axes.size()) +
                                " axis limits for a segment of " + std::to_string(n) + " axes");
  const DerivativeBounds b = segment.bounds();
  const double length = segment.length();

  // The velocity the block asks for.
  double v_programmed = 0.0;
  if (move.rapid) {
    // 000 l.360: each axis at MIN(rapid, reference, maximum); the slowest axis sets the time.
    double v = kInf;
    for (std::size_t i = 0; i < n; ++i) {
      if (b.d1[i] <= kTiny) continue;
      const AxisLimits& ax = axes[i];
      v = std::min(v, std::min({ax.v_rapid, ax.v_reference, ax.v_max}) / b.d1[i]);
    }
    v_programmed = std::isfinite(v) ? v : 0.0;
  } else if (move.block_time) {
    v_programmed = *move.block_time > 0.0 ? length / *move.block_time : kInf;
  } else {
    v_programmed = move.feed;
  }
  PathLimits out;
  if (move.rapid) {
    // G00 has its own slope (P-AXIS-00004 acceleration, P-AXIS-00200 ramp time; move.hpp).
    // (The 16 axes. G00 limits are built for a G00 block only: costly to fill for every block.)
    std::array<AxisLimits, kMaxAxes> rapid{};
    for (std::size_t i = 0; i < n; ++i)
      rapid[i] = rapid_limits(axes[i]);
    out = limits_from_bounds(b, std::span<const AxisLimits>(rapid.data(), n), v_programmed,
                             jerk_limited(move.slope));
    // The rapid velocity already is the axes' own; it is never "capped".
    if (out.limit == VelocityLimit::axis_velocity) out.limit = VelocityLimit::programmed;
  } else {
    out = limits_from_bounds(b, axes.first(n), v_programmed, jerk_limited(move.slope));
    if (out.limit == VelocityLimit::centripetal && segment.kind() == SegmentKind::arc)
      out = best_share(b, axes.first(n), v_programmed, jerk_limited(move.slope), length, out);
  }
  out.v_end = move.end_feed ? std::min(out.v_max, std::max(*move.end_feed, 0.0)) : out.v_max;
  return out;
}

std::size_t arc_options(const Segment& segment, const Move& move, std::span<const AxisLimits> axes,
                        const PathLimits& planned, std::array<PathLimits, kArcOptions>& out) {
  const std::size_t n = segment.axis_count();
  if (axes.size() < n || move.rapid || segment.kind() != SegmentKind::arc) return 0;
  const DerivativeBounds b = segment.bounds();
  const bool jerk = jerk_limited(move.slope);
  constexpr double kTopShare = 0.99;
  const double top =
      limits_from_bounds(b, axes.first(n), planned.v_programmed, jerk, kTopShare).v_max;
  if (!(top > 0.0)) return 0;
  static const std::array<double, kArcOptions> kFractions = {1.0, 0.92, 0.84, 0.72, 0.58};
  std::size_t count = 0;
  for (const double f : kFractions) {
    PathLimits p = limits_from_bounds(b, axes.first(n), f * top, jerk, kTopShare);
    if (!(p.v_max > 0.0) || !(p.a_max > 0.0) || !(p.d_max > 0.0) || !(p.j_max > 0.0)) continue;
    p.v_programmed = planned.v_programmed;
    p.limit = planned.limit;
    p.limiting_axis = planned.limiting_axis;
    p.v_end = std::min(planned.v_end, p.v_max);
    out[count++] = p;
  }
  return count;
}

PathLimits best_share(const DerivativeBounds& b, std::span<const AxisLimits> axes,
                      double v_programmed, bool jerk, double length, const PathLimits& standard) {
  PathLimits best = standard;
  double t_best = arc_time_model(length, standard.v_max, std::min(standard.a_max, standard.d_max),
                                 standard.j_max);
  for (const double share : kCentripetalShares) {
    const PathLimits p = limits_from_bounds(b, axes, v_programmed, jerk, share);
    if (!(p.v_max > 0.0) || !(p.a_max > 0.0) || !(p.d_max > 0.0) || !(p.j_max > 0.0)) continue;
    const double t = arc_time_model(length, p.v_max, std::min(p.a_max, p.d_max), p.j_max);
    if (t < t_best * (1.0 - kRelTol)) {
      best = p;
      t_best = t;
    }
  }
  return best;
}

PathLimits limits_from_bounds(const DerivativeBounds& b, std::span<const AxisLimits> axes,
                              double v_programmed, bool jerk, double centripetal_share) {
  const std::size_t n = axes.size();
  PathLimits out;
  out.v_programmed = v_programmed;
  double cap = out.v_programmed;
  VelocityLimit limit = VelocityLimit::programmed;
  std::uint8_t limiting_axis = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto ax_id = static_cast<std::uint8_t>(i);
    const AxisLimits& ax = axes[i];
    if (b.d1[i] > kTiny)
      lower(std::min(ax.v_max, ax.v_reference) / b.d1[i], VelocityLimit::axis_velocity, ax_id, cap,
            limit, limiting_axis);
    const double a_axis = std::min(ax.a_max, ax.d_max);
    if (b.d2[i] > kTiny)
      lower(std::sqrt(centripetal_share * a_axis / b.d2[i]), VelocityLimit::centripetal, ax_id, cap,
            limit, limiting_axis);
    if (jerk && b.d3[i] > kTiny)
      lower(std::cbrt(kCurvatureJerkShare * ax.j_max / b.d3[i]), VelocityLimit::curvature_jerk,
            ax_id, cap, limit, limiting_axis);
  }
  out.v_max = std::max(cap, 0.0);
  out.limit = limit;
  out.limiting_axis = limiting_axis;
  out.v_end = out.v_max;

  const double v = out.v_max;
  double a_plus = kInf;
  double a_minus = kInf;
  for (std::size_t i = 0; i < n; ++i) {
    const AxisLimits& ax = axes[i];
    const bool curved = b.d2[i] > kTiny;
    // On a curve an axis may speed up or slow down whatever the path does: use the smaller.
    const double up = curved ? std::min(ax.a_max, ax.d_max) : ax.a_max;
    const double down = curved ? std::min(ax.a_max, ax.d_max) : ax.d_max;
    const double centripetal = b.d2[i] * v * v;
    if (b.d1[i] > kTiny) {
      // Two bounds of the axis acceleration, each safe alone: |x'_i| a + |x''_i| v^2, and on a
      // metric axis sqrt(a^2 + (curvature v^2)^2) (x' orthogonal to x''); the larger A wins.
      const double curv = has(b.metric, i) ? b.curvature * v * v : kInf;
      const auto allowed = [&](double a_axis_max) {
        const double linear = (a_axis_max - centripetal) / b.d1[i];
        return curv < a_axis_max
                   ? std::max(linear, std::sqrt(a_axis_max * a_axis_max - curv * curv))
                   : linear;
      };
      a_plus = std::min(a_plus, allowed(up));
      a_minus = std::min(a_minus, allowed(down));
    }
    if (jerk && curved && v > 0.0) {
      double cross = kCrossJerkShare * ax.j_max / (3.0 * b.d2[i] * v);
      // On a plane circle the cross term is orthogonal to the rest (circle_jerk): the largest
      // A that still leaves the path jerk kCrossJerkShare of the axis's.
      const double kv = b.curvature * v;
      const double rest = kCrossJerkShare * ax.j_max + kv * kv * v;
      if (b.circle && has(b.metric, i) && rest < ax.j_max)
        cross = std::max(cross, std::sqrt(ax.j_max * ax.j_max - rest * rest) / (3.0 * kv));
      a_plus = std::min(a_plus, cross);
      a_minus = std::min(a_minus, cross);
    }
  }
  out.a_max = a_plus;
  out.d_max = a_minus;

  double j_path = kInf;
  if (jerk) {
    const double a = std::max(a_plus, a_minus);
    for (std::size_t i = 0; i < n; ++i) {
      if (b.d1[i] <= kTiny) continue;
      const double used = b.d3[i] * v * v * v + 3.0 * b.d2[i] * v * a;
      double allowed = (axes[i].j_max - used) / b.d1[i];
      if (b.circle && has(b.metric, i)) allowed = std::max(allowed, circle_jerk(b, axes[i], v, a));
      j_path = std::min(j_path, allowed);
    }
  }
  out.j_max = j_path;
  return out;
}

}  // namespace ncsim::planner
