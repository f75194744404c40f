// ipo/x_virtual: the static processing unit's belt feed (see x_virtual.hpp).

#include "ipo/x_virtual.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "ipo/caxtrack.hpp"
#include "planner/limits.hpp"
#include "planner/path.hpp"

namespace ncsim::ipo {

namespace {

constexpr int kMaxDepth = 6;  ///< halvings of a spline piece at most (64 parts)
constexpr int kSamples = 16;  ///< X-share samples per spline part

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

std::string format(const char* fmt, double a, double b) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

/// Sets the belt feed of one part and checks it against the planner's limits.
std::optional<XvError> finish(planner::Move& mv, double length, const XVirtualParams& p,
                              std::span<const planner::AxisLimits> limits,
                              std::span<const std::string> names) {
  const double dx = mv.end[static_cast<std::size_t>(p.x)] - mv.start[static_cast<std::size_t>(p.x)];
  mv.rapid = false;
  mv.block_time.reset();
  mv.end_feed.reset();
  mv.feed = p.v_belt * length / std::fabs(dx);
  const planner::Segment seg = planner::Segment::from_move(mv);
  const planner::PathLimits pl = planner::path_limits(seg, mv, limits);
  if (pl.v_max >= mv.feed * (1.0 - 1e-9)) return std::nullopt;
  const char* what = pl.limit == planner::VelocityLimit::axis_velocity ? "velocity"
                     : pl.limit == planner::VelocityLimit::centripetal ? "acceleration"
                                                                       : "jerk";
  const std::size_t axis = std::min<std::size_t>(pl.limiting_axis, names.size() - 1);
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "x_virtual: a belt at %.6g mm/s (1.1 x CONV_VEL, the fastest before 50653) needs a "
                "path velocity of %.6g mm/s here; axis %s's %s allows only %.6g mm/s: a dynamic "
                "error, the belt cannot be slowed (004 l.440, l.621)",
                p.v_belt, mv.feed, names[axis].c_str(), what, pl.v_max);
  return XvError{kXvTooFastId, buf};
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
  if (!mv.spline) {
    const double dx = mv.end[x] - mv.start[x];
    if (dx * p.sign >= -1e-9) {
      out.error = XvError{kXvDirectionId,
                          format("x_virtual: the block must run against the conveying direction "
                                 "(004 l.439): X moves by %.6g mm (the belt moves in %+g X)",
                                 dx, p.sign)};
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
  // A spline piece: halve it until the X share varies little over each part.
  std::vector<std::pair<planner::Move, int>> todo{{mv, 0}};
  while (!todo.empty()) {
    auto [part, depth] = std::move(todo.front());
    todo.erase(todo.begin());
    double lo = 1e300, hi = 0.0;
    for (int k = 0; k <= kSamples; ++k) {
      const double u = static_cast<double>(k) / kSamples;
      const auto [speed, vx] = speeds(part, p, std::clamp(u, 1e-4, 1.0 - 1e-4));
      if (vx * p.sign >= 0.0 || speed <= 0.0) {
        out.error = XvError{kXvDirectionId,
                            format("x_virtual: the spline must run against the conveying "
                                   "direction everywhere (004 l.439): X turns near X = %.6g mm "
                                   "(the belt moves in %+g X)",
                                   part.start[x], p.sign)};
        return out;
      }
      const double share = std::fabs(vx) / speed;
      lo = std::min(lo, share);
      hi = std::max(hi, share);
    }
    if ((hi - lo) > kXvFeedSpread * lo && depth < kMaxDepth) {
      auto [a, b] = split_spline(part);
      todo.insert(todo.begin(), {std::move(b), depth + 1});
      todo.insert(todo.begin(), {std::move(a), depth + 1});
      continue;
    }
    if (auto e = finish(part, spline_length(part, p), p, limits, names)) {
      out.error = std::move(e);
      return out;
    }
    out.moves.push_back(std::move(part));
  }
  return out;
}

}  // namespace ncsim::ipo
