#pragma once
// planner/prepare: from a stream of Moves to planned path segments with joint velocities.
//
// Purpose: the stage before the look-ahead. Each Move becomes a Segment with its PathLimits;
// each joint to the next Move becomes either a stop (G09, G60/G360, G00 -> G01/G02/G03, end of
// the stream), a tolerance-ball blend (G61/G261 PATH_DEV) inserted as its own segment, or a
// link at the velocity corner.hpp allows.
// Inputs: Moves in program order (push), then finish() at the end of the stream (#FLUSH, M30).
// Outputs: PreparedSegments appended to the caller's vector, in path order. A segment is only
// emitted once its successor is known (the joint needs both), so the stage holds one Move.
// Chains: consecutive segments joined C2 (or at a knee that carries the acceleration,
// corner.hpp) whose joint limits nothing and whose velocity caps are equal are emitted as one
// Chain (at most Chain::kMaxParts), with the smallest a, d, j of its
// parts, so the look-ahead carries the acceleration through those joints. Segments of
// different caps are chained at the smaller cap when neither side loses more than 1 % by it
// (its own caps within 1 %, or too short to rise 1 % above it; docs/planner.md "Chains").
// Invariants: consecutive emitted segments join (end of one == start of the next); v_end of a
// segment is its joint velocity cap (0 at a stop); memory is one pending Move and one held
// chain, whatever the length of the stream. Zero-length moves (below 1e-9 mm) are dropped; their
// stop request (G09, G60) passes to the joint before them.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "planner/blend.hpp"
#include "planner/chain.hpp"
#include "planner/corner.hpp"
#include "planner/joint_limits.hpp"
#include "planner/limits.hpp"
#include "planner/move.hpp"
#include "planner/path.hpp"
#include "planner/spline.hpp"

namespace ncsim::planner {

/// Why the path velocity is 0 at the end of a segment.
enum class StopReason : std::uint8_t {
  none,           ///< no stop: the joint is passed at up to v_end
  stop_at_end,    ///< G09
  exact_stop,     ///< G60 / G360 (the exact-stop window is checked by the interpolator)
  rapid_to_feed,  ///< G00 followed by G01/G02/G03 behaves like G09 (isg-language.md §2.4)
  end_of_stream,  ///< the last segment before finish() (#FLUSH, end of program)
};

/// One segment ready for the look-ahead.
struct PreparedSegment {
  Chain path;                 ///< the curve (blocks trimmed by tolerance balls; C2 runs chained)
  PathLimits limits;          ///< velocity cap and path a, d, j on this segment
  double v_end = 0.0;         ///< cap of the velocity at the end joint [mm/s]
  bool a_zero_at_end = true;  ///< path acceleration must be 0 at the end joint (C0, C1, stop)
  StopReason stop = StopReason::none;
  TransitionClass joint = TransitionClass::c0;  ///< class of the end joint (when not a stop)
  LinkRule rule = LinkRule::segment_caps;       ///< what set v_end (when not a stop)
  bool blend = false;                           ///< a tolerance-ball blend, not a programmed block
  std::uint32_t line = 0;  ///< source line (a blend carries its incoming block's line)
  /// An arc's limits under other velocity caps (arc_options): the look-ahead plans with
  /// `limits` and takes, once it knows the entry and exit, the fastest of these that fits.
  std::array<PathLimits, kArcOptions> options{};
  std::uint8_t option_count = 0;
};

/// The planner cannot plan a segment under the kinematic transform: the inverse transform
/// fails on it (a point outside the workspace). `line` is the Move's line (the interpolator's
/// token: it maps it back to the source line).
class KinematicError : public std::runtime_error {
 public:
  KinematicError(std::uint32_t line, const std::string& what)
      : std::runtime_error(what), line_(line) {}
  std::uint32_t line() const noexcept { return line_; }

 private:
  std::uint32_t line_;
};

/// Joint limits under a kinematic transform (#TRAFO ON; joint_limits.hpp).
struct JointLimits {
  JointMap inverse;                ///< Cartesian point -> joint values
  std::vector<AxisLimits> joints;  ///< one per joint: v, a, j [deg | mm]
  /// The path axes' own limits under the transform (X, Y, Z Cartesian; one per axis in use);
  /// empty: the Preparer's axes. The corner, knee and blend rules use them for transformed
  /// Moves, the joint rules apply on top.
  std::vector<AxisLimits> cartesian;
};

class Preparer {
 public:
  /// `axes` must outlive the Preparer (one entry per machine axis in use); throws
  /// std::invalid_argument on unusable limits.
  Preparer(std::span<const AxisLimits> axes, ChannelLimits channel);

  /// Adds the next Move; appends the segments that became complete. Throws
  /// std::invalid_argument when the Move is malformed (validate()).
  void push(const Move& move, std::vector<PreparedSegment>& out);
  /// Adds a spline piece (spline.hpp) as the next block: the modal state (slope, contour,
  /// transition, exact stop, path axes) comes from `modal`; start, end, feed and line from the
  /// piece, whose curve is planned as it is (never chopped). Joints between pieces are then
  /// classified like any other (Akima: C1, B-spline: C2, chained at one cap).
  void push(const SplinePiece& piece, const Move& modal, std::vector<PreparedSegment>& out);
  /// End of the stream: appends the held segment, ending in a stop.
  void finish(std::vector<PreparedSegment>& out);
  /// Under a kinematic transform: from now on the limits of every segment of a transformed
  /// Move (Move::transformed: #TRAFO ON) also keep each joint inside its own v, a, j
  /// (planner::path_limits with a JointMap; docs/planner.md "Kinematics"), with
  /// `joints.cartesian` as the axes' limits; Moves without the flag keep the axes' limits alone.
  /// A segment the transform cannot map throws KinematicError. Throws std::invalid_argument on
  /// an empty map or unusable joint or Cartesian limits. A Move whose `transformed` differs from
  /// the Move before it without a stop between (finish()) throws std::invalid_argument.
  void set_joints(JointLimits joints);

 private:
  struct Pending {
    Move move;
    Segment path;            ///< possibly trimmed at its start by a blend
    double full_length = 0;  ///< length before any trimming [mm]
    StopReason stop = StopReason::none;
    std::optional<PathLimits> limits;  ///< limits(path, move) once computed (pending_limits)
  };
  /// limits(p.path, p.move), computed once per pending path.
  const PathLimits& pending_limits(Pending& p) const;
  /// push() with the curve given (a Move's own curve or a spline piece).
  void push_path(const Move& move, const Segment& seg, std::vector<PreparedSegment>& out);
  PreparedSegment make(const Segment& path, const Move& move, bool blend) const;
  /// The same with the path's limits known (limits(path, move)).
  PreparedSegment make(const Segment& path, const Move& move, bool blend,
                       const PathLimits& limits) const;
  /// Path limits of a segment: the axes', and the joints' under a transform.
  PathLimits limits(const Segment& path, const Move& move) const;
  /// The axis limits a Move is planned with (the Cartesian ones for a transformed Move).
  std::span<const AxisLimits> axes_for(const Move& move) const;
  /// axes_for() without the weightings: the Cartesian or belt limits of `move`.
  std::span<const AxisLimits> belt_axes_for(const Move& move) const;
  /// The joint limits that apply to a Move (null: none).
  const JointLimits* joints_for(const Move& move) const;
  /// Appends `in` with its end joint to `out_path` (velocity cap v_out; `out_rapid`: the
  /// outgoing block is G00) resolved; `ends`, when given, is the joint's joint_ends (blend.hpp),
  /// else it is evaluated here.
  void emit_joint(PreparedSegment in, const Move& in_move, const Segment& out_path, bool out_rapid,
                  double v_out, std::vector<PreparedSegment>& out, const JointEnds* ends = nullptr);
  /// The limits the corner formulas take at a joint of a G00 block (`rapid_in` / `rapid_out`)
  /// with `axes` (joint_slope, docs/planner.md "G00 slope"); `axes` itself at a feed joint.
  std::span<const AxisLimits> slopes_at_joint(std::span<const AxisLimits> axes, bool rapid_in,
                                              bool rapid_out) const;
  /// Appends the pending segment ending in a stop.
  void emit_stop(Pending& p, StopReason why, std::vector<PreparedSegment>& out);
  /// Chaining stage: merges `ps` into the held segment across a C2 joint that limits nothing
  /// and at an equal velocity cap, else emits the held one and holds `ps`.
  void output(PreparedSegment ps, std::vector<PreparedSegment>& out);

  std::span<const AxisLimits> axes_;
  ChannelLimits channel_;
  /// The pending segment and, in the other slot, the one before it: push_path() hands the
  /// previous one on by reference instead of moving it out (a Move and a Segment copied).
  std::array<std::optional<Pending>, 2> pending_slots_;
  std::size_t pending_slot_ = 0;  ///< the slot of the pending segment
  std::optional<Pending>& pending() noexcept { return pending_slots_[pending_slot_]; }
  std::optional<PreparedSegment> held_;  ///< chaining stage
  double held_v_hi_ = 0.0;  ///< highest own velocity cap among the held chain's parts [mm/s]
  std::optional<JointLimits> joints_;  ///< set_joints()
  /// axes_for()'s limits of a Move on a conveyor (Move::belt), rewritten per call.
  mutable std::array<AxisLimits, kMaxAxes> belt_axes_{};
  /// axes_for()'s limits of a Move with dynamics weightings (Move::weights), rewritten per call.
  mutable std::array<AxisLimits, kMaxAxes> weighted_axes_{};
  /// slopes_at_joint()'s limits at a joint with a G00 block, rewritten per call.
  mutable std::array<AxisLimits, kMaxAxes> joint_axes_{};
  /// limits()'s joint limits of a Move on a conveyor (Move::belt_joints).
  mutable std::array<AxisLimits, kMaxAxes> belt_joints_{};
};

}  // namespace ncsim::planner
