#pragma once
// scenario/player: evaluates a Scenario cycle by cycle for the channel loop.
//
// Purpose: the one place that decides which scenario events are due when. The channel loop
// (channel/) owns a Player; per interpolation cycle it reports the blocks that started executing
// (block_started) and then asks for the actions due in that cycle (step).
// Inputs: the Scenario (must outlive the Player), the cycle index and time, the main-program
// lines of the blocks that start. Outputs: the due Actions in order, the V.E. store the
// seam's barrier answers read from, the override / feed-hold state, and the stop reason once
// a [stop] condition is met.
// Order (docs/scenario.md "When events fire"): in one cycle, feed-hold releases scheduled by
// `duration` come first (by due time, then by when they were scheduled), then the due events
// in file order; an event's actions in the order Event::actions holds. An `at` event is due
// at the first cycle whose time is >= at - kTimeEpsilon; a `line` event in the cycle whose
// step() follows the block_started() of its pass. When a stop condition is met the run ends
// before that cycle: step() yields nothing more.
// Invariants: a pure function of the scenario and the reported progress (no clock, no
// randomness): the same reports give the same actions. Memory: one counter per line the
// scenario names, one entry per pending hold release; nothing grows with the run's length.
// The per-cycle calls never throw; a misuse (time or cycle going backwards) aborts.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scenario/scenario.hpp"

namespace ncsim::scenario {

/// The V.E. values of the world outside the NC: the scenario's initial values, then the
/// events' writes. The channel answers a barrier's V.E. names from here.
class VeStore {
 public:
  explicit VeStore(const Scenario& scenario);
  /// Writes V.E.`name` (upper case).
  void write(const std::string& name, double value);
  /// The value of V.E.`name`, if the world has one.
  std::optional<double> read(std::string_view name) const;
  /// For each of `names` the store holds, out[name] = value; the others are left out (the
  /// interpreter then keeps the value it has: interp::RunState::external).
  void answer(const std::vector<std::string>& names, std::map<std::string, double>& out) const;
  /// Every value held, by name.
  const std::map<std::string, double, std::less<>>& values() const { return values_; }
  /// Writes so far: a barrier waiting for a value need only be re-answered when it changed.
  std::uint64_t generation() const { return generation_; }

 private:
  std::map<std::string, double, std::less<>> values_;
  std::uint64_t generation_ = 0;
};

class Player {
 public:
  /// `scenario` must outlive the player.
  explicit Player(const Scenario& scenario);

  /// A block starts executing: `line` is its main-program source line, 0 for a block from
  /// another file. Call once per block in execution order (several per cycle allowed), before
  /// the step() of the cycle in which it starts.
  void block_started(std::uint32_t line);

  /// The cycle `cycle` (0-based, one more than the last call's) at time `t` [s] is about to be
  /// computed. Returns the actions due now, in order (valid until the next call); V.E. writes
  /// among them are already in ve(), overrides and feed hold already in the state below.
  const std::vector<Action>& step(std::uint64_t cycle, double t);

  /// Fires now, at the time of the last step(), the `line` events whose pass a block_started()
  /// since the last step() or fire_lines() began: the channel calls it right after
  /// block_started() inside the cycle in which the block starts (docs/scenario.md "When events
  /// fire"). Returns their actions, in order (valid until the next call), applied as step()'s
  /// are; nothing once a [stop] is met or the stop line's last pass has ended (the run ends
  /// before the next cycle).
  const std::vector<Action>& fire_lines();

  /// True while a later step() may still fire something or end the run without a block
  /// starting: a time event not yet due, a pending hold release, or a [stop] time / cycles.
  /// False: a path standing by feed hold or override 0 stands forever (the channel's NC6301).
  bool more_to_come() const {
    return next_time_ < time_events_.size() || !releases_.empty() || scenario_.stop.time ||
           scenario_.stop.cycles;
  }

  /// Set by the step() that met a [stop] condition: the run ends before that cycle.
  std::optional<StopReason> stop() const { return stop_; }
  /// The world's V.E. values.
  const VeStore& ve() const { return ve_; }
  /// The same store, writable: the program's own V.E. writes go in too (ProgramSource).
  VeStore& ve() { return ve_; }
  /// Path override in force [-] (1.0 = 100 %).
  double path_override() const { return path_override_; }
  /// Override in force for INDP axis `axis` [-]; 1.0 when no event set one.
  double axis_override(std::string_view axis) const;
  /// Feed hold in force.
  bool feed_hold() const { return feed_hold_; }
  /// The reduced actual-value filter (MCV_SetReducedFilter) as the events last set it.
  bool reduced_filter() const { return reduced_filter_; }
  /// Passes of main-program line `line` started so far (0 for a line the scenario does not
  /// name: only those are counted).
  std::uint32_t passes(std::uint32_t line) const;

 private:
  struct Release {
    double t;           // [s] due time
    std::uint64_t seq;  // scheduling order
  };
  void apply(const Action& action);
  void fire(const Event& event, double t);

  const Scenario& scenario_;
  VeStore ve_;
  std::vector<std::size_t> time_events_;  // indices of `at` events (in time order)
  std::size_t next_time_ = 0;             // first time event not yet due
  struct LineCount {
    std::uint32_t passes = 0;         // passes started
    std::vector<std::size_t> events;  // `line` events on this line (indices, file order)
  };
  std::map<std::uint32_t, LineCount> lines_;  // the lines the scenario names
  std::vector<std::size_t> line_due_;         // `line` events whose pass started, not yet fired
  std::vector<Release> releases_;             // pending hold releases, sorted by (t, seq)
  std::uint64_t release_seq_ = 0;
  std::uint32_t current_line_ = 0;  // line of the block executing
  bool pass_stop_pending_ = false;  // the stop line's last pass ended
  std::optional<std::uint64_t> last_cycle_;
  double last_t_ = 0.0;
  std::optional<StopReason> stop_;
  std::vector<Action> due_;
  double path_override_ = 1.0;
  std::map<std::string, double, std::less<>> axis_override_;
  bool feed_hold_ = false;
  bool reduced_filter_ = false;
};

}  // namespace ncsim::scenario
