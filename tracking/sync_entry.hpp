#pragma once
// tracking/sync_entry: the hand-over from a catch-up that meets its workpiece moving (#SYNC IN
// FEED_CONT > 0 / FEED_CONT_AUTO, seed 004 l.284, l.508-531) to the path's first PCS1 block.
//
// Purpose: decide the relative velocity f the catch-up meets its target with, so that the path
// can start its first contour block at f without breaking a limit: "reduced as required"
// (004 l.284; docs/conveyor.md S-1).
// Inputs: the velocity asked for (FEED_CONT [mm/s], +inf for FEED_CONT_AUTO), the catch-up's
// direction u in PCS1 (unit over X/Y/Z: ConveyorSync::catch_up_direction), the first segment
// the look-ahead holds after the catch-up and its highest entry velocity (the backward pass:
// its cap = F and the axes' limits under the PCS1 velocity split, and its braking within the
// window), the axes' limits and the cycle T.
// Outputs: f = min(asked, the link's bound, the entry cap) and which of them set it; the joint
// the hand-over passes (the axes' velocity and acceleration steps) for the audit.
// Method: the joint between the catch-up's end (tangent u, no curvature: the relative motion
// is straight at constant velocity, acceleration 0) and the first segment's start is a corner
// under the planner's own rules (planner/corner.hpp): C0 (VELOJUMP, 000 l.108: per axis
// f |t_i - u_i| <= C0_i min(A+_i, A-_i) T), C1 (the acceleration step f^2 |x''_i| within
// j_i T), C2 (nothing). Both sides have path acceleration 0 there (the catch-up ends at
// acceleration 0, the look-ahead starts every segment at a = 0).
// Invariants: 0 <= f <= every bound; pure functions, no allocation, never throw.

#include <cstdint>
#include <span>

#include "ipo/interpolator.hpp"
#include "planner/corner.hpp"
#include "planner/limits.hpp"
#include "planner/prepare.hpp"

namespace ncsim::tracking {

/// What set the relative velocity of the hand-over.
enum class EntryLimit : std::uint8_t {
  asked,      ///< FEED_CONT itself
  corner,     ///< the link between the catch-up's direction and the block's tangent
  entry_cap,  ///< the first block's feed and limits, or its braking (the look-ahead)
  nothing,    ///< no contour block follows (a dwell, a wait, #SYNC OUT, the end): 0
};

struct SyncEntry {
  double v = 0.0;            ///< the relative velocity of the meeting and the path's entry [mm/s]
  double v_corner = 0.0;     ///< the link's bound [mm/s] (+inf: none)
  double v_entry_cap = 0.0;  ///< the look-ahead's highest entry velocity [mm/s]
  EntryLimit limit = EntryLimit::nothing;
  planner::TransitionClass cls = planner::TransitionClass::c2;  ///< class of the link
  planner::LinkRule rule = planner::LinkRule::segment_caps;     ///< what bounds v_corner
};

/// The hand-over's relative velocity for `asked` [mm/s] (+inf: FEED_CONT_AUTO) along `u`
/// into `first` (null: nothing follows), entered at most at `entry_cap` [mm/s].
SyncEntry sync_entry(double asked, const planner::AxisVec& u, const planner::PreparedSegment* first,
                     double entry_cap, std::span<const planner::AxisLimits> axes,
                     double t_cycle) noexcept;

/// The joint the path passes at the hand-over at velocity `v` [mm/s] (the audit's allowance
/// for the velocity step of a corner): at time `t` [s], source line `line`.
ipo::Joint sync_entry_joint(const SyncEntry& entry, const planner::AxisVec& u,
                            const planner::PreparedSegment& first, double v, double t,
                            std::uint32_t line, std::size_t axis_count) noexcept;

}  // namespace ncsim::tracking
