// tracking/x_virtual: the static processing unit's belt feed (see x_virtual.hpp).

#include "tracking/x_virtual.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"
#include "planner/blend.hpp"
#include "planner/corner.hpp"
#include "planner/limits.hpp"
#include "planner/path.hpp"
#include "tracking/caxtrack.hpp"

namespace ncsim::tracking {

namespace {

constexpr int kMaxDepth = 6;      ///< halvings of a spline piece at most (64 parts)
constexpr int kMaxArcDepth = 10;  ///< halvings of an arc at most (1024 parts)
constexpr int kSamples = 16;      ///< X-share samples per spline / arc part
constexpr double kTwoPi = 6.283185307179586;

bool metric(const XVirtualParams& p, std::size_t i) {
  return ((p.path_axes >> i) & 1u) != 0;
}

/// d/du of the spline Move's axis i at u.
double d1(const planner::Move& mv, std::size_t i, double u) {
  const double w = 1.0 - u;
  return 3.0 * (w * w * (mv.spline->c1[i] - mv.start[i]) +
                2.0 * w * u * (mv.spline->c2[i] - mv.spline->c1[i]) +
                u * u * (mv.end[i] - mv.spline->c2[i]));
}

/// |dP/du| over the path axes and dX/du of a spline Move at u.
std::pair<double, double> speeds(const planner::Move& mv, const XVirtualParams& p, double u) {
  double sum = 0.0;
  for (std::size_t i = 0; i < mv.axis_count; ++i)
    if (metric(p, i)) sum += d1(mv, i, u) * d1(mv, i, u);
  return {std::sqrt(sum), d1(mv, static_cast<std::size_t>(p.x), u)};
}

/// An arc Move (G17/G18/G19 plane of two machine axes) as angle(u) = phi0 + dir * sweep * u,
/// u in [0, 1]; the other axes (a helix's, a tracking C) linear in u, as the planner and
/// tracking/caxtrack run them.
struct ArcGeom {
  std::size_t a1 = 0, a2 = 1;  ///< plane axes (slots)
  double c1 = 0.0, c2 = 0.0;   ///< centre [mm]
  double r = 0.0;              ///< radius at the start [mm]
  double phi0 = 0.0;           ///< start angle [rad]
  double sweep = 0.0;          ///< swept angle, > 0 [rad]
  double dir = 1.0;            ///< +1 G03, -1 G02
};

ArcGeom arc_geom(const planner::Move& mv) {
  const planner::Arc& a = *mv.arc;
  ArcGeom g;
  g.a1 = a.axis_1;
  g.a2 = a.axis_2;
  g.c1 = a.centre_1;
  g.c2 = a.centre_2;
  const double rx = mv.start[g.a1] - g.c1, ry = mv.start[g.a2] - g.c2;
  const double ex = mv.end[g.a1] - g.c1, ey = mv.end[g.a2] - g.c2;
  g.r = std::hypot(rx, ry);
  g.dir = a.clockwise ? -1.0 : 1.0;
  g.phi0 = std::atan2(ry, rx);
  g.sweep = (std::atan2(ey, ex) - g.phi0) * g.dir;
  while (g.sweep <= kTiny)
    g.sweep += kTwoPi;
  if (a.full_circle) g.sweep = kTwoPi;
  return g;
}

/// d/du of the arc Move's axis i at u.
double arc_d1(const planner::Move& mv, const ArcGeom& g, std::size_t i, double u) {
  const double phi = g.phi0 + g.dir * g.sweep * u;
  if (i == g.a1) return -g.r * std::sin(phi) * g.dir * g.sweep;
  if (i == g.a2) return g.r * std::cos(phi) * g.dir * g.sweep;
  return mv.end[i] - mv.start[i];
}

/// The arc Move's point at u (axis i).
double arc_point(const planner::Move& mv, const ArcGeom& g, std::size_t i, double u) {
  const double phi = g.phi0 + g.dir * g.sweep * u;
  if (i == g.a1) return g.c1 + g.r * std::cos(phi);
  if (i == g.a2) return g.c2 + g.r * std::sin(phi);
  return mv.start[i] + (mv.end[i] - mv.start[i]) * u;
}

/// |dP/du| over the path axes and dX/du of an arc Move at u.
std::pair<double, double> arc_speeds(const planner::Move& mv, const XVirtualParams& p, double u) {
  const ArcGeom g = arc_geom(mv);
  double sum = 0.0;
  for (std::size_t i = 0; i < mv.axis_count; ++i)
    if (metric(p, i)) sum += arc_d1(mv, g, i, u) * arc_d1(mv, g, i, u);
  return {std::sqrt(sum), arc_d1(mv, g, static_cast<std::size_t>(p.x), u)};
}

/// Path length of an arc / helix Move over the path axes (constant speed in u: exact).
double arc_length(const planner::Move& mv, const XVirtualParams& p) {
  return arc_speeds(mv, p, 0.0).first;
}

/// NC9100 unless the planner's own limits of `curve`, planned as `probe` asked for `need`
/// [mm/s], allow `need`; `where` names the place (after "mm/s"), `there` echoes it (after the
/// limit).
std::optional<XvError> belt_too_fast(const planner::Segment& curve, planner::Move probe,
                                     double need, const XVirtualParams& p,
                                     std::span<const planner::AxisLimits> limits,
                                     std::span<const std::string> names, const std::string& where,
                                     const char* there) {
  probe.feed = need;  // the planner caps at the programmed feed: ask for `need`
  const planner::PathLimits pl = planner::path_limits(curve, probe, limits);
  if (pl.v_max >= need * (1.0 - kRelTol)) return std::nullopt;
  const char* what = pl.limit == planner::VelocityLimit::axis_velocity ? "velocity"
                     : pl.limit == planner::VelocityLimit::centripetal ? "acceleration"
                                                                       : "jerk";
  const std::size_t axis = std::min<std::size_t>(pl.limiting_axis, names.size() - 1);
  return XvError{kXvTooFastId,
                 "x_virtual: a belt at " + core::human(p.v_belt) +
                     " mm/s (1.1 x CONV_VEL, the fastest before 50653) needs a path velocity of " +
                     core::human(need) + " mm/s" + where + " here; axis " + names[axis] + "'s " +
                     what + " allows only " + core::human(pl.v_max) + " mm/s" + there +
                     ": a dynamic error, the belt cannot be slowed (004 l.440, l.621)"};
}

}  // namespace

std::pair<planner::Move, planner::Move> split_arc(const planner::Move& mv) {
  const ArcGeom g = arc_geom(mv);
  planner::Move a = mv;
  planner::Move b = mv;
  for (std::size_t i = 0; i < mv.axis_count; ++i)
    a.end[i] = b.start[i] = arc_point(mv, g, i, 0.5);
  a.arc->full_circle = false;
  b.arc->full_circle = false;
  b.event_tag = 0;  // the events fire once, when the first half starts
  return {std::move(a), std::move(b)};
}

namespace {

/// Arc length of a spline Move over the path axes (Gauss-Legendre, 5 points).
double spline_length(const planner::Move& mv, const XVirtualParams& p) {
  constexpr std::array<double, 5> x{-0.9061798459386640, -0.5384693101056831, 0.0,
                                    0.5384693101056831, 0.9061798459386640};
  constexpr std::array<double, 5> w{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                    0.4786286704993665, 0.2369268850561891};
  double len = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    len += w[k] * speeds(mv, p, 0.5 * (x[k] + 1.0)).first;
  return 0.5 * len;
}

/// Sets the belt feed of one part and checks it against the planner's limits.
std::optional<XvError> finish(planner::Move& mv, double length, const XVirtualParams& p,
                              std::span<const planner::AxisLimits> limits,
                              std::span<const std::string> names, double peak_feed = 0.0) {
  const double dx = mv.end[static_cast<std::size_t>(p.x)] - mv.start[static_cast<std::size_t>(p.x)];
  mv.rapid = false;
  mv.block_time.reset();
  mv.end_feed.reset();
  // A curved part is planned at the velocity its steepest point needs (its
  // smallest X share), so the plan is nowhere slower than the belt asks; where it is faster the
  // channel's velocity cap brings the X component down to the belt's (channel/channel_static.cpp).
  mv.feed = std::max(p.v_belt * length / std::fabs(dx), peak_feed);
  return belt_too_fast(planner::Segment::from_move(mv), mv, mv.feed, p, limits, names, "", "");
}

}  // namespace

double x_share(const planner::Move& mv, const XVirtualParams& p) noexcept {
  double sum = 0.0;
  for (std::size_t i = 0; i < mv.axis_count; ++i)
    if (metric(p, i)) sum += (mv.end[i] - mv.start[i]) * (mv.end[i] - mv.start[i]);
  const double len = std::sqrt(sum);
  if (len <= 0.0) return 0.0;
  return std::fabs(mv.end[static_cast<std::size_t>(p.x)] -
                   mv.start[static_cast<std::size_t>(p.x)]) /
         len;
}

double line_belt_feed(const planner::Move& mv, const XVirtualParams& p) noexcept {
  const double share = x_share(mv, p);
  return share > 0.0 ? p.v_belt / share : 0.0;
}

XvOutcome belt_feed(const planner::Move& mv, const XVirtualParams& p,
                    std::span<const planner::AxisLimits> limits,
                    std::span<const std::string> names) {
  XvOutcome out;
  const auto x = static_cast<std::size_t>(p.x);
  if (!mv.spline && !mv.arc) {
    const double dx = mv.end[x] - mv.start[x];
    if (dx * p.sign >= -kSamePoint) {
      out.error = XvError{kXvDirectionId,
                          "x_virtual: the block must run against the conveying direction "
                          "(004 l.439): X moves by " +
                              core::human(dx) + " mm (the belt moves in " +
                              core::signed_human(p.sign) + " X)"};
      return out;
    }
    planner::Move m = mv;
    double sum = 0.0;
    for (std::size_t i = 0; i < mv.axis_count; ++i)
      if (metric(p, i)) sum += (mv.end[i] - mv.start[i]) * (mv.end[i] - mv.start[i]);
    if (auto e = finish(m, std::sqrt(sum), p, limits, names)) {
      out.error = std::move(e);
      return out;
    }
    out.moves.push_back(std::move(m));
    return out;
  }
  // A spline piece or an arc: halve it until the X share varies little over each part.
  const bool arc = mv.arc.has_value();
  const auto at = [&](const planner::Move& m, double u) {
    return arc ? arc_speeds(m, p, u) : speeds(m, p, u);
  };
  std::vector<std::pair<planner::Move, int>> todo{{mv, 0}};
  while (!todo.empty()) {
    auto [part, depth] = std::move(todo.front());
    todo.erase(todo.begin());
    double lo = 1e300, hi = 0.0;
    for (int k = 0; k <= kSamples; ++k) {
      const double u = static_cast<double>(k) / kSamples;
      const auto [speed, vx] = at(part, std::clamp(u, 1e-4, 1.0 - 1e-4));
      if (vx * p.sign >= 0.0 || speed <= 0.0) {
        out.error =
            XvError{kXvDirectionId, std::string("x_virtual: the ") + (arc ? "arc" : "spline") +
                                        " must run against the conveying direction everywhere (004 "
                                        "l.439): X turns near X = " +
                                        core::human(part.start[x]) + " mm (the belt moves in " +
                                        core::signed_human(p.sign) + " X)"};
        return out;
      }
      const double share = std::fabs(vx) / speed;
      lo = std::min(lo, share);
      hi = std::max(hi, share);
    }
    if ((hi - lo) > kXvFeedSpread * lo && depth < (arc ? kMaxArcDepth : kMaxDepth)) {
      auto [a, b] = arc ? split_arc(part) : split_spline(part);
      todo.insert(todo.begin(), {std::move(b), depth + 1});
      todo.insert(todo.begin(), {std::move(a), depth + 1});
      continue;
    }
    const double length = arc ? arc_length(part, p) : spline_length(part, p);
    if (auto e = finish(part, length, p, limits, names, p.v_belt / lo)) {
      out.error = std::move(e);
      return out;
    }
    out.moves.push_back(std::move(part));
  }
  return out;
}

std::optional<XvError> blend_belt_feed(planner::Move& in, planner::Move& out,
                                       const XVirtualParams& p,
                                       std::span<const planner::AxisLimits> limits,
                                       std::span<const std::string> names) {
  constexpr int kBallSamples = 64;  // X-share samples over the ball
  const planner::Segment a = planner::Segment::from_move(in);
  const planner::Segment b = planner::Segment::from_move(out);
  // As planner::Preparer::push_path (planner::corner_blend, DEV or DIST): each side gives at
  // most half of its part.
  const std::optional<planner::Blend> ball =
      planner::corner_blend(in, a, b, a.length() / 2, b.length() / 2);
  if (!ball) return std::nullopt;
  const auto x = static_cast<std::size_t>(p.x);
  double lo = 1e300;  // smallest X share over the ball
  for (int k = 0; k <= kBallSamples; ++k) {
    const planner::PathPoint q =
        ball->curve.at(ball->curve.length() * static_cast<double>(k) / kBallSamples);
    double sum = 0.0;
    for (std::size_t i = 0; i < in.axis_count; ++i)
      if (metric(p, i)) sum += q.d1[i] * q.d1[i];
    if (q.d1[x] * p.sign >= 0.0 || sum <= 0.0)
      return XvError{
          kXvDirectionId,
          "x_virtual: the tolerance ball (G61/G261, radius " + core::human(ball->radius) +
              " mm) turns the path along the conveying direction near X = " + core::human(q.x[x]) +
              " mm (004 l.439)"};
    lo = std::min(lo, std::fabs(q.d1[x]) / std::sqrt(sum));
  }
  const double need = p.v_belt / lo;  // path velocity where the ball runs steepest [mm/s]
  in.feed = std::max(in.feed, need);
  out.feed = std::max(out.feed, need);
  const std::string where =
      " in the tolerance ball (G61/G261, radius " + core::human(ball->radius) + " mm)";
  return belt_too_fast(ball->curve, in, need, p, limits, names, where, " there");
}

std::optional<XvError> joint_belt_check(const planner::Move& in, const planner::Move& out,
                                        const XVirtualParams& p,
                                        std::span<const planner::AxisLimits> limits,
                                        const planner::ChannelLimits& channel,
                                        std::span<const std::string> names) {
  const planner::Segment a = planner::Segment::from_move(in);
  const planner::Segment b = planner::Segment::from_move(out);
  // As planner::Preparer::push_path: a tolerance ball makes the joint C2 (blend_belt_feed).
  if (planner::corner_blend(in, a, b, a.length() / 2, b.length() / 2)) return std::nullopt;
  const planner::PathPoint end = a.at(a.length());
  const planner::PathPoint start = b.at(0.0);
  const auto x = static_cast<std::size_t>(p.x);
  const double share = std::min(std::fabs(end.d1[x]), std::fabs(start.d1[x]));
  if (!(share > 0.0)) return std::nullopt;  // NC9102 is belt_feed's
  const double need = p.v_belt / share;     // [mm/s] the path velocity at the joint
  // As planner::Preparer::emit_joint: #TRANSVELMIN does not act at a contoured joint.
  const std::optional<double> v_min = planner::contoured(in) ? std::nullopt : in.transvelmin;
  const std::uint8_t n = std::max(a.axis_count(), b.axis_count());
  const planner::Link link =
      planner::link_velocity(end, start, n, a.metric() | b.metric(), limits, channel, need, need,
                             v_min, planner::jerk_limited(in.slope));
  if (link.v_link >= need * (1.0 - kRelTol)) return std::nullopt;
  const std::size_t axis = std::min<std::size_t>(link.limiting_axis, names.size() - 1);
  const bool knee = link.cls == planner::TransitionClass::c0;
  // A knee's link is VELOJUMP's, or the C1 rule's where the curvature jump binds first
  // (planner::link_velocity; docs/planner.md "Corners").
  const bool velojump = link.rule == planner::LinkRule::velojump;
  return XvError{
      kXvTooFastId,
      "x_virtual: a belt at " + core::human(p.v_belt) +
          " mm/s (1.1 x CONV_VEL, the fastest before 50653) needs a path velocity of " +
          core::human(need) + " mm/s at this block's end, " +
          (knee ? "a knee (an axis's tangent jumps)" : "a C1 joint (the curvature jumps)") +
          "; axis " + names[axis] + "'s " +
          (velojump ? "acceleration (VELOJUMP, one cycle's velocity step)"
                    : "jerk (the C1 rule, one cycle's acceleration step)") +
          " allows only " + core::human(link.v_link) +
          " mm/s there: a dynamic error, the belt cannot be slowed (004 l.440, l.441: the "
          "contour must be C2, l.621)"};
}

}  // namespace ncsim::tracking
