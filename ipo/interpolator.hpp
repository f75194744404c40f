#pragma once
// ipo/interpolator: the path interpolator, one interpolation cycle T per step().
//
// Purpose: turn a stream of planner::Move values (and dwells) into the cycle stream the axes
// receive: per cycle the path state s, v, a, j from the closed-form jerk-limited segment
// profiles (planner::profile / profile_at), the point on the curve for every axis, the axis
// velocity, acceleration and jerk by the chain rule, and the source line of the active block.
// Inputs: a Source the interpolator pulls from lazily (it may be endless), the axis limits
// (planner::AxisLimits), the exact-stop settings of each axis (P-AXIS-00236 window,
// P-AXIS-00532 settling time), the channel settings (cycle T) and the look-ahead window size
// (P-CHAN-00650).
// Outputs: step() returns the Cycle record of the cycle just done; an optional Sink sees every
// cycle and every joint the path passes (with its documented VELOJUMP / #TRANSVELMIN / C1 step).
// Method (docs/ipo.md): the look-ahead window is kept full (planner::Preparer +
// planner::LookAhead); the active segment's profile is evaluated at the local time t_in; a
// cycle that reaches the end of a segment carries the rest of T into the next one exactly, so
// the motion time of a program is the sum of its profile durations. Time is rounded up to
// whole cycles only where the path stands still by program: before a dwell (G04), at an exact
// stop (G60 / G360: window and settling time follow) and at the program end.
// Invariants: the per-cycle path never throws (errors from the source or a malformed Move end
// the stream with Status::error and a message); memory is bounded by the window (a ring of
// (N + 2) * 64 programmed Moves, N window entries, fixed at construction; the planner's chains
// hold their parts in vectors of at most 64); positions are continuous; a stop puts the axes
// on the programmed end point of its block bit for bit.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "ipo/override.hpp"
#include "planner/lookahead.hpp"
#include "planner/move.hpp"
#include "planner/prepare.hpp"

namespace ncsim::ipo {

using planner::AxisVec;

/// G04: dwell between motions [s] (the path stops before it).
struct Dwell {
  double seconds = 0.0;         ///< programmed dwell time [s], >= 0
  std::uint32_t line = 0;       ///< source line of the G04 block
  std::uint32_t event_tag = 0;  ///< channel events up to this tag fire when the dwell starts
  std::uint16_t file = 0;       ///< source file of `line` (interp::Command::file, 0: main)
  /// A technology function's acknowledgement (Activity::tech), not a G04
  bool tech = false;
  /// `seconds` count from the output of the events of `event_tag` when a motion started with
  /// them (MVS_SNS: the wait at the block's end is what the motion did not cover)
  bool since_output = false;
};

/// A point of the program where the channel takes over (program/channel_event.hpp): the path
/// stops exactly at the end of the block before it (the look-ahead ends there, as at a dwell);
/// the WaitHandler then decides whether the path goes on at once or holds (Activity::channel
/// cycles) until release_wait().
struct ChannelWait {
  std::uint32_t line = 0;  ///< source line of the command that needs the standing path
  std::uint32_t tag = 0;   ///< channel events up to this tag are due at the wait
  /// --- sync-feed: the wait after a block of INDP_SYN ... INTERRUPTIBLE motions followed by
  /// MC_TouchProbe or #SYNC IN: it need not wait for them (the catch-up takes them over).
  bool interruptible = false;
  std::uint16_t file = 0;  ///< source file of `line` (interp::Command::file, 0: main)
};

/// One item of the program stream.
using Item = std::variant<planner::Move, Dwell, ChannelWait>;

struct ChannelEvent;  // program/channel_event.hpp

/// Where the interpolator pulls its items from. next() fills `out` and returns true, or
/// returns false at the end of the program. May be endless; may throw (the interpolator
/// turns that into Status::error).
class Source {
 public:
  virtual ~Source() = default;
  virtual bool next(Item& out) = 0;
  /// The oldest channel event whose tag is <= `up_to`, removed from the source; false when
  /// there is none (sources without events: always).
  virtual bool take_event(std::uint32_t up_to, ChannelEvent& out) {
    (void)up_to;
    (void)out;
    return false;
  }
};

/// Called by the interpolator when the path has stopped at a ChannelWait (inside step()).
class WaitHandler {
 public:
  virtual ~WaitHandler() = default;
  /// True: the path goes on in the same step(); false: it holds until release_wait().
  virtual bool on_wait(const ChannelWait& wait) noexcept = 0;
};

/// A Source from a callable `bool(Item&)` (the adapter from the interpreter's commands).
class CallbackSource final : public Source {
 public:
  explicit CallbackSource(std::function<bool(Item&)> next) : next_(std::move(next)) {}
  bool next(Item& out) override { return next_(out); }

 private:
  std::function<bool(Item&)> next_;
};

/// Exact-stop settings of one axis (G60 / G360).
struct ExactStop {
  double window = 0.01;      ///< P-AXIS-00236 exact-stop window [mm | deg], > 0
  double settle_time = 0.0;  ///< P-AXIS-00532 time the axis stays in the window [s], >= 0
};

/// How much each cycle computes.
enum class Detail : std::uint8_t {
  path,  ///< path state and line only (`ncsim time`): no point, no axis values, no joints
  axes,  ///< also the point, each axis's v, a, j, and the joints (run, audit)
};

struct Config {
  std::vector<planner::AxisLimits> axes;  ///< one per machine axis in use
  std::vector<ExactStop> exact_stop;      ///< one per axis (empty: defaults)
  planner::ChannelLimits channel;         ///< cycle T [s], P-CHAN-00009
  std::size_t window = 120;               ///< look-ahead entries (planner::window_size)
  AxisVec start{};                        ///< axis positions before the first move [mm | deg]
  Detail detail = Detail::axes;
  /// Channel hook (channel/channel.hpp): true makes a G60 / G360 stop wait, in exact_stop
  /// cycles, until release_exact_stop() instead of for the settling time (the channel tests
  /// the window P-AXIS-00236 on the axes' actual positions).
  bool hold_exact_stop = false;
  /// Under a kinematic transform (#TRAFO ON): `axes` are the Cartesian X, Y, Z (...) and the
  /// path is also limited so that every joint keeps its own v, a, j (planner::Preparer::
  /// set_joints); the per-cycle joint setpoints come from ipo::JointStage (joint_stage.hpp).
  std::optional<planner::JointLimits> joints;
  OverrideType override_type = OverrideType::reduced;  ///< NCSIM-CHAN-630 (000 §7.5.6)
};

/// What the channel did in a cycle.
enum class Activity : std::uint8_t {
  motion,      ///< the path moved (or reached its end) in this cycle
  dwell,       ///< G04 dwell
  exact_stop,  ///< G60 / G360: waiting for the window and the settling time
  starved,     ///< the source gave nothing that moves (zero-length blocks only)
  channel,     ///< the path stands at a ChannelWait until the channel releases it
  tech,        ///< waiting for a technology function's acknowledgement (Dwell::tech)
};

/// The cycle just done.
struct Cycle {
  std::uint64_t index = 0;  ///< cycles done so far, this one included
  double t = 0.0;           ///< time at the end of this cycle [s] (index * T)
  std::uint32_t line = 0;   ///< source line of the active block
  std::uint16_t file = 0;   ///< source file of `line` (interp::Command::file, 0: main program)
  Activity activity = Activity::motion;
  bool rapid = false;                 ///< the active block is G00
  bool jerk_limited = true;           ///< the active block's slope is TRAPEZ / SIN2 / HSC
  bool interval_jerk_limited = true;  ///< every segment traversed in this cycle is jerk-limited
  double feed = 0.0;                  ///< programmed path velocity of the active segment [mm/s]
  /// The axes' velocity cap of the active segment when it is below `feed` (F capped:
  /// planner::PathLimits::feed_capped) [mm/s]; 0 when the axes allow F.
  double feed_cap = 0.0;
  planner::PathState path;                    ///< s (from the segment start), v, a, j of the path
  double distance = 0.0;                      ///< path length covered in this cycle [mm]
  AxisVec x{};                                ///< axis positions [mm | deg] (Detail::axes)
  AxisVec v{};                                ///< axis velocities, closed form [mm/s]
  AxisVec a{};                                ///< axis accelerations, closed form [mm/s^2]
  AxisVec j{};                                ///< axis jerks, closed form [mm/s^3]
  const planner::Move* programmed = nullptr;  ///< the block x belongs to (motion cycles)
  // --- override additions (issue 13, docs/ipo.md "Override and feed hold")
  bool held = false;    ///< motion cycle in which the path stands by feed hold / override 0
  double factor = 1.0;  ///< override factor of the plan the path follows (0 while holding)
  double lost = 0.0;    ///< time lost to override and holds in this cycle [s] (< 0: gained)
  /// Channel events up to this tag are due: the largest event_tag of the blocks and dwells
  /// started so far and of the waits reached (never decreases).
  std::uint32_t event_tag = 0;
  // --- indp: set by ipo::Channel (docs/ipo.md "INDP axes and technology functions")
  /// Bit i: axis i is driven by its INDP motion in this cycle; x, v, a, j are then the INDP
  /// setpoint's, and the axis is not part of the block's contour.
  planner::AxisMask independent = 0;
};

/// A joint between two planned segments, passed inside a cycle (Detail::axes only).
struct Joint {
  double t = 0.0;          ///< time of the joint [s]
  std::uint32_t line = 0;  ///< line of the incoming block
  std::uint16_t file = 0;  ///< source file of `line` (interp::Command::file, 0: main program)
  planner::TransitionClass cls = planner::TransitionClass::c0;
  planner::StopReason stop = planner::StopReason::none;
  bool jerk_limited = true;  ///< both sides jerk-limited slopes
  /// P-CHAN-00009 on (ChannelLimits::limit_c1_by_jerk): the acceleration steps are bounded by
  /// j T; off, the kernel does not reduce the velocity for them and they are not bounded.
  bool c1_limited = true;
  double v = 0.0;                                            ///< path velocity at the joint [mm/s]
  planner::LinkRule rule = planner::LinkRule::segment_caps;  ///< what set the link velocity
  double transvelmin = 0.0;  ///< #TRANSVELMIN of the incoming block [mm/s] (0: not programmed)
  AxisVec dv{};              ///< axis velocity step out - in [mm/s] (VELOJUMP)
  AxisVec da{};              ///< axis acceleration step out - in [mm/s^2] (C1, and C0 on curves)
  /// --- trafo: under a kinematic transform (Config::joints, both blocks transformed) the
  /// joints' steps: velocity v (q'_out - q'_in), acceleration v^2 (q''_out - q''_in) +
  /// a (q'_out - q'_in), q' = dq/ds from the inverse (planner::joint_derivatives).
  bool joint_steps = false;
  AxisVec dq{};  ///< joint velocity step [mm/s | deg/s]
  AxisVec dw{};  ///< joint acceleration step [mm/s^2 | deg/s^2]
};

/// Receives the cycle stream (audit, CSV writer).
class Sink {
 public:
  virtual ~Sink() = default;
  /// A joint passed within the cycle that on_cycle() reports next.
  virtual void on_joint(const Joint& joint) = 0;
  virtual void on_cycle(const Cycle& cycle) = 0;
};

enum class Status : std::uint8_t {
  running,   ///< a cycle was done
  finished,  ///< the program has ended; no cycle was done
  error,     ///< the source failed or gave a malformed Move; message() says why
};

// --- operator: every block start (issue 13, docs/ipo.md "Block starts")
/// Told of every block that starts executing, in execution order, inside the step() of the
/// cycle in which it starts (also when several start in one cycle).
class BlockObserver {
 public:
  virtual ~BlockObserver() = default;
  /// A programmed Move (at its first path point) or a G04 dwell (> 0 s) of source line `line`
  /// in source file `file` (interp::Command::file, 0: the main program).
  virtual void on_block_started(std::uint32_t line, std::uint16_t file) noexcept = 0;
};
// --- operator: end

class PathInterpolator {
 public:
  /// Throws std::invalid_argument (value and parameter named) on unusable limits, window,
  /// cycle or exact-stop settings. `source` must outlive the interpolator; `sink` may be null.
  PathInterpolator(Config config, Source& source, Sink* sink = nullptr);
  PathInterpolator(const PathInterpolator&) = delete;
  PathInterpolator& operator=(const PathInterpolator&) = delete;

  /// Advances one interpolation cycle. Never throws.
  Status step() noexcept;
  /// The cycle done by the last step() that returned Status::running.
  const Cycle& cycle() const noexcept { return cycle_; }
  /// Why the stream ended with Status::error.
  const std::string& message() const noexcept { return message_; }
  double t_cycle() const noexcept { return t_; }  ///< [s]
  std::size_t axis_count() const noexcept { return axes_.size(); }
  const std::vector<planner::AxisLimits>& axes() const noexcept { return axes_; }
  /// Programmed Moves the interpolator holds (ring capacity, fixed).
  std::size_t ring_capacity() const noexcept { return ring_.size(); }
  /// Entries in the look-ahead window now.
  std::size_t window_fill() const noexcept { return window_.size(); }
  /// Channel hook (Config::hold_exact_stop): a G60 / G360 stop is waiting for release.
  bool holding_exact_stop() const noexcept { return held_; }
  /// Channel hook: ends the exact-stop wait; the next step() goes on with the path.
  void release_exact_stop() noexcept { held_ = false; }
  /// Channel hook: who decides at a ChannelWait (null: the path goes on at once).
  void set_wait_handler(WaitHandler* handler) noexcept { wait_handler_ = handler; }
  /// The path holds at a ChannelWait.
  bool holding_channel() const noexcept { return channel_held_; }
  /// Channel hook: ends the hold at a ChannelWait; the next step() goes on with the path.
  void release_wait() noexcept { channel_held_ = false; }

  // --- override additions (issue 13, docs/ipo.md "Override and feed hold")
  /// Path override factor (1 = 100 %), in [0, max_override(type)]; takes effect from the next
  /// step() with jerk-limited ramps (after the tolerance ball if the path is inside one).
  /// Throws std::invalid_argument naming the value and NCSIM-CHAN-630 when out of range.
  void set_override(double factor);
  /// Feed hold: the path stops on the contour as soon as the ramps allow and holds until
  /// released (then it resumes at the override). Acts inside a tolerance ball too (a stop).
  void set_feed_hold(bool on) noexcept { hold_ = on; }
  double override_factor() const noexcept { return override_; }  ///< set factor [1]
  bool feed_hold() const noexcept { return hold_; }
  OverrideType override_type() const noexcept { return override_type_; }
  // --- operator: block starts (null: none); `observer` must outlive the interpolator.
  void observe_blocks(BlockObserver* observer) noexcept { observer_ = observer; }
  // --- workspace: a path velocity cap from outside (issue 14, tracking/workspace_hold.hpp)
  /// Caps the path velocity [mm/s] (+inf: none) from the next step(): a jerk-limited replan
  /// from the path state as for an override change (also inside a tolerance ball); the entry
  /// that starts while capped starts capped. Negative or NaN values are taken as 0.
  void set_velocity_cap(double cap) noexcept { cap_ = cap >= 0.0 ? cap : 0.0; }
  double velocity_cap() const noexcept { return cap_; }  ///< [mm/s]
  /// The entry the path is on (null: none yet); valid until the next step().
  const planner::PlannedSegment* active_entry() const noexcept { return active_ ? &cur_ : nullptr; }
  /// --- hold: the k-th entry after the active one in the look-ahead window (null: none known).
  const planner::PreparedSegment* queued_entry(std::size_t k) const noexcept {
    return window_.queued(k);
  }
  // --- workspace: end
  // --- sync-feed: a path that starts moving after a catch-up (issue 14, tracking/sync_entry.hpp)
  /// While the path holds at a ChannelWait: pulls and prepares what follows the wait into the
  /// look-ahead window (as the path's own start would), so that its first segment is known.
  /// False when the source failed (the next step() reports it).
  bool prefill() noexcept;
  /// The first segment the path will run after the hold (null: none known: a dwell, a wait or
  /// the end follows) and the highest velocity it may be entered with [mm/s].
  const planner::PreparedSegment* next_segment() const noexcept { return window_.front(); }
  double next_entry_cap() const noexcept { return window_.front_entry_cap(); }
  /// The path's next segment starts at `v` [mm/s] (at most next_entry_cap()), and `lag` [s]
  /// (in [0, T)) after the start of the next cycle. Returns the velocity set.
  double start_moving(double v, double lag) noexcept;
  // --- sync-feed: end

 private:
  struct PendingDwell {
    double seconds = 0.0;
    std::uint32_t line = 0;
    std::uint32_t event_tag = 0;
    std::uint16_t file = 0;
    bool tech = false;
    bool since_output = false;
  };
  /// Keeps the window full: pulls items, prepares Moves, pushes segments. Returns false on error.
  bool fill() noexcept;
  /// Pops the next planned segment into cur_; false when the window is empty.
  bool start_next() noexcept;
  /// Makes `next` the active segment, at its start.
  void begin(planner::PlannedSegment&& next) noexcept;
  /// Fills the cycle record from cur_ at t_in_.
  void sample(double distance) noexcept;
  /// Reports the joint between the ending cur_ and the next segment (Detail::axes).
  void report_joint(const planner::PlannedSegment& next, double t_joint) noexcept;
  /// Reports the inner joints of cur_'s chain passed in (s_from, s_to] (Detail::axes, sink set).
  void report_inner_joints(double s_from, double s_to) noexcept;
  const planner::Move& programmed(std::uint32_t token) const noexcept {
    return ring_[token & ring_mask_];
  }
  Status fail(const char* what) noexcept;
  /// Ends the motion part of the cycle at a stop: axes exactly on the block's end point.
  void stop_at_end(double distance) noexcept;
  std::uint64_t cycles_for(double seconds) const noexcept;
  // --- override additions
  double effective_factor() const noexcept { return hold_ ? 0.0 : override_; }
  /// Plans cur_ from its start at the arrival velocity (the 100 % profile when it applies).
  bool plan_entry() noexcept;
  /// Replans cur_ for factor f from the state (s [mm], v [mm/s], a [mm/s^2]); false (plan
  /// kept) when nothing fits.
  bool replan(double f, double s, double v, double a) noexcept;
  /// True when s lies inside a tolerance-ball blend of cur_.
  bool in_ball(double s) const noexcept;
  /// Time of the 100 % profile at s on cur_ [s] (accounting of lost time).
  double t100(double s) const noexcept;
  /// Advances the plan time from t_in_ to t_new, accounting the time lost.
  void advance_to(double t_new) noexcept;

  std::vector<planner::AxisLimits> axes_;
  std::optional<planner::JointLimits> joints_;  ///< --- trafo-conveyor: Config::joints
  std::vector<ExactStop> exact_stop_;
  double t_ = 0.001;
  bool c1_limited_ = true;  ///< P-CHAN-00009 (ChannelLimits::limit_c1_by_jerk), for Joint
  Detail detail_ = Detail::axes;
  Source& source_;
  Sink* sink_ = nullptr;
  planner::Preparer prep_;
  planner::LookAhead window_;
  std::vector<planner::PreparedSegment> ready_;  ///< prepared, not yet in the window
  std::size_t ready_next_ = 0;
  std::vector<planner::Move>
      ring_;  ///< programmed Moves by token (Move::line given to the planner)
  std::uint64_t ring_mask_ = 0;
  std::uint64_t next_token_ = 0;  ///< token of the next Move pulled
  std::uint64_t oldest_ = 0;      ///< first token of the active segment
  Item item_;
  bool source_done_ = false;
  bool finished_ = false;
  bool failed_ = false;
  std::optional<PendingDwell> dwell_;  ///< G04 after the moves in the window
  /// The last rise of Cycle::event_tag by a motion: its tag and the cycle it rose in (the
  /// output of its events; Dwell::since_output)
  std::uint32_t tag_rise_ = 0;
  std::uint64_t tag_rise_index_ = 0;
  std::optional<ChannelWait> wait_;  ///< ChannelWait after the moves in the window
  WaitHandler* wait_handler_ = nullptr;
  bool channel_held_ = false;  ///< the path holds at a ChannelWait until release_wait()

  bool active_ = false;  ///< cur_ is being traversed
  planner::PlannedSegment cur_;
  planner::SegmentProfile prof_;
  double dur_ = 0.0;   ///< duration of cur_'s profile [s]
  double t_in_ = 0.0;  ///< time into cur_ [s]
  double s_prev_ = 0.0;
  bool interval_jerk_limited_ = true;  ///< every segment visited in this cycle is jerk-limited
  std::uint64_t wait_left_ = 0;        ///< dwell / settling cycles still to do
  bool hold_exact_stop_ = false;       ///< Config::hold_exact_stop
  bool held_ = false;                  ///< an exact stop waits for release_exact_stop()
  Activity wait_kind_ = Activity::dwell;
  std::uint32_t wait_line_ = 0;
  std::uint16_t wait_file_ = 0;  ///< source file of wait_line_
  // --- override additions
  OverrideType override_type_ = OverrideType::reduced;
  double override_ = 1.0;      ///< set factor
  bool hold_ = false;          ///< feed hold requested
  PathPlan plan_;              ///< the plan the path follows on cur_
  bool on_plan_ = true;        ///< plan_ is the look-ahead's 100 % profile itself
  double plan_factor_ = 1.0;   ///< factor plan_ was made for
  double v_arrive_ = 0.0;      ///< path velocity at the end of the previous entry [mm/s]
  double a_arrive_ = 0.0;      ///< path acceleration there [mm/s^2] (a carried ramp)
  bool has_ball_ = false;      ///< cur_ holds a tolerance-ball blend
  bool raised_ready_ = false;  ///< raised_ computed for cur_
  RaisedLimits raised_;        ///< cur_'s limits above 100 %
  double t100_prev_ = 0.0;     ///< 100 % profile time at s_prev_ [s]
  double lost_ = 0.0;          ///< time lost in the cycle being done [s]
  // --- workspace
  double cap_ = std::numeric_limits<double>::infinity();       ///< velocity cap set [mm/s]
  double plan_cap_ = std::numeric_limits<double>::infinity();  ///< cap plan_ was made for
  double start_lag_ = 0.0;  ///< --- sync-feed: start_moving()'s lag, used by the next motion [s]
  // --- operator: block starts
  /// Reports the Moves up to ring token `token` (low 32 bits) not reported yet.
  void report_starts_to(std::uint32_t token) noexcept;
  /// Reports the parts of cur_'s chain starting in (s_from, s_to].
  void report_part_starts(double s_from, double s_to) noexcept;
  BlockObserver* observer_ = nullptr;
  std::uint64_t reported_ = 0;  ///< tokens below this one were reported started
  Cycle cycle_;
  std::string message_;
};

}  // namespace ncsim::ipo
