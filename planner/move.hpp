#pragma once
// planner/move: the planner's own input values: one motion block and the axis limits.
//
// Purpose: the planner plans from plain values, independent of how the interpreter and the
// machine lists spell them (an adapter from interp::Command / machines::Machine comes at
// integration). A Move is one path block in machine-axis coordinates of one frame; AxisLimits
// are one axis's dynamics, already in the planner's units.
// Units: mm and degrees for positions, mm/s (deg/s) for velocities, mm/s^2 for accelerations,
// mm/s^3 for jerk, s for times. Feeds are path feeds in mm/s (converted from mm/min before).
// Invariants (checked by validate(), which throws std::invalid_argument naming the field):
// every number finite; axis_count in 1..kMaxAxes; an arc's plane axes distinct and below
// axis_count, its radius > 0; limits > 0 (C0 factor >= 0).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

namespace ncsim::planner {

/// Most axes one channel addresses (machines::kMaxChannelAxes).
inline constexpr std::size_t kMaxAxes = 16;
using AxisVec = std::array<double, kMaxAxes>;  ///< one value per machine axis [mm | deg]
using AxisMask = std::uint32_t;                ///< bit i: machine axis i

/// Whether axis i is in the mask.
constexpr bool has(AxisMask mask, std::size_t i) {
  return ((mask >> i) & 1U) != 0;
}

/// Block transition at the end of a block (isg-language.md §2.4).
enum class Transition : std::uint8_t {
  accelerate_at_start,  ///< G08 (modal, initial): normal look-ahead
  stop_at_end,          ///< G09 (this block): velocity 0 at the block end
  decel_at_end,         ///< G900: decelerate at block end (treated as G08 in the look-ahead)
  decel_after_end,      ///< G901: decelerate after block end (treated as G08)
};

/// #SLOPE TYPE (isg-language.md §5.5): STEP is acceleration-limited, TRAPEZ/SIN2 jerk-limited.
enum class SlopeType : std::uint8_t { step, trapez, sin2, hsc };

/// Corner handling at the end of a block.
enum class Contour : std::uint8_t {
  none,       ///< G260: corners are C0 transitions (VELOJUMP)
  tolerance,  ///< G61 / G261 with #CONTOUR MODE DEV: a blend inside a ball of radius path_dev
  /// G61 / G261 with #CONTOUR MODE DIST: a blend from pre_dist before the corner to post_dist
  /// after it (isg-language.md §5.3, PROG-475180811)
  distance,
};

/// A circle plane that is not spanned by two machine axes: an arc programmed under a rotated
/// #CS frame, transformed to machine coordinates (docs/planner.md "Arcs in a general plane").
/// The plane is spanned by the orthonormal u, v over the three machine axes `axes` (X, Y, Z);
/// the arc turns from u towards v (counter-clockwise about n = u x v) unless `clockwise`.
struct ArcPlane {
  std::array<std::uint8_t, 3> axes{0, 1, 2};  ///< machine axes of u, v, centre components
  std::array<double, 3> u{1.0, 0.0, 0.0};     ///< first in-plane unit vector [1]
  std::array<double, 3> v{0.0, 1.0, 0.0};     ///< second in-plane unit vector, u . v = 0 [1]
  std::array<double, 3> centre{};             ///< a point of the circle's axis [mm]
};

/// Circle plane (G17 / G18 / G19) given as the two machine axes of the plane (a general plane
/// is Move::arc_plane, which then replaces axis_1 / axis_2 / centre_1 / centre_2).
struct Arc {
  std::uint8_t axis_1 = 0;   ///< first plane axis (X for G17, Z for G18, Y for G19)
  std::uint8_t axis_2 = 1;   ///< second plane axis
  double centre_1 = 0.0;     ///< centre, first plane coordinate [mm]
  double centre_2 = 0.0;     ///< centre, second plane coordinate [mm]
  bool clockwise = false;    ///< G02 (true) or G03, seen from the positive third axis
  bool full_circle = false;  ///< start == end in the plane means one full turn
};

/// Inner control points of a cubic Bezier spline piece (#SPLINE, spline.hpp); the outer ones
/// are Move::start and Move::end.
struct SplineControl {
  AxisVec c1{};  ///< second control point [mm | deg]
  AxisVec c2{};  ///< third control point [mm | deg]
};

/// What a conveyor takes of each joint's acceleration and jerk on a PCS1 block
/// under #TRAFO ON (docs/conveyor.md "Machining in PCS1"; tracking::belt_share).
struct JointShare {
  AxisVec a{};  ///< acceleration taken of joint i, >= 0 [deg/s^2 | mm/s^2]
  AxisVec j{};  ///< jerk taken of joint i, >= 0 [deg/s^3 | mm/s^3]
};

/// A block's dynamics weightings (interp::DynamicsWeights, TF5200 G127..G133, G230, G231, G233) per
/// axis as fractions <= 1 of the limits it plans with: `v` of v_max and v_reference (G00:
/// v_rapid), `a` of the accelerations, `j` of the jerks (the acceleration's weight over the
/// ramp time's); docs/interp.md "Dynamics weighting".
struct AxisWeights {
  AxisVec v{};
  AxisVec a{};
  AxisVec j{};
};

/// One path block (a line, or an arc / helix when `arc` is set).
struct Move {
  std::uint8_t axis_count = 3;        ///< machine axes in use, 1..kMaxAxes
  AxisMask path_axes = 0b111;         ///< axes whose motion measures the path length (main axes)
  AxisVec start{};                    ///< [mm | deg]
  AxisVec end{};                      ///< [mm | deg]
  std::optional<Arc> arc;             ///< G02/G03: circle in the plane; other axes move linearly
  std::optional<ArcPlane> arc_plane;  ///< with `arc`: a plane not spanned by two machine axes
  /// A #SPLINE piece: cubic Bezier (not with `arc`). Shared and immutable, so that lines and
  /// arcs, the bulk of every program, do not carry 256 bytes of control points in each copy.
  std::shared_ptr<const SplineControl> spline;
  bool rapid = false;  ///< G00: per-axis MIN(rapid, reference, max) (000 l.360)
  /// Programmed F [mm/s]. A rapid ignores it, except a transformed G00 in PCS1 (belt_joints
  /// set): there it is the velocity cap the belt's share leaves (0: none; path_limits).
  double feed = 0.0;
  std::optional<double> block_time;  ///< G93: machining time of the block [s]
  std::optional<double> end_feed;    ///< E: feed at the block end [mm/s]
  Transition transition = Transition::accelerate_at_start;
  bool exact_stop = false;          ///< G60 / G360: velocity 0 and the window at the end
  Contour contour = Contour::none;  ///< G61 / G261 at the end of this block
  double path_dev = 1.0;            ///< #CONTOUR MODE DEV PATH_DEV: ball radius [mm]
  double pre_dist = 1.0;   ///< #CONTOUR MODE DIST PRE_DIST: blend start before the corner [mm]
  double post_dist = 1.0;  ///< #CONTOUR MODE DIST POST_DIST: blend end after the corner [mm]
  std::optional<double> transvelmin;  ///< #TRANSVELMIN [mm/s]
  SlopeType slope = SlopeType::step;  ///< #SLOPE TYPE
  std::uint32_t line = 0;             ///< source line, for notes and reports
  /// Source file of `line`: an index into the interpreter's file table (interp::Command::file,
  /// 0: the main program), so a run-time error in a subroutine file names that file.
  std::uint16_t file = 0;
  /// Channel events (program/channel_event.hpp) up to this tag fire when the block starts; tags
  /// increase in program order, 0: none.
  std::uint32_t event_tag = 0;
  /// #TRAFO ON: X, Y, Z are the Cartesian TCP and the joints of the kinematic transform limit
  /// the path (Preparer::set_joints); false: axis values (docs/planner.md "Kinematics").
  bool transformed = false;
  /// While synchronised (PCS1), the velocity the conveyor takes of each axis
  /// [mm/s]: the block is planned with v_max, v_reference and v_rapid lowered by it
  /// (belt_limits; 004 l.311-319, docs/conveyor.md "velocity split"); all 0 off the conveyor.
  /// Negative on an axis the block moves against the belt (raised by it).
  AxisVec belt{};
  /// Under #TRAFO ON while synchronised, the acceleration and jerk the conveyor
  /// takes of each joint: the block is planned with the joints' limits lowered by them
  /// (belt_joint_limits). Shared and immutable, as `spline`; null off the conveyor.
  std::shared_ptr<const JointShare> belt_joints;
  /// Dynamics weightings (AxisWeights); null: none. Not applied to the joints under #TRAFO ON.
  std::shared_ptr<const AxisWeights> weights;
};

/// Whether the corner at the end of `move` is contoured (G61 / G261, DEV or DIST).
constexpr bool contoured(const Move& move) noexcept {
  return move.contour != Contour::none;
}

/// The minimum transition velocity at the corner at the end of `move` [mm/s]: its
/// #TRANSVELMIN, which acts at discontinuous transitions only, not under G61 / G261
/// (isg-language.md §5.6); none without it.
constexpr std::optional<double> transvelmin_at_end(const Move& move) noexcept {
  return contoured(move) ? std::nullopt : move.transvelmin;
}

/// The distance from the programmed corner that the contour at the end of `move` may reach,
/// the bound its blend provably stays within (blend.hpp): PATH_DEV under DEV,
/// max(PRE_DIST, POST_DIST) under DIST (decision, docs/planner.md "DIST"), 0 without
/// contouring [mm].
double contour_bound(const Move& move) noexcept;

/// One machine axis's dynamics as the planner uses them (000 l.75, l.105-108, l.360).
struct AxisLimits {
  double v_max = 0.0;        ///< maximum velocity [mm/s]
  double v_reference = 0.0;  ///< reference velocity, an extra upper limit [mm/s] (000 l.75)
  double v_rapid = 0.0;      ///< rapid traverse velocity G00 [mm/s]
  double a_max = 0.0;        ///< maximum acceleration A+ [mm/s^2]
  double d_max = 0.0;        ///< maximum deceleration |A-| [mm/s^2]
  double j_max = 0.0;        ///< maximum jerk [mm/s^3]
  double c0 = 1.0;           ///< VELOJUMP factor C0 (000 l.105-108), >= 0
  /// G00 acceleration, both ways (P-AXIS-00004) [mm/s^2]; 0: G00 uses a_max / d_max.
  double a_rapid = 0.0;
  /// G00 jerk (P-AXIS-00004 / P-AXIS-00200) [mm/s^3]; 0: G00 uses j_max.
  double j_rapid = 0.0;
};

/// `axis` (axis i of a block, G00 when `rapid`) with the block's weights applied: velocity,
/// accelerations and jerks lowered, never below 1 um/s (TF5200 G127: "0 %: 1 um/s").
AxisLimits weighted_limits(const AxisLimits& axis, const AxisWeights& w, std::size_t i,
                           bool rapid) noexcept;

/// The limits a G00 block is planned with: a_rapid / j_rapid where set, else the feed values.
AxisLimits rapid_limits(const AxisLimits& axis) noexcept;
/// The slope in force on both sides of a joint between a block (`rapid_in`: G00) and the next
/// (`rapid_out`): each of a_max, d_max, j_max the smaller of the two blocks' (a G00 block's
/// from rapid_limits), for the corner formulas VELOJUMP and C1 (000 l.108 "A+[i], A-[i] the
/// acceleration or deceleration limits for the axis": the step happens in both blocks).
AxisLimits joint_slope(const AxisLimits& axis, bool rapid_in, bool rapid_out) noexcept;

/// The limits of an axis of which a conveyor takes `taken` [mm/s] (004
/// l.311-319): v_max, v_reference and v_rapid lowered by it, each kept at >= 1 % of itself;
/// accelerations and jerk unchanged. taken 0: the axis as it is. --- belt-split: taken < 0, a
/// block against the conveying direction, raises them by |taken| (v_max + v_conv).
AxisLimits belt_limits(const AxisLimits& axis, double taken) noexcept;

/// The limits of a joint of which a conveyor takes `a` >= 0 of the acceleration
/// and `j` >= 0 of the jerk: a_max, d_max and j_max lowered by them, each kept at >= 1 % of
/// itself (the adapter refuses a share that leaves less: NC6211); velocities unchanged.
AxisLimits belt_joint_limits(const AxisLimits& joint, double a, double j) noexcept;

/// Channel-wide planner settings.
struct ChannelLimits {
  double t_cycle = 0.001;  ///< interpolation cycle T [s] (VELOJUMP, C1 budget)
  /// P-CHAN-00009 semantics: limit the velocity at C1 transitions so that each axis's
  /// acceleration step fits its jerk budget j_max * T (docs/planner.md "C1").
  bool limit_c1_by_jerk = true;
  /// The share of A+, A- and J a PCS1 block leaves unused on the axes the belt
  /// moves (Move::belt != 0) and on the joints of a block with belt shares (NCSIM-CHAN-640,
  /// 004 l.454) [fraction]; 0: none.
  double belt_reserve = 0.0;
};

/// `axis` with A+, A- and J lowered by the fraction `reserve` (NCSIM-CHAN-640).
AxisLimits reserved_limits(const AxisLimits& axis, double reserve) noexcept;

/// Throws std::invalid_argument naming the field and value when a Move breaks its invariants.
void validate(const Move& move);
/// Throws std::invalid_argument naming the axis, field and value when a limit is not usable.
void validate(std::span<const AxisLimits> limits);

}  // namespace ncsim::planner
