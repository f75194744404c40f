#pragma once
// jerk/jerk: the one home of 1-D jerk-limited motion maths (design.md §1): the axes' setpoint
// generator, the planner's forward and backward passes, the interpolator and the conveyor
// catch-up all call these functions and nothing else for "how far / how fast / how long".
//
// Purpose: closed-form (or guaranteed-convergent) answers about a single coordinate moved with
// piecewise constant jerk, bounded acceleration and velocity:
//  - velocity_ramp / velocity_change: the time-optimal change from (v0, a0) to (v1, a = 0)
//    (jerk build-up, [constant acceleration], jerk reduction; 002_* 2.1 phases 1-3 / 5-7);
//    velocity_ramp_to: the same to (v1, a1) with an end acceleration (planner C2 joints);
//  - stopping_distance: the same change to v = 0;
//  - reachable_velocity / entry_velocity_for_exit: the inverse problems a planner's forward and
//    backward passes need (highest velocity reachable within a distance);
//  - move_of_duration: a ramp-cruise-ramp move that takes exactly a prescribed duration (time
//    synchronisation of several axes, INDP TIME=).
// Inputs: velocities [mm/s], accelerations [mm/s^2], jerks [mm/s^3], distances [mm], times [s]
// (or the same with degrees for rotary coordinates). Limits must be finite and > 0.
// Outputs: small value types (Ramp, TimeDistance, Move); nothing allocates, nothing throws.
// Invariants: |jerk| is 0 or j in every phase; accelerations stay within the limits except
// where the start state itself lies beyond them (then they are brought back first, with j);
// every function is total on finite input (never NaN), and the inverse functions are monotone
// in the distance and consistent with the forward ones to rounding (jerk_test.cpp).
// Frame: functions with a_up/a_down work in the caller's frame (a_up bounds positive, a_down
// negative acceleration). Functions taking Limits use the path meaning of 002_* 2.1 in the
// frame in which the motion goes forward: a_max bounds speeding up, d_max slowing down.

#include <array>
#include <cstddef>
#include <cstdint>

namespace ncsim::jerk {

/// Dynamic limits of one coordinate (002_* 2.1, Tab. 1/2; path quantities).
struct Limits {
  double v_max = 0.0;  ///< V, velocity limit [mm/s], > 0
  double a_max = 0.0;  ///< A+, acceleration limit when speeding up [mm/s^2], > 0
  double d_max = 0.0;  ///< A-, deceleration limit when slowing down (magnitude) [mm/s^2], > 0
  double j_max = 0.0;  ///< J, jerk limit [mm/s^3], > 0
};

/// True when every limit is finite and > 0.
bool valid(const Limits& limits) noexcept;

/// State of a coordinate at one instant.
struct State {
  double p = 0.0;  ///< position [mm]
  double v = 0.0;  ///< velocity [mm/s]
  double a = 0.0;  ///< acceleration [mm/s^2]
};

/// State after moving with constant jerk j [mm/s^3] for dt [s] from `s` (closed form).
State advance(const State& s, double j, double dt) noexcept;

/// Up to three constant-jerk phases that change the velocity to v_end with a = 0: jerk
/// towards the peak, [hold at a_peak], jerk back to 0. The intended boundary values travel
/// with it, so a caller chaining phases can start each from its exact value.
struct Ramp {
  std::array<double, 3> jerk{};      ///< jerk of each phase [mm/s^3]
  std::array<double, 3> duration{};  ///< duration of each phase [s], >= 0
  double a_peak = 0.0;               ///< acceleration after phase 1 and in phase 2 [mm/s^2]
  double v_end = 0.0;                ///< velocity after phase 3 (acceleration 0) [mm/s]
  /// Total duration [s].
  double time() const noexcept { return duration[0] + duration[1] + duration[2]; }
};

/// Time-optimal change from (v0, a0) to (v1, 0) with |jerk| = j, acceleration within
/// [-a_down, a_up]. A start acceleration beyond the limit of the pulse's direction is first
/// brought back to it with j (phase 1 then has the opposite jerk).
Ramp velocity_ramp(double v0, double a0, double v1, double a_up, double a_down, double j) noexcept;

/// Distance [mm] travelled by `ramp` from (v0, a0).
double distance(double v0, double a0, const Ramp& ramp) noexcept;

/// Time and distance of a motion piece.
struct TimeDistance {
  double t = 0.0;  ///< [s]
  double s = 0.0;  ///< signed distance [mm]
};

/// Minimum time and its distance to go from velocity v0 with acceleration a0 to v1 with
/// acceleration 0, |a| <= a_lim [mm/s^2], |jerk| <= j [mm/s^3].
TimeDistance velocity_change(double v0, double a0, double v1, double a_lim, double j) noexcept;

/// Minimum time and distance to rest from (v0, a0) with deceleration magnitude <= d_max.
TimeDistance stopping_distance(double v0, double a0, double d_max, double j) noexcept;

/// Distance [mm] of a ramp from rest to v >= 0 [mm/s] under a_lim and j (symmetric S-ramp).
double ramp_distance(double v, double a_lim, double j) noexcept;

/// Highest velocity v1 [mm/s] for which the change (v0, a0) -> (v1, 0) under a_lim, j covers
/// at most the distance s [mm]. The distance of that change grows strictly with v1, so this is
/// its inverse: velocity_change(v0, a0, reachable_velocity(v0, a0, s, ..), ..).s == s.
/// Exact to rounding, never NaN, monotone in s.
double reachable_velocity(double v0, double a0, double s, double a_lim, double j) noexcept;

/// Highest velocity [mm/s] at the start of a distance s >= 0 (acceleration 0 there) from which
/// the velocity can be brought down to v_exit >= 0 (acceleration 0) within s under d_max, j.
/// (By time reversal the speed-up from v_exit over s.) Monotone in s, >= v_exit.
double entry_velocity_for_exit(double v_exit, double s, double d_max, double j) noexcept;

/// Up to three constant-jerk phases that take a start moving backward in its frame (v0 < 0)
/// through v = 0 with a positive acceleration: jerk up to a_peak, [hold], jerk to a_zero,
/// reached exactly when v = 0. Path limits (002_* 2.1): while v < 0 the positive acceleration
/// slows the motion (bounded by A-), after v = 0 it speeds it up (bounded by A+), so a_peak
/// <= A- and a_zero <= min(A+, A-). All zero when a move has no such part.
struct Crossing {
  std::array<double, 3> jerk{};      ///< jerk of each phase [mm/s^3]
  std::array<double, 3> duration{};  ///< duration of each phase [s], >= 0
  double a_peak = 0.0;               ///< acceleration after phase 1 and in phase 2 [mm/s^2]
  double a_zero = 0.0;               ///< acceleration at v = 0, after phase 3 [mm/s^2]
  /// Total duration [s].
  double time() const noexcept { return duration[0] + duration[1] + duration[2]; }
};

/// Time-optimal change from (v0, a0) moving backward (v0 < 0, or v0 >= 0 with an acceleration
/// that reverses the motion: v0 + a0|a0|/(2J) < 0) to (v1 > 0, 0) through v = 0 under the
/// path limits (A- before v = 0, A+ after it): `cross` takes the start to (0, cross.a_zero),
/// `rest` from there to (v1, 0) (a positive pulse under A+). False when the change is not of
/// that kind: no backward motion, v1 <= 0, a start acceleration beyond A-, or one that forces
/// more than min(A+, A-) or than v1 allows at v = 0 (callers then use velocity_ramp).
bool crossing_ramp(double v0, double a0, double v1, const Limits& limits, Crossing& cross,
                   Ramp& rest) noexcept;

/// A single-peak move: change to v_level, cruise, change to the end velocity. All values in
/// the frame of the move (sign +1: forward, -1: backward; world = sign * frame).
struct Move {
  double sign = 1.0;      ///< world direction of the frame, +1 or -1
  Crossing cross;         ///< frame start moving backward: its phases through v = 0 (else 0)
  Ramp first;             ///< (v0, a0) -> (v_level, 0), frame values (from (0, cross.a_zero)
                          ///< when cross has phases)
  double t_cruise = 0.0;  ///< cruise at v_level [s]
  Ramp second;            ///< (v_level, 0) -> (v1, 0), frame values
  double v_level = 0.0;   ///< frame velocity of the cruise [mm/s], >= 0
  /// Total duration [s].
  double time() const noexcept { return cross.time() + first.time() + t_cruise + second.time(); }
};

/// Outcome of move_of_duration.
enum class Status : std::uint8_t {
  ok,             ///< move computed
  invalid_input,  ///< non-finite input, invalid limits, |v1| > V, negative duration
  too_short,      ///< the duration is below the minimum of the move family
  not_supported,  ///< no single-peak move of this duration (needs a reversal)
};

/// A move from `start` to (p1, v1, a = 0) that takes exactly `duration` [s]: the single-peak
/// ramp-cruise-ramp family with the cruise level lowered until the time matches; a target at
/// rest the start cannot stop before is met by overshooting and returning at a lowered level
/// (the reversed frame). Limits hold (V, A+, A-, J) from starts inside them. Not supported
/// (Status::not_supported): an arrival velocity that needs a turn (the frame of travel from
/// p0 to p1 disagrees with v1, or the start cannot stop within the distance: see
/// reversal_of_duration). The end state is met exactly by the chain to rounding. A move whose
/// time is not `duration` to kRelTol relative is never answered (not_supported instead).
Status move_of_duration(const State& start, double p1, double v1, double duration,
                        const Limits& limits, Move& out) noexcept;

/// Minimum duration [s] accepted by move_of_duration from `start` to (p1, v1, 0): the family's
/// level at a root of dist(vm) = D bracketed from 0 (from which it can be lowered); this can
/// exceed fastest_move's time where the feasible levels are not one interval. Returns a
/// negative value when the family does not apply (Status::not_supported).
double min_single_peak_time(const State& start, double p1, double v1,
                            const Limits& limits) noexcept;

/// The fastest single-peak move from `start` to (p1, v1, a = 0): the highest level V and the
/// distance allow, in the frame toward the target or (targets at rest) in the reversed one,
/// which overshoots and returns without stopping in between. Start states beyond the limits
/// are brought inside by the first ramp (acceleration first with j, a velocity above V with
/// d_max). Status::not_supported when neither frame's family reaches the target.
Status fastest_move(const State& start, double p1, double v1, const Limits& limits,
                    Move& out) noexcept;

/// World state at the end of `move` started from `start` (closed-form chain).
State end_state(const State& start, const Move& move) noexcept;

// Two-peak velocity changes (issue 11).

/// A velocity change (v0, a0) -> (v1, 0) whose acceleration keeps one sign and has two peaks
/// (it does not return to 0 between them): jerk from a0 toward 0 down to a_dip, jerk to
/// a_peak, [hold at the limit], jerk to 0. The time-optimal way to change the velocity over a
/// distance between that of the direct ramp (a_dip = a0) and that of releasing a0 first
/// (a_dip = 0), which no single-peak move (level with a = 0) reaches without a detour.
struct TwoPeak {
  std::array<double, 4> jerk{};      ///< jerk of each phase, frame values [mm/s^3]
  std::array<double, 4> duration{};  ///< duration of each phase [s], >= 0
  std::array<double, 4> a_end{};     ///< intended acceleration after each phase [mm/s^2]
  double v_end = 0.0;                ///< velocity after the last phase (a = 0) [mm/s]
  double sign = 1.0;                 ///< world direction of the frame, +1 or -1
  /// Total duration [s].
  double time() const noexcept { return duration[0] + duration[1] + duration[2] + duration[3]; }
};

/// The two-peak change from `start` to (p1, v1, a = 0) in the frame toward the target, when
/// its distance lies between those of the direct ramp and of releasing the start acceleration
/// first; the velocity stays monotone between v0 and v1 (v1 >= 0 in the frame, |v0| <= V), so
/// A+ bounds a speeding pulse and A- a braking one; from a start moving backward (v0 < 0) the
/// speeding pulse stays within min(A+, A-) (it slows the motion before v = 0 and speeds it up
/// after). Status::not_supported otherwise.
Status two_peak_move(const State& start, double p1, double v1, const Limits& limits,
                     TwoPeak& out) noexcept;

/// World state at the end of `tp` started from `start` (closed-form chain).
State end_state(const State& start, const TwoPeak& tp) noexcept;

/// A move that turns round once on the way to an arrival velocity v1 != 0: `out` goes in the
/// direction -sign(v1) to a level (frame of `out`), cruises, and `back` turns into the
/// direction of v1 and arrives at (p1, v1, 0). Both use the path limits through v = 0
/// (crossing_ramp). Needed where the target is too close to arrive at v1 without a detour
/// (overshoot and come back, or an arrival against the direction of travel).
struct Reversal {
  Move out;   ///< to the turning level and its cruise (sign = -sign(v1))
  Move back;  ///< through v = 0 to (v1, 0) (sign = sign(v1))
  /// Total duration [s].
  double time() const noexcept { return out.time() + back.time(); }
};

/// The fastest Reversal from `start` to (p1, v1 != 0, a = 0): the highest turning level in
/// (0, V] for which the turn still reaches p1, with a cruise at V when V itself falls short.
/// The displacement is not monotone in the level: the kink where the out part vanishes splits
/// (0, V] into two pieces with one root each, and the piece holding the highest feasible level
/// is searched (jerk/reverse.cpp). Status::not_supported when v1 == 0 or no level fits (`out` then
/// unspecified).
Status reversal_move(const State& start, double p1, double v1, const Limits& limits,
                     Reversal& out) noexcept;

/// A change that brakes through v = 0 with a free peak (issue 11, session 31): from a start
/// moving against the arrival velocity v1 != 0 while braking (in the frame of v1, sign g =
/// sign(v1): u0 = g v0 < 0, b0 = g a0 in (0, A-]) straight to (p1, v1, 0), the velocity
/// monotone from u0 to g v1: the braking first eases to a_dip in [0, b0] (jerk -J in the
/// frame), then the crossing of crossing_ramp from there (A- before v = 0, A+ after: a peak up
/// to A-, at v = 0 the acceleration min(A-, A+, sqrt(2 J |v1|), the start's own), the rest
/// under A+). a_dip = b0 is crossing_ramp itself; smaller dips keep the motion longer against
/// v1, so they cover a distance between the direct crossing's and that of releasing the
/// braking first (the turn's level at the release velocity, reversal_move). All values but
/// `sign` in the frame.
struct DipCrossing {
  double sign = 1.0;      ///< world direction of the frame (sign of v1)
  double jerk = 0.0;      ///< jerk of the easing phase, -J [mm/s^3]
  double dip = 0.0;       ///< duration of the easing phase [s], >= 0
  double a_dip = 0.0;     ///< acceleration after it [mm/s^2], in [0, b0]
  Crossing cross;         ///< from the dip's end through v = 0 (all 0 where the dip ends at v = 0)
  Ramp rest;              ///< from (0, cross.a_zero) to (|v1|, 0)
  double t_cruise = 0.0;  ///< cruise at |v1| after `rest` (prescribed durations only) [s]
  /// Total duration [s].
  double time() const noexcept { return dip + cross.time() + rest.time() + t_cruise; }
};

/// The DipCrossing from `start` to (p1, v1, a = 0) where its distance reaches the target
/// (between the direct crossing's and the released one's; the dip found by a bracketed root
/// search, jerk/dip_cross.cpp). Status::not_supported where the shape does not apply (v1 == 0,
/// a start not moving against v1, not braking, beyond A- or V, or one that reaches v = 0 with
/// more acceleration than v1 allows) or the target lies outside the family's distances.
Status dip_crossing_move(const State& start, double p1, double v1, const Limits& limits,
                         DipCrossing& out) noexcept;

/// A DipCrossing from `start` to (p1, v1, a = 0) taking exactly `duration` [s] (>= the fastest
/// one's time): the change meets p1 - v1 t_cruise and the rest is cruised at v1, t_cruise found
/// by bisection (each step the fastest member for its target). Status::too_short below the
/// fastest time; not_supported where the family does not apply or no cruise gives the duration
/// to kRelRounding (the members end before the target moves out of their reach).
Status dip_crossing_of_duration(const State& start, double p1, double v1, double duration,
                                const Limits& limits, DipCrossing& out) noexcept;

/// World state at the end of `dc` started from `start` (closed-form chain).
State end_state(const State& start, const DipCrossing& dc) noexcept;

namespace detail {
/// fastest_move with Newton steps only in its level search (no curvature step): the oracle of
/// the curvature step (level_curve_test.cpp); the same result to the search's tolerance.
Status fastest_move_newton(const State& start, double p1, double v1, const Limits& limits,
                           Move& out) noexcept;
}  // namespace detail

/// A Reversal from `start` to (p1, v1 != 0, a = 0) taking exactly `duration` [s] (>= the
/// fastest Reversal's time): the turning level lowered below the fastest one, the rest of the
/// way cruised at it (time synchronisation of a move that must turn). Status::too_short below
/// the fastest time, not_supported where no Reversal applies, where stop-and-go already fills
/// the way (no slower turn exists), or where the duration falls into the gap between the two
/// stretches of feasible levels (jerk/reverse.cpp).
Status reversal_of_duration(const State& start, double p1, double v1, double duration,
                            const Limits& limits, Reversal& out) noexcept;

// Velocity changes that end with an acceleration (issue 12).

/// Up to three constant-jerk phases from (v0, a0) to (v1, a1): jerk towards the extreme
/// acceleration a_peak, [hold there], jerk to a1. The intended boundary values travel with it.
struct StateRamp {
  std::array<double, 3> jerk{};      ///< jerk of each phase [mm/s^3]
  std::array<double, 3> duration{};  ///< duration of each phase [s], >= 0
  double a_peak = 0.0;               ///< acceleration after phase 1 and in phase 2 [mm/s^2]
  double v_end = 0.0;                ///< velocity after phase 3 [mm/s]
  double a_end = 0.0;                ///< acceleration after phase 3 [mm/s^2]
  /// Total duration [s].
  double time() const noexcept { return duration[0] + duration[1] + duration[2]; }
};

/// Time-optimal change from (v0, a0) to (v1, a1) with |jerk| = j, acceleration within
/// [-a_down, a_up] (the caller's frame; no velocity limit: the velocity may pass v1 on the way
/// when a0 or a1 forces it). a0 and a1 are expected within the limits and are clamped to them.
/// The velocity change dv = v1 - v0 beyond that of the direct jerk from a0 to a1
/// (dv_direct = (a0 + a1) |a1 - a0| / (2j)) sets the direction of the pulse: above it a peak
/// a_p = min(a_up, sqrt(j dv + (a0^2 + a1^2) / 2)) >= max(a0, a1), below it the mirrored
/// trough. With a1 = 0 it is velocity_ramp (same phases to rounding).
StateRamp velocity_ramp_to(double v0, double a0, double v1, double a1, double a_up, double a_down,
                           double j) noexcept;

/// Distance [mm] travelled by `ramp` from (v0, a0) (closed-form chain).
double distance(double v0, double a0, const StateRamp& ramp) noexcept;

/// State (p from 0, v, a) of `ramp` begun at (v0, a0) at time t [s], t clamped to
/// [0, ramp.time()] (closed form per phase, boundary accelerations snapped to the intended).
State state_at(double v0, double a0, const StateRamp& ramp, double t) noexcept;

/// First time [s] at which `ramp` begun at (v0, a0) has covered the distance s [mm]: 0 for
/// s <= 0, ramp.time() when the ramp's distance is below s. Meant for ramps that do not move
/// backward (v >= 0 throughout; then p is monotone and the answer unique): a forward pass
/// follows a change until a joint cuts it and carries (v, a) there (state_at of this time).
/// Bisection on the phase that contains s, to the resolution of double.
double time_at_distance(double v0, double a0, const StateRamp& ramp, double s) noexcept;

}  // namespace ncsim::jerk

#include "jerk/ramp_inline.hpp"  // IWYU pragma: export
