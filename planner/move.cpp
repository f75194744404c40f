// planner/move: boundary checks of the planner's inputs (API misuse throws, style.md).

#include "planner/move.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::planner {

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("planner: " + what);
}

/// A field's name for a message: a string, or a callable that builds it. validate(Move) runs
/// for every block, so its names are built only when a check fails.
template <class Name>
std::string name_of(const Name& field) {
  if constexpr (std::is_invocable_v<const Name&>)
    return field();
  else
    return std::string(field);
}

template <class Name>
void finite(double value, const Name& field) {
  if (!std::isfinite(value)) fail(name_of(field) + " is not finite (" + core::human(value) + ")");
}

template <class Name>
void positive(double value, const Name& field) {
  finite(value, field);
  if (value <= 0.0) fail(name_of(field) + " must be > 0, got " + core::human(value));
}

}  // namespace

double contour_bound(const Move& move) noexcept {
  switch (move.contour) {
    case Contour::none:
      return 0.0;
    case Contour::tolerance:
      return move.path_dev;
    case Contour::distance:
      return std::max(move.pre_dist, move.post_dist);
  }
  return 0.0;
}

void validate(const Move& move) {
  const auto at = [&move] { return "line " + std::to_string(move.line) + ": "; };
  if (move.axis_count == 0 || move.axis_count > kMaxAxes)
    fail(at() + "axis_count " + std::to_string(move.axis_count) + " outside 1.." +
         std::to_string(kMaxAxes));
  for (std::size_t i = 0; i < move.axis_count; ++i) {
    finite(move.start[i], [&] { return at() + "start[" + std::to_string(i) + "]"; });
    finite(move.end[i], [&] { return at() + "end[" + std::to_string(i) + "]"; });
  }
  if (!move.rapid && !move.block_time) positive(move.feed, [&] { return at() + "feed"; });
  if (move.block_time) positive(*move.block_time, [&] { return at() + "block_time (G93)"; });
  if (move.end_feed) {
    finite(*move.end_feed, [&] { return at() + "end_feed (E)"; });
    if (*move.end_feed < 0.0) fail(at() + "end_feed (E) < 0");
  }
  if (move.contour == Contour::tolerance)
    positive(move.path_dev, [&] { return at() + "path_dev (PATH_DEV)"; });
  if (move.contour == Contour::distance) {
    positive(move.pre_dist, [&] { return at() + "pre_dist (PRE_DIST)"; });
    positive(move.post_dist, [&] { return at() + "post_dist (POST_DIST)"; });
  }
  if (move.transvelmin) {
    finite(*move.transvelmin, [&] { return at() + "transvelmin"; });
    if (*move.transvelmin < 0.0) fail(at() + "transvelmin < 0");
  }
  if (move.arc && move.spline) fail(at() + "a move is an arc or a spline piece, not both");
  if (move.spline) {
    for (std::size_t i = 0; i < move.axis_count; ++i) {
      finite(move.spline->c1[i], [&] { return at() + "spline c1[" + std::to_string(i) + "]"; });
      finite(move.spline->c2[i], [&] { return at() + "spline c2[" + std::to_string(i) + "]"; });
    }
  }
  if (move.belt_joints) {
    for (std::size_t i = 0; i < kMaxAxes; ++i) {
      finite(move.belt_joints->a[i],
             [&] { return at() + "belt_joints a[" + std::to_string(i) + "]"; });
      finite(move.belt_joints->j[i],
             [&] { return at() + "belt_joints j[" + std::to_string(i) + "]"; });
      if (move.belt_joints->a[i] < 0.0 || move.belt_joints->j[i] < 0.0)
        fail(at() + "belt_joints < 0 at joint " + std::to_string(i));
    }
  }
  if (move.arc && move.arc_plane) {
    const ArcPlane& g = *move.arc_plane;
    double uu = 0.0, vv = 0.0, uv = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      if (g.axes[k] >= move.axis_count)
        fail(at() + "arc plane axis " + std::to_string(g.axes[k]) + " invalid for " +
             std::to_string(move.axis_count) + " axes");
      finite(g.u[k], [&] { return at() + "arc plane u"; });
      finite(g.v[k], [&] { return at() + "arc plane v"; });
      finite(g.centre[k], [&] { return at() + "arc plane centre"; });
      uu += g.u[k] * g.u[k];
      vv += g.v[k] * g.v[k];
      uv += g.u[k] * g.v[k];
    }
    if (g.axes[0] == g.axes[1] || g.axes[1] == g.axes[2] || g.axes[0] == g.axes[2])
      fail(at() + "arc plane axes not distinct");
    if (std::abs(uu - 1.0) > kRelTol || std::abs(vv - 1.0) > kRelTol || std::abs(uv) > kRelTol)
      fail(at() + "arc plane u, v not orthonormal");
    double x = 0.0, y = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      x += (move.start[g.axes[k]] - g.centre[k]) * g.u[k];
      y += (move.start[g.axes[k]] - g.centre[k]) * g.v[k];
    }
    positive(std::hypot(x, y), [&] { return at() + "arc radius"; });
  } else if (move.arc) {
    const Arc& arc = *move.arc;
    if (arc.axis_1 >= move.axis_count || arc.axis_2 >= move.axis_count || arc.axis_1 == arc.axis_2)
      fail(at() + "arc plane axes " + std::to_string(arc.axis_1) + "/" +
           std::to_string(arc.axis_2) + " invalid for " + std::to_string(move.axis_count) +
           " axes");
    finite(arc.centre_1, [&] { return at() + "arc centre_1"; });
    finite(arc.centre_2, [&] { return at() + "arc centre_2"; });
    const double r =
        std::hypot(move.start[arc.axis_1] - arc.centre_1, move.start[arc.axis_2] - arc.centre_2);
    positive(r, [&] { return at() + "arc radius"; });
  }
}

void validate(std::span<const AxisLimits> limits) {
  if (limits.empty() || limits.size() > kMaxAxes)
    fail("axis limit count " + std::to_string(limits.size()) + " outside 1.." +
         std::to_string(kMaxAxes));
  for (std::size_t i = 0; i < limits.size(); ++i) {
    const AxisLimits& ax = limits[i];
    const std::string at = "axis " + std::to_string(i) + " ";
    positive(ax.v_max, at + "v_max");
    positive(ax.v_reference, at + "v_reference");
    positive(ax.v_rapid, at + "v_rapid");
    positive(ax.a_max, at + "a_max");
    positive(ax.d_max, at + "d_max");
    positive(ax.j_max, at + "j_max");
    finite(ax.c0, at + "c0 (VELOJUMP factor)");
    finite(ax.a_rapid, at + "a_rapid (P-AXIS-00004)");
    finite(ax.j_rapid, at + "j_rapid (P-AXIS-00004 / 00200)");
    if (ax.a_rapid < 0.0)
      fail(at + "a_rapid (P-AXIS-00004) < 0, got " + std::to_string(ax.a_rapid));
    if (ax.j_rapid < 0.0)
      fail(at + "j_rapid (P-AXIS-00004 / 00200) < 0, got " + std::to_string(ax.j_rapid));
    if (ax.c0 < 0.0) fail(at + "c0 (VELOJUMP factor) < 0, got " + std::to_string(ax.c0));
  }
}

AxisLimits belt_limits(const AxisLimits& axis, double taken) noexcept {
  if (taken == 0.0 || !std::isfinite(taken)) return axis;
  // `taken` < 0 (against the belt) raises the velocities by |taken|.
  const auto left = [taken](double v) { return std::max(v - taken, 0.01 * v); };
  AxisLimits out = axis;
  out.v_max = left(axis.v_max);
  out.v_reference = left(axis.v_reference);
  out.v_rapid = left(axis.v_rapid);
  return out;
}

AxisLimits belt_joint_limits(const AxisLimits& joint, double a, double j) noexcept {
  const auto left = [](double limit, double taken) {
    return taken > 0.0 ? std::max(limit - taken, 0.01 * limit) : limit;
  };
  AxisLimits out = joint;
  out.a_max = left(joint.a_max, a);
  out.d_max = left(joint.d_max, a);
  out.j_max = left(joint.j_max, j);
  return out;
}

AxisLimits reserved_limits(const AxisLimits& axis, double reserve) noexcept {
  if (!(reserve > 0.0)) return axis;
  AxisLimits out = axis;
  const double keep = 1.0 - reserve;
  out.a_max *= keep;
  out.d_max *= keep;
  out.j_max *= keep;
  out.a_rapid *= keep;
  out.j_rapid *= keep;
  return out;
}

AxisLimits weighted_limits(const AxisLimits& axis, const AxisWeights& w, std::size_t i,
                           bool rapid) noexcept {
  constexpr double kCreep = 0.001;  // [mm/s] 1 um/s
  AxisLimits out = axis;
  if (rapid) {
    out.v_rapid = std::max(axis.v_rapid * w.v[i], kCreep);
  } else {
    out.v_max = std::max(axis.v_max * w.v[i], kCreep);
    out.v_reference = std::min(axis.v_reference, out.v_max);
  }
  out.a_max *= w.a[i];
  out.d_max *= w.a[i];
  out.a_rapid *= w.a[i];
  out.j_max *= w.j[i];
  out.j_rapid *= w.j[i];
  return out;
}

AxisLimits rapid_limits(const AxisLimits& axis) noexcept {
  AxisLimits r = axis;
  if (axis.a_rapid > 0.0) r.a_max = r.d_max = axis.a_rapid;
  if (axis.j_rapid > 0.0) r.j_max = axis.j_rapid;
  return r;
}

AxisLimits joint_slope(const AxisLimits& axis, bool rapid_in, bool rapid_out) noexcept {
  if (!rapid_in && !rapid_out) return axis;
  const AxisLimits r = rapid_limits(axis);
  if (rapid_in && rapid_out) return r;
  AxisLimits both = axis;
  both.a_max = std::min(axis.a_max, r.a_max);
  both.d_max = std::min(axis.d_max, r.d_max);
  both.j_max = std::min(axis.j_max, r.j_max);
  return both;
}

}  // namespace ncsim::planner
