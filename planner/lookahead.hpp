#pragma once
// planner/lookahead: the look-ahead window over prepared segments (P-CHAN-00650).
//
// Purpose: choose the velocity at every joint so that the path is as fast as the segments'
// caps, joint caps and path a, d, j allow, while it can always stop by the end of what is
// known. The window end is treated as a stop, so the planner never needs more than N segments
// and an endless program runs in constant memory.
// Inputs: PreparedSegments in path order (push); pop() releases the oldest, planned.
// Outputs: PlannedSegments: the segment with its entry and exit velocity; profile() turns one
// into its jerk-limited velocity profile (a pure function, jerk::Move over time, s from 0 to L).
// Method (docs/planner.md "Look-ahead"), with the shared kernel jerk/:
//   backward pass: exit_cap[last] = 0 (window end: a possible stop); going back,
//     entry_cap[k] = min(cap_k, entry_velocity_for_exit(exit_cap[k], L_k, d_k, j_k)) and
//     exit_cap[k-1] = min(joint cap, entry_cap[k]); a push re-runs it from the new end back
//     until a value no longer changes (the rest of the window cannot change either).
//   forward pass, at pop(): v_exit = min(exit_cap, reachable_velocity(v_entry, a_entry, L, a,
//     j)), v_entry = the previous segment's v_exit (0 at the start of the path), or a carried
//     speed-up cut at the segment end (best_carry).
// Path acceleration is 0 at C0 and C1 joints and at stops (the NC I rule, 000 l.108). At a soft
// joint (C2, or a knee that carries the acceleration) a speed-up the length cuts goes on
// through it (a > 0) when the rest of its ramp fits the next entries and the window's braking
// (docs/planner.md "Acceleration at joints"); a brake into slower entries runs on through up
// to kMaxBrakeJoints joints where its ramp ends exactly at a later entry's end (a = 0 there)
// and that is faster.
// STEP slopes (no jerk limit) are planned with j = max(a, d) / T: the acceleration step
// takes one interpolation cycle.
// Invariants: 0 <= v_entry, v_exit <= exit cap with a = 0 there, and a carried state only
// where the rest of its ramp fits the window (so the window end can always be a stop); the
// profile of every popped segment fits its length, its cap and its path a, d, j; memory is N
// segments, allocated once.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "jerk/jerk.hpp"
#include "planner/prepare.hpp"

namespace ncsim::planner {

/// P-CHAN-00650 look-ahead function (isg-language.md §7.1; 004 l.1400-1428).
enum class LookAheadKind : std::uint8_t {
  low,       ///< FCT_LOOK_AHEAD_LOW: 30 blocks
  standard,  ///< FCT_LOOK_AHEAD_STANDARD = FCT_IPO_DEFAULT: 120 blocks
  high,      ///< FCT_LOOK_AHEAD_HIGH: 190 blocks
  custom,    ///< FCT_LOOK_AHEAD_CUSTOM: 10 .. P-CHAN-00653 blocks
};

/// Window size in segments. `custom` is used for LookAheadKind::custom and must lie in
/// [10, custom_max] (P-CHAN-00653); throws std::invalid_argument naming P-CHAN-00650 otherwise.
std::size_t window_size(LookAheadKind kind, std::optional<std::size_t> custom = std::nullopt,
                        std::size_t custom_max = 1000);

/// Which profile a planned segment has (docs/planner.md "Acceleration at joints").
enum class ProfileShape : std::uint8_t {
  plain,       ///< ramp to a level, cruise, ramp to the exit (a = 0 at the exit)
  carry_up,    ///< the first ramp towards v_toward, cut at t_cut (a speed-up carried)
  brake_end,   ///< the rest of a carried brake towards v_toward, then a cruise at it
  carry_down,  ///< ramp to `level`, cruise, brake towards v_brake cut at t_brake
  /// a carried brake towards v_toward that runs on: its ramp from `level` between the cuts
  /// at t_cut (entry) and t_brake (exit), a < 0 at both ends
  brake_through,
};

/// A segment with its planned joint velocities.
struct PlannedSegment {
  PreparedSegment segment;
  double v_entry = 0.0;  ///< path velocity at s = 0 [mm/s]
  double v_exit = 0.0;   ///< path velocity at s = L [mm/s]
  double a_entry = 0.0;  ///< path acceleration at s = 0 [mm/s^2] (!= 0 only after a carry)
  double a_exit = 0.0;   ///< path acceleration at s = L [mm/s^2] (!= 0 only: a carry)
  ProfileShape shape = ProfileShape::plain;
  /// carry_up: the velocity the speed-up heads for; its ramp from (v_entry, a_entry) is cut by
  /// the segment end at t_cut. brake_end, brake_through: the velocity the carried brake ends
  /// at; its ramp from `level` (a = 0) was cut at t_cut by the previous segment's end.
  double v_toward = 0.0;
  double t_cut = 0.0;  ///< time of the cut [s] (carry_up, brake_end, brake_through)
  /// carry_down: the velocity the brake from `level` heads for in a later segment; its ramp
  /// is cut by the segment end at t_brake.
  double v_brake = 0.0;
  double t_brake = 0.0;  ///< [s] (carry_down; brake_through: the cut at this segment's end)
  double level = 0.0;    ///< the brake's start velocity [mm/s] (carry_down, brake_*)
  /// carry_down, brake_through: the highest exit a plan ending at a = 0 may take [mm/s] (the
  /// override's plans): the exit the plan with a = 0 at the joint had. Else v_exit.
  double v_exit_zero = 0.0;
  double a_max = 0.0;  ///< path acceleration used [mm/s^2]
  double d_max = 0.0;  ///< path deceleration used [mm/s^2]
  double j_max = 0.0;  ///< path jerk used (finite; STEP: max(a, d) / T) [mm/s^3]
  /// The limits of a carried ramp (shapes other than plain: the smallest of the segments it
  /// runs on); a_max, d_max, j_max stay the segment's own, for the plans made at run time.
  double ramp_a = 0.0, ramp_d = 0.0, ramp_j = 0.0;
};

/// The velocity profile of a segment over time: the first ramp from (v0, a0) to v_level,
/// followed for t_first (its whole time, or less where the segment end cuts a carried
/// speed-up), a cruise at v_level, the second ramp to the exit, followed for t_second (its
/// whole time, or less where the segment end cuts a carried brake).
struct SegmentProfile {
  double v0 = 0.0;        ///< velocity at the start [mm/s]
  double a0 = 0.0;        ///< acceleration at the start [mm/s^2]
  jerk::Ramp first;       ///< (v0, a0) -> (v_level, 0); cut: towards v_toward
  double t_first = 0.0;   ///< time on `first` [s]
  double t_cruise = 0.0;  ///< cruise at v_level [s]
  jerk::Ramp second;      ///< (v_level, 0) -> (v_exit, 0); a carried brake: towards v_brake
  double t_second = 0.0;  ///< time on `second` [s]: its time(), or less (a carried brake)
  double v_level = 0.0;   ///< cruise level [mm/s]; without one the highest velocity
  /// Total duration [s].
  double time() const noexcept { return t_first + t_cruise + t_second; }
};

/// The jerk-limited velocity profile of a planned segment: ramp from (v_entry, a_entry) to the
/// highest level the length allows (at most the cap), cruise, ramp to v_exit (a = 0); or the
/// carried ramp its shape names (ProfileShape).
SegmentProfile profile(const PlannedSegment& planned) noexcept;

/// The plain profile of a segment of `length` [mm] under `cap` [mm/s]: ramp from (v0, a0) to
/// the highest level whose ramps fit, cruise, ramp to (v1, 0) under a, d, j (what profile()
/// gives a plain plan).
SegmentProfile plain_profile(double length, double cap, double v0, double a0, double v1, double a,
                             double d, double j) noexcept;

/// Path state on a profile.
struct PathState {
  double s = 0.0;  ///< arc length from the segment start [mm]
  double v = 0.0;  ///< path velocity [mm/s]
  double a = 0.0;  ///< path acceleration [mm/s^2]
  double j = 0.0;  ///< path jerk of the phase containing t [mm/s^3]
};

/// State at time t [s] after the start of `profile` (closed form per phase; t is clamped to
/// [0, profile.time()]). Pure evaluation.
PathState profile_at(const SegmentProfile& profile, double t) noexcept;

/// What the forward pass does at soft joints (C2, or knees that carry the acceleration).
enum class SoftJoints : std::uint8_t {
  carry,  ///< a speed-up or a brake goes on through the joint where it fits (default)
  zero,   ///< a = 0 at every joint, as at C0/C1 (the NC I rule; for comparisons)
};

class LookAhead {
 public:
  /// `capacity` segments (window_size()); `t_cycle` [s] for the STEP jerk.
  LookAhead(std::size_t capacity, double t_cycle, SoftJoints soft = SoftJoints::carry);

  bool empty() const noexcept { return count_ == 0; }
  bool full() const noexcept { return count_ == slots_.size(); }
  std::size_t size() const noexcept { return count_; }

  /// Appends a segment; the window must not be full (pop first). Aborts on misuse.
  void push(PreparedSegment segment);
  /// Releases the oldest segment with its velocities planned against what the window knows
  /// (its end is a stop), or only its first piece (an arc in stages, stage_arc: the rest stays
  /// at the front, so the window may still be full afterwards). The window must not be empty.
  PlannedSegment pop();
  /// Velocity at the end of the last popped segment [mm/s] (entry of the next).
  double v_committed() const noexcept { return v_committed_; }
  /// Acceleration there [mm/s^2] (!= 0 only where a ramp is carried across a soft joint).
  double a_committed() const noexcept { return a_committed_; }
  // A path that starts moving (sync-feed: the hand-over from the catch-up, issue 14):
  /// The oldest segment not popped yet (null: the window is empty).
  const PreparedSegment* front() const noexcept {
    return empty() ? nullptr : &slots_[head_].segment;
  }
  /// The highest velocity the oldest segment may be entered with [mm/s]: its cap and what its
  /// braking within the window allows (the backward pass's entry cap; 0 when empty).
  double front_entry_cap() const noexcept { return empty() ? 0.0 : slots_[head_].entry_cap; }
  /// The next pop() starts at `v` [mm/s] instead of v_committed(): clamped to [0,
  /// front_entry_cap()], so the plan stays feasible. Returns the velocity set.
  double start_at(double v) noexcept;
  // The workspace hold's prediction across block ends (issue 14, tracking/workspace_hold):
  /// The k-th oldest segment not popped yet (k = 0: front()); null when k >= size().
  const PreparedSegment* queued(std::size_t k) const noexcept {
    return k < count_ ? &slots_[(head_ + k) % slots_.size()].segment : nullptr;
  }

 private:
  struct Slot {
    PreparedSegment segment;
    double length = 0.0;
    double cap = 0.0;        ///< segment velocity cap [mm/s]
    double joint_cap = 0.0;  ///< cap at its end joint [mm/s]
    double a = 0.0, d = 0.0, j = 0.0;
    double entry_cap = 0.0;  ///< backward pass: highest entry velocity [mm/s]
    double exit_cap = 0.0;   ///< backward pass: highest exit velocity [mm/s]
  };
  Slot& at(std::size_t k) noexcept { return slots_[(head_ + k) % slots_.size()]; }
  /// The path jerk a plan uses: `lim`'s, or for STEP (+inf) max(a, d) / T, the acceleration
  /// step taking one cycle.
  double planned_jerk(const PathLimits& lim) const noexcept;
  void backward_from_end();
  /// Largest exit velocity <= v_upper reachable from (v_entry, a_entry) within the slot's
  /// length (a = 0 at the exit); false when none is (a carried speed-up whose release alone
  /// is longer than the slot).
  bool feasible_exit(double v_entry, double a_entry, double v_upper, const Slot& s,
                     double& out) const noexcept;
  /// A ramp carried across the slot's end joint (docs/planner.md "Acceleration at joints").
  struct Carry {
    double v_toward = 0.0;             ///< level the ramp heads for [mm/s]
    double level = 0.0;                ///< a brake: the velocity its ramp starts from [mm/s]
    double a = 0.0, d = 0.0, j = 0.0;  ///< the ramp's limits (the smallest of the slots it spans)
    double t_cut = 0.0;                ///< time of the cut at the slot end [s]
    double v1 = 0.0, a1 = 0.0;         ///< state at the cut
    /// A brake: its distance from `level` to the cut [mm], and the joints it still crosses
    /// after the next slot's end (0: it ends there).
    double s_cut = 0.0;
    std::size_t joints = 0;
  };
  /// At most this many joints one carried brake crosses (its checks cost one cut per joint).
  static constexpr std::size_t kMaxBrakeJoints = 8;
  /// The ramp from (v0, a0) towards v_toward under a, j, cut at the end of the front slot:
  /// true when it is cut there (does not end inside the slot) and every slot it runs on can
  /// take it: caps, joint caps and soft joints up to where it ends, and from there the window's
  /// braking (the backward pass's caps), so the rest of the window stays feasible.
  /// `with_cut` false: the next slots only (no cut state computed, `out` untouched).
  bool carry_fits(double v0, double a0, double v_toward, double a, double j, Carry& out,
                  bool with_cut) const noexcept;
  /// The best carry from (v0, a0): the highest v_toward that fits (bisection), with the
  /// limits of the slots it spans. False when none fits.
  bool best_carry(double v0, double a0, Carry& out) const noexcept;
  /// A brake carried through the front slot's end joint from (v0, 0): ramp to a level, cruise,
  /// and the brake towards the exit cap of a later slot m (1 <= m <= kMaxBrakeJoints) that
  /// ends exactly at that slot's end, cut at this one's; per m the highest level whose brake
  /// passes every joint it crosses within its caps. `out` is the front slot's plan with a = 0
  /// at the joint (its segment moved in); where a carried brake is faster over the slots it
  /// spans, the fastest m fills it (v_exit, a_exit < 0, v_brake, t_brake, level, limits) and
  /// `carry`; false otherwise.
  bool brake_carry(double v0, PlannedSegment& out, Carry& carry) const noexcept;
  /// The slots a brake carried by brake_carry() may span, and its level (lookahead.cpp).
  class BrakeSpan;
  /// pop() for the front slot: after a carried brake, its rest or its part up to the next
  /// cut; else the plan with a = 0 at the exit, a carried speed-up or a carried brake.
  void end_brake(PlannedSegment& out) noexcept;
  void through_brake(PlannedSegment& out) noexcept;
  void plan_front(PlannedSegment& out) noexcept;
  /// A plain plan of an arc entered and left at a = 0: the fastest of its limit sets
  /// (PreparedSegment::limits and ::options) whose profile between the planned entry and exit
  /// fits its length (docs/planner.md "Arc options"). Returns that profile's time [s]; 0 where
  /// it does not apply (no options, not such a plan).
  double fastest_option(PlannedSegment& out) const noexcept;
  static void set_ramp_limits(PlannedSegment& out, const Carry& c) noexcept;
  /// An arc in two pieces, one of them under an option (docs/planner.md "Arc stages").
  struct Stage {
    std::size_t option = kArcOptions;  ///< the option's index; kArcOptions: none faster
    bool head = true;                  ///< a ramp at the start under it (else a brake at the end)
    double cut = 0.0;                  ///< length of the piece under it [mm]
    double t = 0.0;                    ///< the two pieces' time [s]
  };
  /// The fastest Stage for `out` (a plain plan of the front slot), faster than `t_single` (the
  /// best single limit set's time).
  Stage best_stage(const PlannedSegment& out, double t_single) const noexcept;
  /// An arc's plain plan in stages: where a ramp at the start under a lower cap of
  /// `out.segment.options` (more of the axes' acceleration left for the path) and the rest
  /// under `own`, or the rest and a brake at the end under such a cap, is faster than
  /// `t_single`, `out` becomes that first piece and the front slot keeps the rest. Returns
  /// true when it split.
  bool stage_arc(PlannedSegment& out, const PathLimits& own, double t_single) noexcept;

  std::vector<Slot> slots_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  double t_cycle_ = 0.001;
  SoftJoints soft_ = SoftJoints::carry;
  double v_committed_ = 0.0;
  double a_committed_ = 0.0;  ///< != 0: a carried ramp is under way (carry_ below)
  bool split_ = false;        ///< plan_front() left the rest of the front slot in the window
  Carry carry_;               ///< the committed carry (its ramp is the next slot's fallback)
};

}  // namespace ncsim::planner
