// audit/contour: distance from a programmed line, arc or helix (see the header).

#include "audit/contour.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "core/tolerance.hpp"

namespace ncsim::audit {

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

/// The arc's plane as unit vectors over the machine axes and its centre (from the Move alone).
struct Basis {
  planner::AxisVec u{}, v{}, c{};
};

Basis arc_basis(const planner::Move& m) noexcept {
  Basis b;
  const planner::Arc& arc = *m.arc;
  if (m.arc_plane) {
    const planner::ArcPlane& p = *m.arc_plane;
    for (std::size_t k = 0; k < 3; ++k) {
      b.u[p.axes[k]] = p.u[k];
      b.v[p.axes[k]] = p.v[k];
      b.c[p.axes[k]] = p.centre[k];
    }
  } else {
    b.u[arc.axis_1] = 1.0;
    b.v[arc.axis_2] = 1.0;
    b.c[arc.axis_1] = arc.centre_1;
    b.c[arc.axis_2] = arc.centre_2;
  }
  return b;
}

/// In-plane coordinates of p relative to the centre.
std::pair<double, double> in_plane(const Basis& b, const planner::Move& m,
                                   const planner::AxisVec& p) noexcept {
  double x = 0.0, y = 0.0;
  for (std::size_t i = 0; i < m.axis_count; ++i) {
    x += (p[i] - b.c[i]) * b.u[i];
    y += (p[i] - b.c[i]) * b.v[i];
  }
  return {x, y};
}

double arc_distance(const planner::Move& m, const planner::AxisVec& x) noexcept {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const planner::Arc& arc = *m.arc;
  const Basis b = arc_basis(m);
  const auto [x0, y0] = in_plane(b, m, m.start);
  // The chord (dx, dy) and the point (qx, qy) relative to the start, from the positions: no
  // rounding of a centre far away enters (issue 34 item 28: on R 1e8 the audit flagged its
  // own 1.5e-8 mm rounding as a contour error). Angles from the start by atan2 of the cross
  // and dot products divided by r (planner::Segment::arc's sweep), the radial distance as
  // (|w + q|^2 - r^2) / (|w + q| + r) = (2 w.q + |q|^2) / (|w + q| + r), w the start radius.
  double dx = 0.0, dy = 0.0, qx = 0.0, qy = 0.0;
  for (std::size_t i = 0; i < m.axis_count; ++i) {
    dx += (m.end[i] - m.start[i]) * b.u[i];
    dy += (m.end[i] - m.start[i]) * b.v[i];
    qx += (x[i] - m.start[i]) * b.u[i];
    qy += (x[i] - m.start[i]) * b.v[i];
  }
  const double r = std::hypot(x0, y0);
  const double ends = std::min(point_distance(m, x, m.start), point_distance(m, x, m.end));
  if (!(r > 0.0)) return ends;
  const double ux = x0 / r, uy = y0 / r;
  const auto angle = [&](double ax, double ay) {  // from the start to start + (ax, ay)
    return std::atan2(ux * ay - uy * ax, r + ux * ax + uy * ay);
  };
  const double dir = arc.clockwise ? -1.0 : 1.0;
  // Swept angle in (0, 2 pi], measured in the direction of motion.
  double sweep = dir * angle(dx, dy);
  if (sweep <= 0.0) sweep += kTwoPi;
  if (arc.full_circle) sweep = kTwoPi;
  double off = dir * angle(qx, qy);
  if (off < 0.0) off += kTwoPi;
  if (off > sweep && sweep < kTwoPi) return ends;  // beyond the arc: nearest is an end point
  const double u = off / sweep;
  const double px = x0 + qx, py = y0 + qy;
  const double radial = (2.0 * (x0 * qx + y0 * qy) + qx * qx + qy * qy) / (std::hypot(px, py) + r);
  // Out of the plane: the point's displacement from the start without its in-plane part,
  // against the share u of the block's own out-of-plane displacement (the helix rise).
  double sum = radial * radial;
  for (std::size_t i = 0; i < m.axis_count; ++i) {
    const double have = x[i] - m.start[i] - qx * b.u[i] - qy * b.v[i];
    const double rise = m.end[i] - m.start[i] - dx * b.u[i] - dy * b.v[i];
    const double e = have - u * rise;
    sum += e * e;
  }
  return std::min(std::sqrt(sum), ends);
}

/// Cubic Bezier point of a spline piece at t (de Casteljau, independent of planner::Segment).
planner::AxisVec cubic_at(const planner::Move& m, double t) noexcept {
  planner::AxisVec p{};
  const double s = 1.0 - t;
  for (std::size_t i = 0; i < m.axis_count; ++i) {
    const double c0 = m.start[i], c1 = m.spline->c1[i], c2 = m.spline->c2[i], c3 = m.end[i];
    p[i] = s * s * s * c0 + 3.0 * s * s * t * c1 + 3.0 * s * t * t * c2 + t * t * t * c3;
  }
  return p;
}

double spline_distance(const planner::Move& m, const planner::AxisVec& x) noexcept {
  // The distance along the cubic sampled at 129 parameters; every local minimum of the samples
  // is refined by a golden-section search in the two intervals beside it (a piece that folds
  // back passes near itself: the nearest sample may lie on the other branch). The result is an
  // upper bound of the true distance in any case, and exact where the refinement converges.
  constexpr int kSamples = 128;
  std::array<double, kSamples + 1> d{};
  for (int k = 0; k <= kSamples; ++k)
    d[static_cast<std::size_t>(k)] =
        point_distance(m, x, cubic_at(m, static_cast<double>(k) / kSamples));
  double best = *std::min_element(d.begin(), d.end());
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int k = 0; k <= kSamples; ++k) {
    const auto u = static_cast<std::size_t>(k);
    const bool left = k == 0 || d[u] <= d[u - 1];
    const bool right = k == kSamples || d[u] <= d[u + 1];
    if (!left || !right) continue;
    double lo = std::max(0, k - 1) / static_cast<double>(kSamples);
    double hi = std::min(kSamples, k + 1) / static_cast<double>(kSamples);
    for (int it = 0; it < 60 && hi - lo > kParameterWidth; ++it) {
      const double a = hi - g * (hi - lo);
      const double b = lo + g * (hi - lo);
      if (point_distance(m, x, cubic_at(m, a)) < point_distance(m, x, cubic_at(m, b)))
        hi = b;
      else
        lo = a;
    }
    best = std::min(best, point_distance(m, x, cubic_at(m, 0.5 * (lo + hi))));
  }
  return best;
}

}  // namespace

double contour_distance(const planner::Move& move, const planner::AxisVec& x) noexcept {
  if (move.spline) return spline_distance(move, x);
  return move.arc ? arc_distance(move, x) : line_distance(move, x);
}

}  // namespace ncsim::audit
