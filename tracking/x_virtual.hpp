#pragma once
// tracking/x_virtual: the static processing unit, P-CHAN-00364 conveyor_sync.x_virtual = 1
// (seed 004 §2.1.6 l.432-443, §4.1.2 l.617-621, §4.10; docs/conveyor.md "Static processing
// unit").
//
// Purpose: while synchronised, the channel's X is a virtual (simulation) axis: the real unit
// cannot move in X, the belt carries the workpiece under it. The program's X in PCS1 is the
// workpiece coordinate; the tool stands still in MCS X exactly when the path's X component
// runs against the conveying direction at the belt's velocity. "The feed rate is dependent on
// the conveyor velocity and cannot be influenced independently" (l.438): ncsim gives every
// synchronised path block the feed whose X component is the belt's velocity (decision in
// docs/conveyor.md: a path feed equal to the belt's would let a static X drift on every
// slanted block), so the block takes the time the belt needs to carry its X extent under the
// tool; the channel's path override then follows the real belt (channel/channel_static.cpp).
// Inputs: a Move in MCS at belt travel 0 (interpolated order), the X slot, the conveying sign
// (P-CHAN-00363), the belt velocity to plan for (the adapter passes kXvPlanFactor x CONV_VEL)
// [mm/s], the axis limits the planner plans with.
// Outputs: the Move(s) with their feed set (a spline piece or an arc halved until its X
// component's feed varies by at most kXvFeedSpread), or a positioned program error: NC9100 the belt
// is too fast for the contour (an axis's velocity, acceleration or jerk bound would make the
// planner slow the path below the belt, in a block, a tolerance ball or at a joint without a
// ball: "it is not possible to reduce conveyor velocity", l.440, "the CNC will output a dynamic
// error", l.621), NC9101 a corner the path would stop
// at, NC9102 a block that does not run against the conveying direction (l.439).
// Invariants: pure functions; throw nothing but std::bad_alloc.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "planner/move.hpp"

namespace ncsim::tracking {

/// NC9100: x_virtual: the belt is too fast for the contour (the "dynamic error" of 004 l.621).
inline constexpr const char* kXvTooFastId = "NC9100";
/// NC9101: x_virtual: the path would stop on the belt (a corner, a C-only #CAXTRACK turn, G60).
inline constexpr const char* kXvStopId = "NC9101";
/// NC9102: x_virtual: a block does not run against the conveying direction (004 l.439).
inline constexpr const char* kXvDirectionId = "NC9102";
/// The belt may run up to 10 % faster than CONV_VEL before error 50653 (004 §5.2): the static
/// unit's blocks are planned for kXvPlanFactor * CONV_VEL and the channel's path override
/// (Channel::static_override) brings the path down to the belt's actual velocity.
inline constexpr double kXvPlanFactor = 1.1;
/// Largest relative spread of the belt feed over one spline part before it is halved.
inline constexpr double kXvFeedSpread = 0.01;

/// The static unit's view of the synchronised path.
struct XVirtualParams {
  int x = 0;                            ///< interpolated slot of X (the virtual axis)
  double sign = 1.0;                    ///< +1: the belt moves in +X (P-CHAN-00363 = 0), -1: in -X
  double v_belt = 0.0;                  ///< belt velocity the blocks are planned for [mm/s], > 0
  planner::AxisMask path_axes = 0b111;  ///< axes that measure the path length
};

/// A program error of the static unit: id and message (the caller positions it).
struct XvError {
  const char* id = kXvTooFastId;
  std::string message;
};

/// The result of belt_feed: the Moves with their feed, or an error.
struct XvOutcome {
  std::vector<planner::Move> moves;
  std::optional<XvError> error;
};

/// The two halves (by angle) of arc Move `mv` (not full_circle afterwards); the axes outside
/// the plane, a helix's and a tracking C, are split linearly in the angle.
std::pair<planner::Move, planner::Move> split_arc(const planner::Move& mv);

/// |dX/ds| of a line (the X share of its path length) [1].
double x_share(const planner::Move& mv, const XVirtualParams& p) noexcept;
/// The feed [mm/s] of line `mv` whose X component is the belt's: v_belt / x_share.
double line_belt_feed(const planner::Move& mv, const XVirtualParams& p) noexcept;

/// The belt feed for one synchronised path block (line, spline piece or arc), checked against
/// the planner's own limits `limits` and named by `names` (one per interpolated axis). An arc
/// is halved (by angle) until the X share varies by at most kXvFeedSpread over each part (at
/// most 1024 parts), each part with its own feed; a part is NC9100 also when the velocity the
/// belt needs where its X share is smallest exceeds the limits (docs/conveyor.md "arcs").
XvOutcome belt_feed(const planner::Move& mv, const XVirtualParams& p,
                    std::span<const planner::AxisLimits> limits,
                    std::span<const std::string> names);

/// The tolerance ball (G61 / G261) the planner puts between belt-fed parts `in`
/// (ending with the ball) and `out` (the next part), as planner::Preparer builds it
/// (planner::corner_blend, DEV or DIST, each side at most half of its part). Its X share |dX/ds|
/// varies; the path must be able to run at v_belt / |dX/ds| everywhere in it, so both parts' feeds
/// are raised to v_belt / min |dX/ds| over the ball (the planner's ball moves at most at the slower
/// neighbour's feed; the channel's velocity cap keeps the X component at the belt's where the
/// plan is faster, channel/channel_static.cpp). NC9100 when the planner's own limits of the ball
/// (its curvature and jerk) do not allow that velocity, NC9102 when the ball turns along the
/// belt. Nothing happens when the corner gets no ball.
std::optional<XvError> blend_belt_feed(planner::Move& in, planner::Move& out,
                                       const XVirtualParams& p,
                                       std::span<const planner::AxisLimits> limits,
                                       std::span<const std::string> names);

/// The joint of two belt-fed parts `in` and `out` that meet without a tolerance
/// ball (a line or an arc into an arc, spline pieces, a knee of less than 1 deg). The path must
/// pass it at v_belt / |dX/ds| (the X share at the joint); the planner passes it at most at its
/// own link velocity (planner::link_velocity with the limits `limits` and `channel` it plans
/// with: the C1 rule v <= sqrt(j_i T / |dx''_i|) where the curvature jumps, VELOJUMP where an
/// axis's tangent jumps, e.g. a tracking C at an inflection). NC9100 naming the axis and its
/// rule when that link is below the belt's need (004 l.440, l.441: the contour must be C2,
/// l.621); nothing when the joint is C2 or fast enough.
std::optional<XvError> joint_belt_check(const planner::Move& in, const planner::Move& out,
                                        const XVirtualParams& p,
                                        std::span<const planner::AxisLimits> limits,
                                        const planner::ChannelLimits& channel,
                                        std::span<const std::string> names);

}  // namespace ncsim::tracking
