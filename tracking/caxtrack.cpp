// tracking/caxtrack: #CAXTRACK, the tracking axis's values per block (see caxtrack.hpp).

#include "tracking/caxtrack.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/tolerance.hpp"

namespace ncsim::tracking {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr int kSamples = 24;  ///< tangent samples per spline piece (fit check, unwrapping)
constexpr int kMaxDepth = 6;  ///< halvings of a spline piece at most (64 parts)

using planner::AxisVec;

/// Control points P0..P3 of a spline Move, axis `k`.
std::array<double, 4> controls(const planner::Move& mv, int k) {
  const auto i = static_cast<std::size_t>(k);
  return {mv.start[i], mv.spline->c1[i], mv.spline->c2[i], mv.end[i]};
}

/// Derivative of a cubic Bezier with control values `p` at `u`.
double bezier_d1(const std::array<double, 4>& p, double u) {
  const double w = 1.0 - u;
  return 3.0 * (w * w * (p[1] - p[0]) + 2.0 * w * u * (p[2] - p[1]) + u * u * (p[3] - p[2]));
}

/// Second derivative of a cubic Bezier with control values `p` at `u`.
double bezier_d2(const std::array<double, 4>& p, double u) {
  return 6.0 * ((1.0 - u) * (p[2] - 2.0 * p[1] + p[0]) + u * (p[3] - 2.0 * p[2] + p[1]));
}

double bezier(const std::array<double, 4>& p, double u) {
  const double w = 1.0 - u;
  return w * w * w * p[0] + 3.0 * w * w * u * p[1] + 3.0 * w * u * u * p[2] + u * u * u * p[3];
}

/// Tangent angle of a spline Move at u [deg]; where the derivative vanishes (a doubled control
/// point at an end) it is taken just inside, which gives its limit direction.
std::optional<double> spline_tangent(const planner::Move& mv, int x, int y, double u) {
  if (auto t = tangent_angle(bezier_d1(controls(mv, x), u), bezier_d1(controls(mv, y), u)))
    return t;
  const double uc = std::clamp(u, 1e-4, 1.0 - 1e-4);
  return tangent_angle(bezier_d1(controls(mv, x), uc), bezier_d1(controls(mv, y), uc));
}

/// d theta / du of a spline Move at u [deg per unit u] (the XY curvature times |P'(u)|);
/// nullopt where the derivative vanishes.
std::optional<double> spline_turn_rate(const planner::Move& mv, int x, int y, double u) {
  const double dx = bezier_d1(controls(mv, x), u);
  const double dy = bezier_d1(controls(mv, y), u);
  const double q = dx * dx + dy * dy;
  if (!(q > kSamePoint * kSamePoint)) return std::nullopt;
  const double ddx = bezier_d2(controls(mv, x), u);
  const double ddy = bezier_d2(controls(mv, y), u);
  return (dx * ddy - dy * ddx) / q * kRadToDeg;
}

}  // namespace

std::optional<double> tangent_angle(double dx, double dy) noexcept {
  if (std::hypot(dx, dy) < kSamePoint) return std::nullopt;
  return std::atan2(dy, dx) * kRadToDeg;
}

double unwrap_near(double angle, double near) noexcept {
  return angle + 360.0 * std::round((near - angle) / 360.0);
}

double tracking_value(const CaxTrackParams& p, double theta) noexcept {
  return p.rotmode == 1 ? p.offset - theta : theta + p.offset;
}

std::pair<planner::Move, planner::Move> split_spline(const planner::Move& mv) {
  planner::Move a = mv;
  planner::Move b = mv;
  auto ca = std::make_shared<planner::SplineControl>();
  auto cb = std::make_shared<planner::SplineControl>();
  for (std::size_t i = 0; i < mv.axis_count; ++i) {
    const double p0 = mv.start[i], p1 = mv.spline->c1[i], p2 = mv.spline->c2[i], p3 = mv.end[i];
    const double p01 = 0.5 * (p0 + p1), p12 = 0.5 * (p1 + p2), p23 = 0.5 * (p2 + p3);
    const double p012 = 0.5 * (p01 + p12), p123 = 0.5 * (p12 + p23);
    const double mid = 0.5 * (p012 + p123);
    a.end[i] = mid;
    ca->c1[i] = p01;
    ca->c2[i] = p012;
    b.start[i] = mid;
    cb->c1[i] = p123;
    cb->c2[i] = p23;
  }
  a.spline = std::move(ca);
  b.spline = std::move(cb);
  b.event_tag = 0;  // the events fire once, when the first half starts
  return {std::move(a), std::move(b)};
}

std::optional<std::pair<double, double>> move_tangents(const planner::Move& mv, int x, int y) {
  const auto xs = static_cast<std::size_t>(x), ys = static_cast<std::size_t>(y);
  if (mv.spline) {
    const auto s = spline_tangent(mv, x, y, 0.0);
    const auto e = spline_tangent(mv, x, y, 1.0);
    if (!s || !e) return std::nullopt;
    return std::pair{*s, *e};
  }
  if (mv.arc) {
    const planner::Arc& a = *mv.arc;
    const double rx = mv.start[xs] - a.centre_1, ry = mv.start[ys] - a.centre_2;
    const double ex = mv.end[xs] - a.centre_1, ey = mv.end[ys] - a.centre_2;
    const double dir = a.clockwise ? -1.0 : 1.0;
    const auto s = tangent_angle(-dir * ry, dir * rx);
    if (!s) return std::nullopt;
    double sweep = (std::atan2(ey, ex) - std::atan2(ry, rx)) * kRadToDeg * dir;
    while (sweep <= kSamePoint)
      sweep += 360.0;
    if (a.full_circle || (std::hypot(ex - rx, ey - ry) < kSamePoint)) sweep = 360.0;
    return std::pair{*s, *s + dir * sweep};
  }
  const auto t = tangent_angle(mv.end[xs] - mv.start[xs], mv.end[ys] - mv.start[ys]);
  if (!t) return std::nullopt;
  return std::pair{*t, *t};
}

CaxOutcome CaxTracker::track(const planner::Move& in) {
  CaxOutcome out;
  const auto c = static_cast<std::size_t>(c_);
  planner::Move mv = in;
  if (mv.arc && (mv.arc_plane || mv.arc->axis_1 != x_ || mv.arc->axis_2 != y_)) {
    out.error = "#CAXTRACK with an arc outside the XY plane (G17 only)";
    return out;
  }
  const auto tangents = move_tangents(mv, x_, y_);
  if (!tangents) {  // no XY motion: C stays
    mv.start[c] = mv.end[c] = c_now_;
    if (mv.spline) {
      auto ctl = std::make_shared<planner::SplineControl>(*mv.spline);
      ctl->c1[c] = ctl->c2[c] = c_now_;
      mv.spline = std::move(ctl);
    }
    out.moves.push_back(std::move(mv));
    return out;
  }
  const double c_start = unwrap_near(tracking_value(p_, tangents->first), c_now_);
  out.joint_turn = std::fabs(c_start - c_now_);
  double shift = 0.0;  // the joint's turn shared out over the block (0 after a turn block)
  if (out.joint_turn > p_.anglimit + kSamePoint) {
    planner::Move turn = mv;
    turn.arc.reset();
    turn.arc_plane.reset();
    turn.spline.reset();
    turn.end = turn.start;
    turn.start[c] = c_now_;
    turn.end[c] = c_start;
    turn.rapid = true;
    turn.contour = planner::Contour::none;
    turn.transition = planner::Transition::stop_at_end;
    mv.event_tag = 0;  // the events fire with the turn block
    out.moves.push_back(std::move(turn));
    out.turned = true;
  } else {
    shift = c_now_ - c_start;
  }
  if (mv.spline) {
    fit_spline(mv, c_start, shift, 0.0, 0, out.moves);
    return out;
  }
  // Lines and arcs: C is linear in the block's parameter (arc angle), from the start value
  // (less the shared-out turn) to the end tangent's value.
  const double sweep = tracking_value(p_, tangents->second) - tracking_value(p_, tangents->first);
  mv.start[c] = c_start + shift;
  mv.end[c] = c_start + sweep;
  c_now_ = mv.end[c];
  out.moves.push_back(std::move(mv));
  return out;
}

void CaxTracker::fit_spline(const planner::Move& mv, double c_start, double shift0, double shift1,
                            int depth, std::vector<planner::Move>& out) {
  // g(u): the unwrapped tracking value along the piece plus the shared-out joint turn, which
  // falls linearly from shift0 at u = 0 to shift1 at u = 1.
  std::array<double, kSamples + 1> g{};
  double prev = c_start;
  double theta_prev = 0.0;
  for (int k = 0; k <= kSamples; ++k) {
    const double u = static_cast<double>(k) / kSamples;
    const auto theta = spline_tangent(mv, x_, y_, u);
    const double th = theta ? *theta : theta_prev;
    theta_prev = th;
    prev = unwrap_near(tracking_value(p_, th), prev);
    g[static_cast<std::size_t>(k)] = prev + shift0 + (shift1 - shift0) * u;
  }
  const double c0 = g[0], c3 = g[kSamples];
  // Hermite ends: C's derivative at both ends is the tangent's turn rate (plus the shared-out
  // turn's), so C is C1 where the path is (a knee of C at every piece joint made the joints
  // C0 and let C's acceleration step pass unbounded: docs/caxtrack.md); where the rate is
  // not defined (a doubled control point) the values at u = 1/3 and 2/3 are met instead.
  const auto r0 = spline_turn_rate(mv, x_, y_, 0.0);
  const auto r1 = spline_turn_rate(mv, x_, y_, 1.0);
  std::array<double, 4> p{};
  if (r0 && r1) {
    const double sign = p_.rotmode == 1 ? -1.0 : 1.0;
    const double turn = shift1 - shift0;
    p = {c0, c0 + (sign * *r0 + turn) / 3.0, c3 - (sign * *r1 + turn) / 3.0, c3};
  } else {
    const double a = 27.0 * g[kSamples / 3] - 8.0 * c0 - c3;
    const double b = 27.0 * g[2 * kSamples / 3] - c0 - 8.0 * c3;
    p = {c0, (2.0 * a - b) / 18.0, (2.0 * b - a) / 18.0, c3};
  }
  double err = 0.0;
  for (int k = 0; k <= kSamples; ++k) {
    const double u = static_cast<double>(k) / kSamples;
    err = std::max(err, std::fabs(bezier(p, u) - g[static_cast<std::size_t>(k)]));
  }
  if (err > kCaxFitTolerance && depth < kMaxDepth) {
    auto [first, second] = split_spline(mv);
    const double mid = 0.5 * (shift0 + shift1);
    fit_spline(first, c_start, shift0, mid, depth + 1, out);
    fit_spline(second, c_now_ - mid, mid, shift1, depth + 1, out);
    return;
  }
  planner::Move m = mv;
  const auto c = static_cast<std::size_t>(c_);
  auto ctl = std::make_shared<planner::SplineControl>(*mv.spline);
  ctl->c1[c] = p[1];
  ctl->c2[c] = p[2];
  m.spline = std::move(ctl);
  m.start[c] = p[0];
  m.end[c] = p[3];
  c_now_ = c3;
  out.push_back(std::move(m));
}

}  // namespace ncsim::tracking
