// planner/path: lines, arcs and helices (closed form); blends are in path_bezier.cpp.
// Arc notation: theta(s) = theta0 + omega * s, omega = sweep / L; x(s) = o + lin s +
// r (cos(theta) u + sin(theta) v): for G17 / G18 / G19 u, v are the plane's unit axes (plane
// axis 1 is c1 + r cos(theta), axis 2 c2 + r sin(theta)); every other axis moves linearly.
// Evaluated from the start point p0 = x(0), not from the centre o: x(s) = p0 + lin s +
// r ((cos(theta) - cos(theta0)) u + (sin(theta) - sin(theta0)) v), the differences written with
// the half angle h = omega s / 2 as -2 sin(theta0 + h) sin(h) and 2 cos(theta0 + h) sin(h). So a
// point carries the rounding of the chord, not of a centre 1e9 mm away (issue 34 items 4, 28;
// docs/planner.md "Arcs of a huge radius").

#include "planner/path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/tolerance.hpp"

namespace ncsim::planner {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

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

// Point evaluation of lines and arcs, one function per kind with a single named result, so that
// the 512-byte PathPoint is built in the caller's storage (a function that returns different
// objects on different paths copies it: git history of docs/benchmarks.md, issue 12 session 24).

AxisVec line_point(const geom::LineGeom& l, std::size_t n, double s) {
  AxisVec x = l.p0;
  for (std::size_t i = 0; i < n; ++i)
    x[i] += l.dir[i] * s;
  return x;
}

AxisVec arc_point(const geom::ArcGeom& a, std::size_t n, double s) {
  AxisVec x = a.p0;
  const double h = 0.5 * a.omega * s;
  const double m = a.theta0 + h;
  const double chord = 2.0 * a.radius * std::sin(h);  // signed chord length
  const double dc = -chord * std::sin(m);             // r (cos(theta) - cos(theta0))
  const double ds = chord * std::cos(m);              // r (sin(theta) - sin(theta0))
  for (std::size_t i = 0; i < n; ++i)
    x[i] += a.lin[i] * s + dc * a.u[i] + ds * a.v[i];
  return x;
}

PathPoint line_at(const geom::LineGeom& l, std::size_t n, double s) {
  PathPoint p{l.p0, l.dir, {}, {}};
  for (std::size_t i = 0; i < n; ++i)
    p.x[i] += l.dir[i] * s;
  return p;
}

PathPoint arc_at(const geom::ArcGeom& a, std::size_t n, double s) {
  PathPoint p{a.p0, {}, {}, {}};
  const double h = 0.5 * a.omega * s;
  const double sh = std::sin(h), ch = std::cos(h);
  const double sm = std::sin(a.theta0 + h), cm = std::cos(a.theta0 + h);
  const double c = cm * ch - sm * sh;   // cos(theta)
  const double sn = sm * ch + cm * sh;  // sin(theta)
  const double r = a.radius;
  const double w = a.omega;
  const double chord = 2.0 * r * sh;
  const double dc = -chord * sm;  // r (cos(theta) - cos(theta0))
  const double ds = chord * cm;   // r (sin(theta) - sin(theta0))
  for (std::size_t i = 0; i < n; ++i) {
    p.x[i] += a.lin[i] * s + dc * a.u[i] + ds * a.v[i];
    p.d1[i] = a.lin[i] + r * w * (-sn * a.u[i] + c * a.v[i]);
    p.d2[i] = -r * w * w * (c * a.u[i] + sn * a.v[i]);
    p.d3[i] = r * w * w * w * (sn * a.u[i] - c * a.v[i]);
  }
  return p;
}

}  // namespace

AxisMask effective_metric(std::uint8_t axis_count, AxisMask path_axes, const AxisVec& delta) {
  double moved = 0.0;
  AxisMask all = 0;
  for (std::size_t i = 0; i < axis_count; ++i) {
    all |= AxisMask{1} << i;
    if (has(path_axes, i)) moved = std::max(moved, std::abs(delta[i]));
  }
  return moved > kZeroLength ? (path_axes & all) : all;
}

AxisMask polygon_metric(std::uint8_t axis_count, AxisMask path_axes,
                        const std::array<AxisVec, 4>& c) {
  AxisVec travel{};
  for (std::size_t m = 0; m < 3; ++m)
    for (std::size_t i = 0; i < axis_count; ++i)
      travel[i] += std::abs(c[m + 1][i] - c[m][i]);
  return effective_metric(axis_count, path_axes, travel);
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
  LineGeom& g = std::get<LineGeom>(seg.geom_);  // a default Segment holds a zero line
  g.p0 = a;
  if (length > 0.0)
    for (std::size_t i = 0; i < axis_count; ++i)
      g.dir[i] = delta[i] / length;
  seg.s_hi_ = length;
  return seg;
}

Segment Segment::arc(const Move& move) {
  const Arc& arc = *move.arc;
  Segment seg;
  seg.n_ = move.axis_count;
  ArcGeom g;
  AxisMask plane = 0;
  if (move.arc_plane) {
    // A general plane (docs/planner.md "Arcs in a general plane"): centre and u, v over X, Y, Z.
    const ArcPlane& p = *move.arc_plane;
    g.o = move.start;
    for (std::size_t k = 0; k < 3; ++k) {
      g.u[p.axes[k]] = p.u[k];
      g.v[p.axes[k]] = p.v[k];
      plane |= AxisMask{1} << p.axes[k];
    }
    // o: the start with its in-plane part replaced by the centre's.
    double cu = 0.0, cv = 0.0, su = 0.0, sv = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      cu += p.centre[k] * p.u[k];
      cv += p.centre[k] * p.v[k];
      su += move.start[p.axes[k]] * p.u[k];
      sv += move.start[p.axes[k]] * p.v[k];
    }
    for (std::size_t k = 0; k < 3; ++k)
      g.o[p.axes[k]] += (cu - su) * p.u[k] + (cv - sv) * p.v[k];
  } else {
    g.o = move.start;
    g.o[arc.axis_1] = arc.centre_1;
    g.o[arc.axis_2] = arc.centre_2;
    g.u[arc.axis_1] = 1.0;
    g.v[arc.axis_2] = 1.0;
    plane = (AxisMask{1} << arc.axis_1) | (AxisMask{1} << arc.axis_2);
  }
  // In-plane coordinates of the start relative to the centre.
  double x0 = 0.0, y0 = 0.0;
  for (std::size_t i = 0; i < move.axis_count; ++i) {
    x0 += (move.start[i] - g.o[i]) * g.u[i];
    y0 += (move.start[i] - g.o[i]) * g.v[i];
  }
  g.p0 = move.start;
  g.radius = std::hypot(x0, y0);
  g.theta0 = std::atan2(y0, x0);
  // Sweep in (0, 2 pi] counter-clockwise, [-2 pi, 0) clockwise; a closed arc is a full turn.
  // The angle from start to end is atan2 of the cross and dot products of (x0, y0) and the
  // end's (x0 + dx, y0 + dy), both divided by r and written with the chord (dx, dy) from the end
  // points, so a tiny sweep on a huge radius keeps its digits (the difference of two atan2 of
  // nearly equal angles kept none: 1e-10 rad became 0, a full circle; issue 34 item 4). Closed
  // means what the interpreter decided (Arc::full_circle) or an end within kSamePoint of the start,
  // its own rule (interp "full" circle), not a chord below kRelTol of the radius.
  double dx = 0.0, dy = 0.0;
  for (std::size_t i = 0; i < move.axis_count; ++i) {
    dx += (move.end[i] - move.start[i]) * g.u[i];
    dy += (move.end[i] - move.start[i]) * g.v[i];
  }
  double phi = 0.0;  // signed angle from start to end, (-pi, pi]
  if (g.radius > 0.0) {
    const double ux = x0 / g.radius, uy = y0 / g.radius;
    phi = std::atan2(ux * dy - uy * dx, g.radius + ux * dx + uy * dy);
  }
  const bool closed = arc.full_circle || std::hypot(dx, dy) < kSamePoint;
  double sweep = 0.0;
  if (closed)
    sweep = arc.clockwise ? -kTwoPi : kTwoPi;
  else if (arc.clockwise)
    sweep = phi < 0.0 ? phi : phi - kTwoPi;
  else
    sweep = phi > 0.0 ? phi : phi + kTwoPi;
  // The rise: the displacement without its in-plane part (0 on the axes of a principal plane).
  AxisVec delta{};
  for (std::size_t i = 0; i < move.axis_count; ++i) {
    if (!move.arc_plane && has(plane, i)) continue;
    delta[i] = move.end[i] - move.start[i] - dx * g.u[i] - dy * g.v[i];
  }
  // Arc length: the plane axes always measure it; the other path axes add the helix rise.
  AxisMask all = 0;
  for (std::size_t i = 0; i < move.axis_count; ++i)
    all |= AxisMask{1} << i;
  seg.metric_ = (move.path_axes | plane) & all;
  double rise2 = 0.0;
  for (std::size_t i = 0; i < move.axis_count; ++i)
    if (has(seg.metric_, i)) rise2 += delta[i] * delta[i];
  const double planar = g.radius * std::abs(sweep);
  const double length = std::sqrt(planar * planar + rise2);
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
  if (move.spline) {
    const std::array<AxisVec, 4> c{move.start, move.spline->c1, move.spline->c2, move.end};
    return cubic(move.axis_count, polygon_metric(move.axis_count, move.path_axes, c), c);
  }
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
  if (const auto* l = std::get_if<LineGeom>(&geom_)) return line_point(*l, n_, s);
  if (const auto* a = std::get_if<ArcGeom>(&geom_)) return arc_point(*a, n_, s);
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
  b.metric = metric_;
  if (const auto* l = std::get_if<LineGeom>(&geom_)) {
    for (std::size_t i = 0; i < n_; ++i)
      b.d1[i] = std::abs(l->dir[i]);
    b.curvature = 0.0;
    return b;
  }
  if (const auto* a = std::get_if<ArcGeom>(&geom_)) {
    const double t0 = a->theta0 + a->omega * s_lo_;
    const double t1 = a->theta0 + a->omega * s_hi_;
    const double lo = std::min(t0, t1);
    const double hi = std::max(t0, t1);
    const double w = std::abs(a->omega);
    const double r = a->radius;
    b.curvature = r * w * w;
    b.circle = std::all_of(a->lin.begin(), a->lin.begin() + n_, [](double c) { return c == 0.0; });
    // Axis i's circle part is r A cos(theta - phi), A = |(u_i, v_i)|, phi = atan2(v_i, u_i):
    // |x'| <= |lin| + r w A |sin|, |x''| = r w^2 A |cos|, |x'''| = r w^3 A |sin| over the range.
    for (std::size_t i = 0; i < n_; ++i) {
      const double amp = std::hypot(a->u[i], a->v[i]);
      b.d1[i] = std::abs(a->lin[i]);
      if (amp == 0.0) continue;
      const double phi = std::atan2(a->v[i], a->u[i]);
      const double c = max_abs_cos(lo - phi, hi - phi);
      const double sn = max_abs_sin(lo - phi, hi - phi);
      b.d1[i] += r * w * amp * sn;
      b.d2[i] = r * w * w * amp * c;
      b.d3[i] = r * w * w * w * amp * sn;
    }
    return b;
  }
  return bezier_bounds();
}

PathPoint Segment::at_raw(double s) const noexcept {
  if (const auto* l = std::get_if<LineGeom>(&geom_)) return line_at(*l, n_, s);
  if (const auto* a = std::get_if<ArcGeom>(&geom_)) return arc_at(*a, n_, s);
  return bezier_at(std::get<BezierGeom>(geom_), s);
}

}  // namespace ncsim::planner
