// planner/corner: classification and link velocity (rules in corner.hpp).

#include "planner/corner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncsim::planner {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

double tangent_angle(const AxisVec& t_in, const AxisVec& t_out, std::size_t axis_count,
                     AxisMask metric) noexcept {
  // atan2(|a x b|, a.b) via |a - b| and |a + b| (accurate at small and large angles).
  double diff = 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < axis_count; ++i) {
    if (!has(metric, i)) continue;
    const double d = t_out[i] - t_in[i];
    const double s = t_out[i] + t_in[i];
    diff += d * d;
    sum += s * s;
  }
  return 2.0 * std::atan2(std::sqrt(diff), std::sqrt(sum));
}

TransitionClass classify(const PathPoint& in_end, const PathPoint& out_start,
                         std::size_t axis_count, AxisMask metric) noexcept {
  return classify_at_angle(in_end, out_start, axis_count,
                           tangent_angle(in_end.d1, out_start.d1, axis_count, metric));
}

TransitionClass classify_at_angle(const PathPoint& in_end, const PathPoint& out_start,
                                  std::size_t axis_count, double angle) noexcept {
  // Every axis counts for the tangent: an auxiliary axis's direction jump is a C0 step too.
  double tangent_gap = 0.0;
  double curv_gap = 0.0;
  double curv_size = 0.0;
  for (std::size_t i = 0; i < axis_count; ++i) {
    tangent_gap = std::max(tangent_gap, std::abs(out_start.d1[i] - in_end.d1[i]));
    curv_gap = std::max(curv_gap, std::abs(out_start.d2[i] - in_end.d2[i]));
    curv_size = std::max({curv_size, std::abs(out_start.d2[i]), std::abs(in_end.d2[i])});
  }
  if (angle > kTangentTolerance || tangent_gap > kTangentTolerance) return TransitionClass::c0;
  if (curv_gap > std::max(kCurvatureTolerance * curv_size, kCurvatureFloor))
    return TransitionClass::c1;
  return TransitionClass::c2;
}

double velojump_velocity(const AxisVec& t_in, const AxisVec& t_out,
                         std::span<const AxisLimits> axes, double t_cycle,
                         std::uint8_t* axis) noexcept {
  double v = kInf;
  for (std::size_t i = 0; i < axes.size() && i < t_in.size(); ++i) {
    const double step = std::abs(t_out[i] - t_in[i]);  // |dv_i| per unit path velocity
    if (step <= 0.0) continue;
    // 000 l.108: v_jump[i] = C0[i] * min(A+[i], -A-[i]) * T (A- negative there).
    const double v_jump = axes[i].c0 * std::min(axes[i].a_max, axes[i].d_max) * t_cycle;
    const double v_i = v_jump / step;
    if (v_i < v) {
      v = v_i;
      if (axis != nullptr) *axis = static_cast<std::uint8_t>(i);
    }
  }
  return v;
}

bool knee_carries_acceleration(const AxisVec& t_in, const AxisVec& t_out,
                               std::span<const AxisLimits> axes, double t_cycle) noexcept {
  // Bound of the path acceleration at the joint: the axis k with the largest |x'_k| on either
  // side takes x'_k a of it, so |a| <= A_k / |x'_k| (path limits, limits.hpp).
  double a_axis = 0.0;
  double t_max = 0.0;
  for (std::size_t i = 0; i < axes.size() && i < t_in.size(); ++i) {
    a_axis = std::max({a_axis, axes[i].a_max, axes[i].d_max});
    t_max = std::max({t_max, std::abs(t_in[i]), std::abs(t_out[i])});
  }
  if (!(t_max > 0.0)) return false;
  const double a_path = a_axis / t_max;
  for (std::size_t i = 0; i < axes.size() && i < t_in.size(); ++i) {
    const double step = std::abs(t_out[i] - t_in[i]);  // |da_i| per unit path acceleration
    if (!(a_path * step <= kKneeBudget * axes[i].j_max * t_cycle)) return false;
  }
  return true;
}

double c1_velocity(const AxisVec& k_in, const AxisVec& k_out, std::span<const AxisLimits> axes,
                   double t_cycle, std::uint8_t* axis) noexcept {
  double v = kInf;
  for (std::size_t i = 0; i < axes.size() && i < k_in.size(); ++i) {
    const double step = std::abs(k_out[i] - k_in[i]);  // |da_i| per unit v^2
    if (step <= 0.0) continue;
    const double v_i = std::sqrt(axes[i].j_max * t_cycle / step);
    if (v_i < v) {
      v = v_i;
      if (axis != nullptr) *axis = static_cast<std::uint8_t>(i);
    }
  }
  return v;
}

Link link_velocity(const PathPoint& in_end, const PathPoint& out_start, std::size_t axis_count,
                   AxisMask metric, std::span<const AxisLimits> axes, const ChannelLimits& channel,
                   double v_in, double v_out, std::optional<double> transvelmin,
                   bool jerk_limited_slope) noexcept {
  const std::span<const AxisLimits> used = axes.first(std::min(axes.size(), axis_count));
  Link link;
  link.angle = tangent_angle(in_end.d1, out_start.d1, axis_count, metric);
  link.cls = classify_at_angle(in_end, out_start, axis_count, link.angle);
  const double cap = std::max(0.0, std::min(v_in, v_out));
  link.v_link = cap;
  switch (link.cls) {
    case TransitionClass::c0: {
      link.zero_acceleration = true;
      std::uint8_t ax = 0;
      const double v = velojump_velocity(in_end.d1, out_start.d1, used, channel.t_cycle, &ax);
      if (v < link.v_link) {
        link.v_link = v;
        link.rule = LinkRule::velojump;
        link.limiting_axis = ax;
      }
      // #TRANSVELMIN raises the link above VELOJUMP (000 l.108 "if v_link < v_min then
      // v_link = v_min").
      if (transvelmin) {
        const double v_min = std::min(std::max(*transvelmin, 0.0), cap);
        if (link.v_link < v_min) {
          link.v_link = v_min;
          link.rule = LinkRule::transvelmin;
        }
      }
      // The curvature jump of a knee into a curve too: the acceleration step v^2 |dk_i| within
      // j_i T, as at a tangent joint (P-CHAN-00009 semantics; docs/planner.md "Corners"):
      // without it a knee of 1e-4 rad let the arc's own cap through, and a jerk of 12x J.
      // It has priority over #TRANSVELMIN (TF5200 PROG-207486091: "with a non-linear slope
      // ... P-CHAN-00009 ... jerk limitation is prioritised"; issue 36 item 5).
      double v_curvature = kInf;
      if (channel.limit_c1_by_jerk && jerk_limited_slope) {
        v_curvature = c1_velocity(in_end.d2, out_start.d2, used, channel.t_cycle, &ax);
        if (v_curvature < link.v_link) {
          link.v_link = v_curvature;
          link.rule = LinkRule::c1_jerk;
          link.limiting_axis = ax;
        }
      }
      // A knee that limits nothing and whose acceleration step fits the C1 budget carries the
      // path acceleration (docs/planner.md "Corners", dense CAM chords), where the curvature
      // step fits the rest of the budget (v^2 scales with it).
      if (link.rule == LinkRule::segment_caps)
        link.zero_acceleration =
            !knee_carries_acceleration(in_end.d1, out_start.d1, used, channel.t_cycle) ||
            link.v_link > v_curvature * std::sqrt(1.0 - kKneeBudget);
      break;
    }
    case TransitionClass::c1: {
      link.zero_acceleration = true;
      if (channel.limit_c1_by_jerk && jerk_limited_slope) {
        std::uint8_t ax = 0;
        const double v = c1_velocity(in_end.d2, out_start.d2, used, channel.t_cycle, &ax);
        if (v < link.v_link) {
          link.v_link = v;
          link.rule = LinkRule::c1_jerk;
          link.limiting_axis = ax;
        }
      }
      break;
    }
    case TransitionClass::c2:
      break;
  }
  return link;
}

}  // namespace ncsim::planner
