// ipo/contour: distance from a programmed line, arc or helix (see the header).

#include "ipo/contour.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncsim::ipo {

namespace {

double point_distance(const planner::Move& m, const planner::AxisVec& x,
                      const planner::AxisVec& p) noexcept {
  double sum = 0.0;
  for (std::size_t i = 0; i < m.axis_count; ++i)
    sum += (x[i] - p[i]) * (x[i] - p[i]);
  return std::sqrt(sum);
}

double line_distance(const planner::Move& m, const planner::AxisVec& x) noexcept {
  double dd = 0.0;
  double dp = 0.0;
  for (std::size_t i = 0; i < m.axis_count; ++i) {
    const double d = m.end[i] - m.start[i];
    dd += d * d;
    dp += d * (x[i] - m.start[i]);
  }
  const double u = dd > 0.0 ? std::clamp(dp / dd, 0.0, 1.0) : 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < m.axis_count; ++i) {
    const double e = x[i] - (m.start[i] + u * (m.end[i] - m.start[i]));
    sum += e * e;
  }
  return std::sqrt(sum);
}

double arc_distance(const planner::Move& m, const planner::AxisVec& x) noexcept {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const planner::Arc& arc = *m.arc;
  const std::size_t a1 = arc.axis_1;
  const std::size_t a2 = arc.axis_2;
  const double r = std::hypot(m.start[a1] - arc.centre_1, m.start[a2] - arc.centre_2);
  const double th0 = std::atan2(m.start[a2] - arc.centre_2, m.start[a1] - arc.centre_1);
  const double th1 = std::atan2(m.end[a2] - arc.centre_2, m.end[a1] - arc.centre_1);
  const double dir = arc.clockwise ? -1.0 : 1.0;
  // Swept angle in (0, 2 pi], measured in the direction of motion.
  double sweep = std::fmod(dir * (th1 - th0) + 2.0 * kTwoPi, kTwoPi);
  if (arc.full_circle || sweep <= 0.0) sweep = kTwoPi;
  const double th = std::atan2(x[a2] - arc.centre_2, x[a1] - arc.centre_1);
  const double off = std::fmod(dir * (th - th0) + 2.0 * kTwoPi, kTwoPi);
  const double ends = std::min(point_distance(m, x, m.start), point_distance(m, x, m.end));
  if (off > sweep && sweep < kTwoPi) return ends;  // beyond the arc: nearest is an end point
  const double u = off / sweep;
  const double radial = std::hypot(x[a1] - arc.centre_1, x[a2] - arc.centre_2) - r;
  double sum = radial * radial;
  for (std::size_t i = 0; i < m.axis_count; ++i) {
    if (i == a1 || i == a2) continue;
    const double e = x[i] - (m.start[i] + u * (m.end[i] - m.start[i]));
    sum += e * e;
  }
  return std::min(std::sqrt(sum), ends);
}

}  // namespace

double contour_distance(const planner::Move& move, const planner::AxisVec& x) noexcept {
  return move.arc ? arc_distance(move, x) : line_distance(move, x);
}

}  // namespace ncsim::ipo
