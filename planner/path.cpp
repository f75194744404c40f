// planner/path: lines, arcs and helices (closed form); blends are in path_bezier.cpp.
// Arc notation: theta(s) = theta0 + omega * s, omega = sweep / L; plane axis 1 is
// c1 + r cos(theta), plane axis 2 is c2 + r sin(theta); every other axis moves linearly.

#include "planner/path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncsim::planner {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

bool has(AxisMask mask, std::size_t i) {
  return ((mask >> i) & 1U) != 0;
}

/// Largest |cos(theta)| over theta in [a, b] (a <= b).
double max_abs_cos(double a, double b) {
  if (b - a >= std::numbers::pi) return 1.0;
  // A multiple of pi inside [a, b] makes |cos| reach 1.
  const double k = std::ceil(a / std::numbers::pi);
  if (k * std::numbers::pi <= b) return 1.0;
  return std::max(std::abs(std::cos(a)), std::abs(std::cos(b)));
}

double max_abs_sin(double a, double b) {
  const double h = std::numbers::pi / 2.0;
  return max_abs_cos(a - h, b - h);
}

}  // namespace

AxisMask effective_metric(std::uint8_t axis_count, AxisMask path_axes, const AxisVec& delta) {
  double moved = 0.0;
  AxisMask all = 0;
  for (std::size_t i = 0; i < axis_count; ++i) {
    all |= AxisMask{1} << i;
    if (has(path_axes, i)) moved = std::max(moved, std::abs(delta[i]));
  }
  return moved > 1e-12 ? (path_axes & all) : all;
}

double Segment::metric_norm(const AxisVec& v) const noexcept {
  double sum = 0.0;
  for (std::size_t i = 0; i < n_; ++i)
    if (has(metric_, i)) sum += v[i] * v[i];
  return std::sqrt(sum);
}

Segment Segment::line(std::uint8_t axis_count, AxisMask metric, const AxisVec& a,
                      const AxisVec& b) {
  Segment seg;
  seg.n_ = axis_count;
  AxisVec delta{};
  for (std::size_t i = 0; i < axis_count; ++i)
    delta[i] = b[i] - a[i];
  seg.metric_ = effective_metric(axis_count, metric, delta);
  const double length = seg.metric_norm(delta);
  LineGeom g;
  g.p0 = a;
  if (length > 0.0)
    for (std::size_t i = 0; i < axis_count; ++i)
      g.dir[i] = delta[i] / length;
  seg.geom_ = g;
  seg.s_hi_ = length;
  return seg;
}

Segment Segment::arc(const Move& move) {
  const Arc& arc = *move.arc;
  Segment seg;
  seg.n_ = move.axis_count;
  ArcGeom g;
  g.a1 = arc.axis_1;
  g.a2 = arc.axis_2;
  g.c1 = arc.centre_1;
  g.c2 = arc.centre_2;
  const double x0 = move.start[g.a1] - g.c1;
  const double y0 = move.start[g.a2] - g.c2;
  const double x1 = move.end[g.a1] - g.c1;
  const double y1 = move.end[g.a2] - g.c2;
  g.radius = std::hypot(x0, y0);
  g.theta0 = std::atan2(y0, x0);
  // Sweep in (0, 2 pi] counter-clockwise, [-2 pi, 0) clockwise; a closed arc is a full turn.
  double ccw = std::atan2(y1, x1) - g.theta0;
  ccw = std::fmod(ccw + 2.0 * kTwoPi, kTwoPi);
  const bool closed = arc.full_circle || std::hypot(x1 - x0, y1 - y0) <= 1e-9 * g.radius;
  double sweep = 0.0;
  if (closed)
    sweep = arc.clockwise ? -kTwoPi : kTwoPi;
  else
    sweep = arc.clockwise ? ccw - kTwoPi : ccw;
  // Arc length: the plane axes always measure it; the other path axes add the helix rise.
  AxisVec delta{};
  for (std::size_t i = 0; i < move.axis_count; ++i)
    if (i != g.a1 && i != g.a2) delta[i] = move.end[i] - move.start[i];
  AxisMask metric = move.path_axes | (AxisMask{1} << g.a1) | (AxisMask{1} << g.a2);
  AxisMask all = 0;
  for (std::size_t i = 0; i < move.axis_count; ++i)
    all |= AxisMask{1} << i;
  seg.metric_ = metric & all;
  double rise2 = 0.0;
  for (std::size_t i = 0; i < move.axis_count; ++i)
    if (has(seg.metric_, i)) rise2 += delta[i] * delta[i];
  const double planar = g.radius * std::abs(sweep);
  const double length = std::sqrt(planar * planar + rise2);
  g.p0 = move.start;
  if (length > 0.0) {
    g.omega = sweep / length;
    for (std::size_t i = 0; i < move.axis_count; ++i)
      g.lin[i] = delta[i] / length;
  }
  seg.geom_ = g;
  seg.s_hi_ = length;
  return seg;
}

Segment Segment::from_move(const Move& move) {
  if (move.arc) return arc(move);
  return line(move.axis_count, move.path_axes, move.start, move.end);
}

SegmentKind Segment::kind() const noexcept {
  switch (geom_.index()) {
    case 0:
      return SegmentKind::line;
    case 1:
      return SegmentKind::arc;
    default:
      return spline_ ? SegmentKind::spline : SegmentKind::blend;
  }
}

AxisVec Segment::point(double s) const noexcept {
  return point_raw(s_lo_ + std::clamp(s, 0.0, length()));
}

PathPoint Segment::at(double s) const noexcept {
  return at_raw(s_lo_ + std::clamp(s, 0.0, length()));
}

AxisVec Segment::point_raw(double s) const noexcept {
  if (const auto* l = std::get_if<LineGeom>(&geom_)) {
    AxisVec x = l->p0;
    for (std::size_t i = 0; i < n_; ++i)
      x[i] += l->dir[i] * s;
    return x;
  }
  if (const auto* a = std::get_if<ArcGeom>(&geom_)) {
    AxisVec x = a->p0;
    for (std::size_t i = 0; i < n_; ++i)
      x[i] += a->lin[i] * s;
    const double th = a->theta0 + a->omega * s;
    x[a->a1] = a->c1 + a->radius * std::cos(th);
    x[a->a2] = a->c2 + a->radius * std::sin(th);
    return x;
  }
  return at_raw(s).x;
}

Segment Segment::trimmed(double s0, double s1) const noexcept {
  Segment seg = *this;
  const double lo = s_lo_ + std::clamp(s0, 0.0, length());
  const double hi = s_lo_ + std::clamp(s1, 0.0, length());
  seg.s_lo_ = lo;
  seg.s_hi_ = std::max(lo, hi);
  return seg;
}

DerivativeBounds Segment::bounds() const noexcept {
  DerivativeBounds b;
  if (const auto* l = std::get_if<LineGeom>(&geom_)) {
    for (std::size_t i = 0; i < n_; ++i)
      b.d1[i] = std::abs(l->dir[i]);
    return b;
  }
  if (const auto* a = std::get_if<ArcGeom>(&geom_)) {
    for (std::size_t i = 0; i < n_; ++i)
      b.d1[i] = std::abs(a->lin[i]);
    const double t0 = a->theta0 + a->omega * s_lo_;
    const double t1 = a->theta0 + a->omega * s_hi_;
    const double lo = std::min(t0, t1);
    const double hi = std::max(t0, t1);
    const double w = std::abs(a->omega);
    const double r = a->radius;
    const double c = max_abs_cos(lo, hi);
    const double s = max_abs_sin(lo, hi);
    // x1 = r cos: |x1'| = r w |sin|, |x1''| = r w^2 |cos|, |x1'''| = r w^3 |sin|.
    b.d1[a->a1] = r * w * s;
    b.d2[a->a1] = r * w * w * c;
    b.d3[a->a1] = r * w * w * w * s;
    b.d1[a->a2] = r * w * c;
    b.d2[a->a2] = r * w * w * s;
    b.d3[a->a2] = r * w * w * w * c;
    return b;
  }
  return bezier_bounds();
}

PathPoint Segment::at_raw(double s) const noexcept {
  PathPoint p;
  if (const auto* l = std::get_if<LineGeom>(&geom_)) {
    p.x = point_raw(s);
    p.d1 = l->dir;
    return p;
  }
  if (const auto* a = std::get_if<ArcGeom>(&geom_)) {
    p.x = point_raw(s);
    p.d1 = a->lin;
    const double th = a->theta0 + a->omega * s;
    const double c = std::cos(th);
    const double sn = std::sin(th);
    const double r = a->radius;
    const double w = a->omega;
    p.d1[a->a1] = -r * w * sn;
    p.d2[a->a1] = -r * w * w * c;
    p.d3[a->a1] = r * w * w * w * sn;
    p.d1[a->a2] = r * w * c;
    p.d2[a->a2] = -r * w * w * sn;
    p.d3[a->a2] = -r * w * w * w * c;
    return p;
  }
  return bezier_at(std::get<BezierGeom>(geom_), s);
}

}  // namespace ncsim::planner
