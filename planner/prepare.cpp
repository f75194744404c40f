// planner/prepare: joints between consecutive Moves (rules in prepare.hpp).

#include "planner/prepare.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"
#include "jerk/jerk.hpp"
#include "planner/blend.hpp"

namespace ncsim::planner {

namespace {

constexpr double kMinLength = 1e-9;  // [mm] shorter moves carry no path

/// How far above a chain's cap a part joined across different caps could have gone on its
/// own (docs/planner.md "Chains": chains across caps).
constexpr double kChainCapSlack = 0.01;

/// Path jerk the kernel plans with (the look-ahead's: STEP slopes spread the acceleration step
/// over one cycle).
double planning_jerk(const PathLimits& lim, double t_cycle) {
  return std::isfinite(lim.j_max) ? lim.j_max : std::max(lim.a_max, lim.d_max) / t_cycle;
}

/// A side whose cap is its programmed feed is not lowered below it: the feed may be a
/// requirement (the static processing unit's belt feed, tracking/x_virtual.cpp, where the X share
/// of the path velocity must equal the belt's).
bool feed_must_hold(const PathLimits& lim, double cap) {
  return lim.limit == VelocityLimit::programmed && lim.v_max > cap;
}

/// A run of parts (highest own cap v_hi [mm/s], `length` [mm], path limits `lim`) loses at most
/// kChainCapSlack of its velocity when planned under the lower cap `cap`: its own caps are within
/// that of `cap`, or it is too short to rise more than that above `cap` even when it is entered
/// at `cap` with a = 0 and may leave at any velocity (jerk::reachable_velocity).
bool fits_under(double cap, double v_hi, double length, const PathLimits& lim, double t_cycle) {
  const double top = (1.0 + kChainCapSlack) * cap;
  if (v_hi <= top) return true;
  return jerk::reachable_velocity(cap, 0.0, length, lim.a_max, planning_jerk(lim, t_cycle)) <= top;
}

StopReason requested_stop(const Move& move) {
  if (move.transition == Transition::stop_at_end) return StopReason::stop_at_end;
  if (move.exact_stop) return StopReason::exact_stop;
  return StopReason::none;
}

/// A knee that VELOJUMP passes at both blocks' velocity caps and that carries the path
/// acceleration (corner.hpp) is left unblended under G261: a blend could only be slower there
/// (its change of curvature caps its velocity) and the programmed path is inside every ball
/// (docs/planner.md "Tolerance balls"). `ends` is joint_ends(in, out); `cap()` is the smaller of
/// the two blocks' velocity caps on `axes` (path_limits), asked only when it decides.
template <class Cap>
bool knee_needs_no_ball(const Segment& in, const Segment& out, const JointEnds& ends,
                        std::span<const AxisLimits> axes, const ChannelLimits& channel,
                        const Cap& cap) {
  const std::uint8_t n = std::max(in.axis_count(), out.axis_count());
  const PathPoint& a = ends.in_end;
  const PathPoint& b = ends.out_start;
  if (classify_at_angle(a, b, n, ends.angle) != TransitionClass::c0) return false;
  const std::span<const AxisLimits> used = axes.first(std::min<std::size_t>(axes.size(), n));
  if (!knee_carries_acceleration(a.d1, b.d1, used, channel.t_cycle)) return false;
  return velojump_velocity(a.d1, b.d1, used, channel.t_cycle) >= cap();
}

}  // namespace

Preparer::Preparer(std::span<const AxisLimits> axes, ChannelLimits channel)
    : axes_(axes), channel_(channel) {
  validate(axes);
  if (!(channel.t_cycle > 0.0))
    throw std::invalid_argument("planner: interpolation cycle must be > 0, got " +
                                core::human(channel.t_cycle));
}

void Preparer::set_joints(JointLimits joints) {
  if (!joints.inverse) throw std::invalid_argument("planner: joint limits without an inverse map");
  validate(joints.joints);
  if (!joints.cartesian.empty()) {
    if (joints.cartesian.size() != axes_.size())
      throw std::invalid_argument("planner: " + std::to_string(joints.cartesian.size()) +
                                  " Cartesian limits for " + std::to_string(axes_.size()) +
                                  " axes");
    validate(joints.cartesian);
  }
  joints_ = std::move(joints);
  if (pending()) pending()->limits.reset();  // computed with the joint limits before
}

std::span<const AxisLimits> Preparer::axes_for(const Move& move) const {
  const std::span<const AxisLimits> axes = belt_axes_for(move);
  if (!move.weights) return axes;
  // Dynamics weightings (AxisWeights, docs/interp.md "Dynamics weighting").
  const std::size_t n = std::min(axes.size(), weighted_axes_.size());
  for (std::size_t i = 0; i < n; ++i)
    weighted_axes_[i] = weighted_limits(axes[i], *move.weights, i, move.rapid);
  return std::span<const AxisLimits>(weighted_axes_.data(), n);
}

std::span<const AxisLimits> Preparer::belt_axes_for(const Move& move) const {
  std::span<const AxisLimits> axes = axes_;
  if (move.transformed && joints_ && !joints_->cartesian.empty()) axes = joints_->cartesian;
  // A PCS1 block on a conveyor: the belt's share taken off (belt_limits).
  // A share is 0 when its bits but the sign are all 0 (+0 and -0); the 16 shares' bits are
  // or-ed without a branch each (most blocks are on no belt: every share is looked at).
  std::uint64_t bits = 0;
  for (const double b : move.belt)
    bits |= std::bit_cast<std::uint64_t>(b) << 1;
  if (bits == 0) return axes;
  for (std::size_t i = 0; i < axes.size() && i < belt_axes_.size(); ++i) {
    belt_axes_[i] = belt_limits(axes[i], move.belt[i]);
    // The belt's own acceleration and jerk get the reserve (NCSIM-CHAN-640)
    if (move.belt[i] != 0.0) belt_axes_[i] = reserved_limits(belt_axes_[i], channel_.belt_reserve);
  }
  return std::span<const AxisLimits>(belt_axes_.data(), std::min(axes.size(), belt_axes_.size()));
}

const JointLimits* Preparer::joints_for(const Move& move) const {
  return move.transformed && joints_ ? &*joints_ : nullptr;
}

PathLimits Preparer::limits(const Segment& path, const Move& move) const {
  const JointLimits* joints = joints_for(move);
  if (joints == nullptr) return path_limits(path, move, axes_for(move));
  std::span<const AxisLimits> joint_limits = joints->joints;
  if (move.belt_joints && joints->joints.size() <= belt_joints_.size()) {
    // A PCS1 block under #TRAFO ON: the belt's share taken off the joints.
    for (std::size_t i = 0; i < joints->joints.size(); ++i)
      belt_joints_[i] = reserved_limits(
          belt_joint_limits(joints->joints[i], move.belt_joints->a[i], move.belt_joints->j[i]),
          channel_.belt_reserve);  // NCSIM-CHAN-640
    joint_limits = std::span<const AxisLimits>(belt_joints_.data(), joints->joints.size());
  }
  const std::optional<PathLimits> l =
      path_limits(path, move, axes_for(move), joints->inverse, joint_limits);
  if (!l)
    throw KinematicError(move.line,
                         "the path leaves the workspace of the kinematic transform [NC3201]");
  return *l;
}

PreparedSegment Preparer::make(const Segment& path, const Move& move, bool blend) const {
  return make(path, move, blend, limits(path, move));
}

PreparedSegment Preparer::make(const Segment& path, const Move& move, bool blend,
                               const PathLimits& limits) const {
  PreparedSegment ps;
  ps.path = Chain(path, move.line);
  ps.limits = limits;
  if (!blend && joints_for(move) == nullptr)
    ps.option_count =
        static_cast<std::uint8_t>(arc_options(path, move, axes_for(move), limits, ps.options));
  ps.blend = blend;
  ps.line = move.line;
  return ps;
}

const PathLimits& Preparer::pending_limits(Pending& p) const {
  if (!p.limits) p.limits = limits(p.path, p.move);
  return *p.limits;
}

std::span<const AxisLimits> Preparer::slopes_at_joint(std::span<const AxisLimits> axes,
                                                      bool rapid_in, bool rapid_out) const {
  if (!rapid_in && !rapid_out) return axes;
  const std::size_t n = std::min(axes.size(), joint_axes_.size());
  for (std::size_t i = 0; i < n; ++i)
    joint_axes_[i] = joint_slope(axes[i], rapid_in, rapid_out);
  return std::span<const AxisLimits>(joint_axes_.data(), n);
}

void Preparer::emit_joint(PreparedSegment in, const Move& in_move, const Segment& out_path,
                          bool out_rapid, double v_out, std::vector<PreparedSegment>& out,
                          const JointEnds* ends) {
  const std::uint8_t n = std::max(in.path.axis_count(), out_path.axis_count());
  const AxisMask metric = in.path.metric() | out_path.metric();
  const std::optional<double> v_min = transvelmin_at_end(in_move);
  const std::span<const AxisLimits> axes =
      slopes_at_joint(axes_for(in_move), in_move.rapid, out_rapid);
  const Link link =
      ends != nullptr
          ? link_velocity(ends->in_end, ends->out_start, n, metric, axes, channel_, in.limits.v_end,
                          v_out, v_min, jerk_limited(in_move.slope))
          : link_velocity(in.path.at(in.path.length()), out_path.at(0.0), n, metric, axes, channel_,
                          in.limits.v_end, v_out, v_min, jerk_limited(in_move.slope));
  in.v_end = link.v_link;
  if (joints_for(in_move) != nullptr && link.cls != TransitionClass::c2) {
    // Under a transform the joints take their own steps at a C0 / C1 joint: the VELOJUMP and
    // C1 rules per joint, on the joints' path derivatives (docs/planner.md "Kinematics").
    const PathPoint a = in.path.at(in.path.length());
    const PathPoint b = out_path.at(0.0);
    AxisVec q1_in{}, q2_in{}, q1_out{}, q2_out{};
    const std::size_t nj = joints_->joints.size();
    if (!joint_derivatives(a, n, joints_->inverse, nj, q1_in, q2_in) ||
        !joint_derivatives(b, n, joints_->inverse, nj, q1_out, q2_out))
      throw KinematicError(in_move.line,
                           "a corner outside the workspace of the kinematic transform [NC3201]");
    // As on the axes: VELOJUMP at C0; the C1 budget on jerk-limited slopes (P-CHAN-00009),
    // at C1 and at C0 too (a knee into a curve: docs/planner.md "The C1 rule at C0 joints").
    if (link.cls == TransitionClass::c0) {
      const double cap = velojump_velocity(q1_in, q1_out, joints_->joints, channel_.t_cycle);
      if (cap < in.v_end) {
        in.v_end = cap;
        in.rule = LinkRule::velojump;
      }
    }
    if (channel_.limit_c1_by_jerk && jerk_limited(in_move.slope)) {
      const double cap = c1_velocity(q2_in, q2_out, joints_->joints, channel_.t_cycle);
      if (cap < in.v_end) {
        in.v_end = cap;
        in.rule = LinkRule::c1_jerk;
      }
    }
  }
  // Under a transform a knee does not carry the acceleration (decision, docs/planner.md
  // "Kinematics"): the knee rule knows the Cartesian stand-in limits, not the joints'.
  in.a_zero_at_end =
      link.zero_acceleration || (joints_for(in_move) != nullptr && link.cls == TransitionClass::c0);
  in.joint = link.cls;
  if (in.v_end == link.v_link) in.rule = link.rule;
  in.stop = StopReason::none;
  output(std::move(in), out);
}

namespace {

/// A symmetric jerk-limited ramp between v0 and v1 >= v0 (acceleration a, jerk j; j = +inf:
/// none): its time [s] and distance [mm].
struct Ramp {
  double time = 0.0;
  double distance = 0.0;
};
Ramp ramp(double v0, double v1, double a, double j) {
  const double dv = std::max(0.0, v1 - v0);
  double t = dv / a;
  if (std::isfinite(j)) t = dv < a * a / j ? 2.0 * std::sqrt(dv / j) : dv / a + a / j;
  return {t, 0.5 * (v0 + v1) * t};
}

/// Whether a corner linked at `v_corner` is passed faster than `ball` (its path limits and
/// length), the blend that would replace the last `cut_in` of the incoming block and the first
/// `cut_out` of the next, between neighbours with the path limits `in` and `out` (issue 36:
/// blending is never slower than not blending; docs/planner.md "Tolerance balls"). The time of
/// each way over the same stretch of the programmed path: on each side from that neighbour's
/// cap down to the corner's link, or to the ball's velocity (a ball of 0.01 mm has path limits
/// of a few mm/s^2: no ramp inside it), with that neighbour's path acceleration and jerk; the
/// ball's way is shorter by what it cuts off, and it moves at most at the slower neighbour's
/// programmed velocity over the part of the faster one it replaces.
bool corner_outruns_ball(double v_corner, const PreparedSegment& ball, double cut_in,
                         double cut_out, const PathLimits& in, const PathLimits& out) {
  const double v_ball = ball.limits.v_max;
  if (v_corner > v_ball * (1.0 + kRelTol)) return true;
  if (!(v_corner > 0.0) || !(v_ball > 0.0) || !(in.d_max > 0.0) || !(out.a_max > 0.0)) return false;
  const double v_joint = std::min({v_corner, in.v_max, out.v_max});
  const double v_blend = std::min({v_ball, in.v_max, out.v_max});
  double t_corner = 0.0;
  double t_ball = ball.path.length() / v_blend;
  // One side (cap v, acceleration a, jerk j, the piece `cut` the ball replaces): each way's
  // time over the longer of the two stretches, at v beyond its ramp.
  const auto side = [&](double v, double a, double j, double cut) {
    const Ramp rc = ramp(v_joint, v, a, j);
    const Ramp rb = ramp(v_blend, v, a, j);
    const double x = std::max(rc.distance, rb.distance + cut);
    t_corner += rc.time + (x - rc.distance) / v;
    t_ball += rb.time + (x - rb.distance - cut) / v;
  };
  side(in.v_max, in.d_max, in.j_max, cut_in);
  side(out.v_max, out.a_max, out.j_max, cut_out);
  return t_corner < t_ball;
}

}  // namespace

void Preparer::emit_stop(Pending& p, StopReason why, std::vector<PreparedSegment>& out) {
  PreparedSegment ps = make(p.path, p.move, false, pending_limits(p));
  ps.v_end = 0.0;
  ps.a_zero_at_end = true;
  ps.stop = why;
  output(std::move(ps), out);
}

void Preparer::output(PreparedSegment ps, std::vector<PreparedSegment>& out) {
  if (held_) {
    PreparedSegment& h = *held_;
    const double cap = h.limits.v_max;
    const bool same_cap = std::abs(ps.limits.v_max - cap) <= 1e-9 * std::max(cap, 1.0);
    // C2 joints and knees that carry the acceleration (corner.hpp) chain alike, when the joint
    // limits nothing below the chain's cap.
    // Both sides jerk-limited or both STEP: a STEP part (no curvature-jerk cap, limits.hpp)
    // would be planned with the other's jerk and treated as jerk-limited by the interpolator and
    // the audit's finite differences (found on a STEP block's ball before a TRAPEZ block at the
    // same cap: 2.8x the axes' J; ipo/program_test.cpp).
    const bool open_joint = h.stop == StopReason::none && !h.a_zero_at_end &&
                            std::isfinite(h.limits.j_max) == std::isfinite(ps.limits.j_max);
    bool join = false;
    if (same_cap) {
      join = open_joint && h.v_end >= cap * (1.0 - 1e-12);
    } else {
      // Across different caps: one piece at the smaller cap, when neither side loses more
      // than kChainCapSlack by it (docs/planner.md "Chains").
      const double low = std::min(cap, ps.limits.v_max);
      join = open_joint && h.v_end >= low * (1.0 - 1e-12) && !feed_must_hold(h.limits, low) &&
             !feed_must_hold(ps.limits, low) &&
             fits_under(low, held_v_hi_, h.path.length(), h.limits, channel_.t_cycle) &&
             fits_under(low, ps.limits.v_max, ps.path.length(), ps.limits, channel_.t_cycle);
    }
    if (join && h.path.parts() + ps.path.parts() <= Chain::kMaxParts) {
      held_v_hi_ = std::max(held_v_hi_, ps.limits.v_max);
      if (!same_cap) {
        h.limits.v_max = std::min(cap, ps.limits.v_max);
        h.limits.v_programmed = std::min(h.limits.v_programmed, ps.limits.v_programmed);
      }
      h.path.append(ps.path);
      h.option_count = 0;  // the options are one arc's
      h.limits.a_max = std::min(h.limits.a_max, ps.limits.a_max);
      h.limits.d_max = std::min(h.limits.d_max, ps.limits.d_max);
      h.limits.j_max = std::min(h.limits.j_max, ps.limits.j_max);
      h.limits.v_end = ps.limits.v_end;
      h.v_end = ps.v_end;
      if (!same_cap) {  // the chain's end joint is passed at most at the chain's cap
        h.limits.v_end = std::min(h.limits.v_end, h.limits.v_max);
        h.v_end = std::min(h.v_end, h.limits.v_max);
      }
      h.a_zero_at_end = ps.a_zero_at_end;
      h.stop = ps.stop;
      h.joint = ps.joint;
      h.rule = ps.rule;
      h.blend = h.blend && ps.blend;
      return;
    }
    out.push_back(std::move(h));
    held_.reset();
  }
  // Hold only what a next segment could join; everything else leaves at once. A joint below
  // the segment's cap can still be joined across caps when the segment would lose little at
  // the joint's cap (a later join's cap is at most that, and fits_under only gets harder).
  const bool open =
      ps.stop == StopReason::none && !ps.a_zero_at_end && ps.path.parts() < Chain::kMaxParts &&
      (ps.v_end >= ps.limits.v_max * (1.0 - 1e-12) ||
       (ps.v_end > 0.0 &&
        fits_under(ps.v_end, ps.limits.v_max, ps.path.length(), ps.limits, channel_.t_cycle)));
  if (open) {
    held_v_hi_ = ps.limits.v_max;
    held_ = std::move(ps);
  } else {
    out.push_back(std::move(ps));
  }
}

void Preparer::push(const Move& move, std::vector<PreparedSegment>& out) {
  validate(move);
  push_path(move, Segment::from_move(move), out);
}

void Preparer::push(const SplinePiece& piece, const Move& modal,
                    std::vector<PreparedSegment>& out) {
  const Move move = spline_move(piece, modal);
  validate(move);
  push_path(move, piece.curve, out);
}

void Preparer::push_path(const Move& move, const Segment& seg, std::vector<PreparedSegment>& out) {
  if (seg.length() < kMinLength) {
    if (pending() && pending()->stop == StopReason::none) pending()->stop = requested_stop(move);
    return;
  }
  if (!pending()) {
    pending().emplace(move, seg, seg.length(), StopReason::none, std::nullopt);  // in place
    return;
  }
  if (pending()->move.transformed != move.transformed)
    throw std::invalid_argument("planner: line " + std::to_string(move.line) +
                                " switches #TRAFO without a stop before it (finish())");
  Pending& p = *pending();  // stays in its slot until the push after this one
  pending_slot_ ^= 1;
  pending().emplace(move, seg, seg.length(), StopReason::none, std::nullopt);  // in place

  StopReason stop = p.stop != StopReason::none ? p.stop : requested_stop(p.move);
  if (stop == StopReason::none && p.move.rapid && !move.rapid) stop = StopReason::rapid_to_feed;
  if (stop != StopReason::none) {
    emit_stop(p, stop, out);
    return;
  }

  // The limits of the new block, computed at most once (its pending limits from the next push on).
  std::optional<PathLimits> seg_limits;
  const auto seg_cap = [&] {
    if (!seg_limits) seg_limits = limits(seg, move);
    return seg_limits->v_max;
  };
  std::optional<JointEnds> ends;  // of the joint p -> seg, evaluated once for all its rules
  if (contoured(p.move)) ends = joint_ends(p.path, seg);
  // The knee rule takes the Preparer's own axis limits; limits() has the same ones except under
  // a transform or on a conveyor (axes_for), so elsewhere it is reused.
  const auto on_own_axes = [&](const Move& m) {
    return joints_for(m) == nullptr && axes_for(m).data() == axes_.data();
  };
  const auto knee_cap = [&] {
    const double in_cap =
        on_own_axes(p.move) ? pending_limits(p).v_max : path_limits(p.path, p.move, axes_).v_max;
    const double out_cap = on_own_axes(move) ? seg_cap() : path_limits(seg, move, axes_).v_max;
    return std::min(in_cap, out_cap);
  };
  if (ends &&
      (joints_for(move) != nullptr ||  // under a transform every G261 corner gets its ball
       !knee_needs_no_ball(p.path, seg, *ends, slopes_at_joint(axes_, p.move.rapid, move.rapid),
                           channel_, knee_cap))) {
    const auto ball = corner_blend(p.move, p.path, seg, *ends,
                                   std::min(p.full_length / 2, p.path.length()), seg.length() / 2);
    if (ball) {
      const Segment in_path = p.path.trimmed(0.0, p.path.length() - ball->cut_in);
      const Segment out_path = seg.trimmed(ball->cut_out, seg.length());
      const PathLimits out_limits = limits(out_path, move);
      // The blend moves at most at the slower of its neighbours' programmed velocities.
      PreparedSegment in_ps = make(in_path, p.move, false);
      Move blend_move = p.move;
      // A ball between two G00 blocks is a G00 curve, planned with their slope (P-AXIS-00004,
      // issue 36 item 2: with the feed slope X took 1114 mm/s^2 against a_grenz 1000).
      blend_move.rapid = p.move.rapid && move.rapid;
      blend_move.block_time.reset();
      blend_move.end_feed.reset();
      blend_move.feed = std::min(in_ps.limits.v_programmed, out_limits.v_programmed);
      // The ball gets the lower of its neighbours' belt limits per axis. Two
      // lines against the belt keep the raised one: the line-line ball's hodograph is a
      // non-negative combination of the two tangents (blend.hpp, k <= 0.71), so its axis
      // velocity keeps their sign (docs/conveyor.md "velocity split").
      for (std::size_t i = 0; i < blend_move.belt.size(); ++i)
        blend_move.belt[i] = std::max(p.move.belt[i], move.belt[i]);
      PreparedSegment blend_ps = make(ball->curve, blend_move, true);
      // Issue 36: a DEV corner that VELOJUMP (000 l.108) passes faster than its ball is kept,
      // planned exactly as under G260; the ball stays jerk-limited where the kernel's default
      // CHECK_JERK=0 would not limit it (TF5200 PROG-475164939, P-CHAN-00110). Not under DIST,
      // whose distances are the curve the program asks for, not a bound it may stay within, nor
      // under a transform, where every G261 corner keeps its ball (the joints' steps;
      // docs/planner.md "Tolerance balls").
      if (p.move.contour == Contour::tolerance && joints_for(p.move) == nullptr &&
          joints_for(move) == nullptr) {
        const std::uint8_t n = std::max(p.path.axis_count(), seg.axis_count());
        const PathLimits& in = pending_limits(p);
        const double out_cap = seg_cap();  // fills seg_limits
        const Link corner =
            link_velocity(ends->in_end, ends->out_start, n, p.path.metric() | seg.metric(),
                          slopes_at_joint(axes_for(p.move), p.move.rapid, move.rapid), channel_,
                          in.v_end, out_cap, std::nullopt, jerk_limited(p.move.slope));
        if (corner_outruns_ball(corner.v_link, blend_ps, ball->cut_in, ball->cut_out, in,
                                *seg_limits)) {
          emit_joint(make(p.path, p.move, false, in), p.move, seg, move.rapid, out_cap, out,
                     &*ends);
          pending()->limits = seg_limits;
          return;
        }
      }
      if (in_path.length() >= kMinLength)
        emit_joint(std::move(in_ps), p.move, ball->curve, blend_move.rapid, blend_ps.limits.v_max,
                   out);
      emit_joint(std::move(blend_ps), blend_move, out_path, move.rapid, out_limits.v_max, out);
      pending()->path = out_path;
      pending()->limits = out_limits;
      return;
    }
  }
  const double v_out = seg_cap();
  pending()->limits = seg_limits;
  emit_joint(make(p.path, p.move, false, pending_limits(p)), p.move, seg, move.rapid, v_out, out,
             ends ? &*ends : nullptr);
}

void Preparer::finish(std::vector<PreparedSegment>& out) {
  if (pending()) {
    const StopReason requested =
        pending()->stop != StopReason::none ? pending()->stop : requested_stop(pending()->move);
    emit_stop(*pending(), requested != StopReason::none ? requested : StopReason::end_of_stream,
              out);
    pending().reset();
  }
  if (held_) out.push_back(std::move(*held_));
  held_.reset();
}

}  // namespace ncsim::planner
