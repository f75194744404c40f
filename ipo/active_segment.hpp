#pragma once
// ipo/active_segment: the segment the path is on and the velocity plan it follows there.
//
// Purpose: hold the active look-ahead entry, its 100 % profile (planner::profile) and the plan
// the path follows on it: the 100 % profile itself, or a run-time plan (ipo/override.hpp)
// after an override, feed hold or velocity cap change; advance the entry's local time and
// account the time lost against the 100 % profile.
// Inputs: the planned segments in path order (begin()), the factor and cap each cycle asks for
// (PathOverride), the axis limits and, under #TRAFO ON, the joint limits (the raised cap above
// 100 %), the programmed Moves (SegmentQueue::programmed).
// Outputs: the path state at the local time (state()), the duration, whether the plan holds,
// the factor followed, the time lost in the cycle, the velocity and acceleration the path
// arrives with at the entry's end.
// Invariants: a factor or cap change inside a tolerance ball waits until the ball is left,
// except a stop (factor 0), its release and a cap, which act at once (000 l.366, 002 l.391);
// every plan keeps the 100 % plan's ceilings (make_plan), so stops and joint caps hold at any
// factor; nothing here throws.

#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include "ipo/override.hpp"
#include "ipo/segment_queue.hpp"
#include "planner/lookahead.hpp"
#include "planner/move.hpp"
#include "planner/prepare.hpp"

namespace ncsim::ipo {

class ActiveSegment {
 public:
  /// `axes`, `joints` and `queue` must outlive the part.
  ActiveSegment(std::span<const planner::AxisLimits> axes,
                const std::optional<planner::JointLimits>& joints, OverrideType type,
                const SegmentQueue& queue) noexcept
      : axes_(axes), joints_(joints), type_(type), queue_(queue) {}
  ActiveSegment(const ActiveSegment&) = delete;
  ActiveSegment& operator=(const ActiveSegment&) = delete;

  /// Makes `next` the active segment, at its start, planned for factor `f` [1] and velocity
  /// cap `cap` [mm/s] from the arrival state (the 100 % profile where it applies). False when
  /// no plan fits (NC6300; the path cannot go on).
  bool begin(planner::PlannedSegment&& next, double f, double cap) noexcept;
  /// At the start of a motion cycle: the factor `f` [1] and cap [mm/s] asked for now; a change
  /// replans from the path state (after the tolerance ball, see the invariants).
  void start_cycle(double f, double cap) noexcept;
  /// Advances the local time to `t_new` [s], accounting the time lost.
  void advance_to(double t_new) noexcept;
  /// The plan holds (feed hold / factor 0) for the `rest` [s] of the cycle: time lost.
  void hold_for(double rest) noexcept { lost_ += rest; }
  /// The end of the entry is reached: the path arrives at the next one with the plan's exit.
  void arrive() noexcept;
  /// The path stops at the end of the entry (a programmed stop or nothing beyond it).
  void stop() noexcept;
  /// The next entry starts at `v` [mm/s] with a = 0 (a moving hand-over, sync-feed).
  void start_from(double v) noexcept {
    v_arrive_ = v;
    a_arrive_ = 0.0;
  }
  /// The path state at the local time; s in [0, L] (L at the end of a plan that does not hold).
  planner::PathState state() const noexcept;
  /// Arc length of the last sample on the entry [mm] and its update.
  double s_sampled() const noexcept { return s_sampled_; }
  void set_sampled(double s) noexcept { s_sampled_ = s; }

  bool active() const noexcept { return active_; }  ///< the entry is being traversed
  const planner::PlannedSegment& segment() const noexcept { return cur_; }
  double t_in() const noexcept { return t_in_; }           ///< local time [s]
  double duration() const noexcept { return dur_; }        ///< of the plan followed [s]
  bool holding() const noexcept { return plan_.hold; }     ///< the plan ends in a hold
  double factor() const noexcept { return plan_factor_; }  ///< factor of the plan [1]
  double lost() const noexcept { return lost_; }  ///< time lost in this cycle [s] (< 0: gained)
  /// Every segment visited in this cycle is jerk-limited.
  bool interval_jerk_limited() const noexcept { return interval_jerk_limited_; }
  /// Ceilings of the plan followed: the highest path velocity [mm/s] and acceleration
  /// [mm/s^2] it can reach (above the 100 % caps under an override above 100 %).
  double v_ceiling() const noexcept { return v_ceiling_; }
  double a_ceiling() const noexcept { return a_ceiling_; }
  double v_arrive() const noexcept { return v_arrive_; }  ///< at the last joint [mm/s]
  double a_arrive() const noexcept { return a_arrive_; }  ///< at the last joint [mm/s^2]

 private:
  /// Plans the entry from its start at the arrival state (the 100 % profile when it applies).
  bool plan_entry(double f, double cap) noexcept;
  /// Replans for factor f and cap from the state (s [mm], v [mm/s], a [mm/s^2]); false (plan
  /// kept) when nothing fits.
  bool replan(double f, double cap, double s, double v, double a) noexcept;

  std::span<const planner::AxisLimits> axes_;
  const std::optional<planner::JointLimits>& joints_;
  OverrideType type_;
  const SegmentQueue& queue_;

  bool active_ = false;
  planner::PlannedSegment cur_;
  planner::SegmentProfile prof_;  ///< the entry's 100 % profile
  double dur_ = 0.0;              ///< duration of the plan followed [s]
  double t_in_ = 0.0;             ///< time into the entry [s]
  double s_sampled_ = 0.0;        ///< arc length of the last sample [mm]
  bool interval_jerk_limited_ = true;
  PathPlan plan_;             ///< the plan the path follows
  bool on_plan_ = true;       ///< plan_ is the look-ahead's 100 % profile itself
  double plan_factor_ = 1.0;  ///< factor plan_ was made for
  double plan_cap_ = std::numeric_limits<double>::infinity();  ///< cap plan_ was made for
  double v_ceiling_ = 0.0;                                     ///< v_ceiling()
  double a_ceiling_ = 0.0;                                     ///< a_ceiling()
  double v_arrive_ = 0.0;      ///< path velocity at the end of the previous entry [mm/s]
  double a_arrive_ = 0.0;      ///< path acceleration there [mm/s^2] (a carried ramp)
  bool has_ball_ = false;      ///< the entry holds a tolerance-ball blend
  bool raised_ready_ = false;  ///< raised_ computed for the entry
  RaisedLimits raised_;        ///< the entry's limits above 100 %
  double t100_prev_ = 0.0;     ///< 100 % profile time at the last advance [s]
  double lost_ = 0.0;          ///< time lost in the cycle being done [s]
};

}  // namespace ncsim::ipo
