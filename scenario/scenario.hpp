#pragma once
// scenario/scenario: the world outside the CNC as one immutable value (design.md "The
// scenario", docs/scenario.md).
//
// Purpose: what the operator and the PLC side do while a program runs: V.E. values at the
// start, events (override of the path and of INDP axes, feed hold on/off, V.E. writes) at a
// time, on reaching a program line, or at the n-th pass of a line, and conditions that stop
// the program (a time, a cycle count, a number of passes of a line).
// Inputs: a TOML file, read and validated by load_scenario() (scenario/loader.hpp).
// Outputs: this value; scenario::Player (scenario/player.hpp) evaluates it cycle by cycle.
// Invariants (established by the loader, relied on by the player): every number is finite and
// in its documented range, converted once to internal units (s, fractions); time-triggered
// events appear in non-decreasing time order; every event has exactly one trigger and at
// least one action; V.E. and axis names are upper case and unique within their table.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/source_file.hpp"
#include "core/tolerance.hpp"

namespace ncsim::scenario {

/// Due at the first cycle whose time is at or after `t` (to kTimeEpsilon).
struct AtTime {
  double t = 0.0;  ///< [s] from the program start
};

/// Due when a block of main-program line `line` starts executing for the `pass`-th time.
struct AtLine {
  std::uint32_t line = 1;  ///< 1-based source line of the main program
  std::uint32_t pass = 1;  ///< 1-based pass count of that line
};

using Trigger = std::variant<AtTime, AtLine>;

/// Path override (P-CHAN override of the channel): 1.0 = 100 %.
struct PathOverride {
  double fraction = 1.0;  ///< [-] 0 .. kOverrideMax
};

/// Override of one INDP axis, by its name in the machine (upper case).
struct AxisOverride {
  std::string axis;       ///< axis name, e.g. "C"
  double fraction = 1.0;  ///< [-] 0 .. kOverrideMax
};

/// Feed hold switched on (`on`) or released.
struct FeedHold {
  bool on = true;
};

/// A value the PLC side writes into V.E.`name`.
struct VeWrite {
  std::string name;  ///< upper case, without "V.E."
  double value = 0.0;
};

/// MCV_SetReducedFilter from the PLC side: the conveyor's reduced actual-value filter on/off.
struct ReducedFilter {
  bool on = true;
};

/// One effect of an event; a Player yields these in order.
using Action = std::variant<PathOverride, AxisOverride, FeedHold, VeWrite, ReducedFilter>;

/// One `[[event]]` of the file.
struct Event {
  Trigger trigger;
  std::vector<Action> actions;         ///< in the documented order (docs/scenario.md)
  std::optional<double> hold_release;  ///< [s] after the trigger: FeedHold{false} (feed_hold
                                       ///< = true with `duration`)
  core::SourceLoc loc;                 ///< position of its `[[event]]` header in the file
};

/// `[stop]`: the program stops when a condition is met (the first one met gives the reason).
struct StopConditions {
  std::optional<double> time;           ///< [s]: due at the first cycle at or after it
  std::optional<std::uint64_t> cycles;  ///< interpolation cycles computed before the stop
  std::optional<std::uint32_t> line;    ///< main-program line counted by `passes`
  std::optional<std::uint32_t> passes;  ///< stop when the `passes`-th pass of `line` ends
  core::SourceLoc loc;                  ///< position of the [stop] table
  bool any() const { return time || cycles || passes; }
};

/// Why a run ended, for the report. The channel owns `program_end` and `error`; the others
/// come from the scenario's [stop] conditions.
/// `endless`: no [stop], and the program came back to an earlier state on its own
/// (interp::Options::end_when_endless).
enum class StopReason { program_end, error, time, cycles, line_passes, endless };

/// "program end", "error", "stop.time", "stop.cycles", "stop.passes", "endless".
std::string_view to_string(StopReason reason);

/// A V.E. initial value of `[ve]`.
struct VeInitial {
  std::string name;  ///< upper case, without "V.E."
  double value = 0.0;
  core::SourceLoc loc;
};

/// How the conveyor belt moves (docs/scenario.md "[conveyor]").
enum class ConveyorMode {
  encoder,  ///< the scenario moves the belt; the conveyor axis is an encoder (ACHSMODE_COUNTER)
  spindle,  ///< the program drives it (S1[MC_MoveVelocity ...])
};

/// A change of the encoder belt's velocity: from `t` on, linear in time over `ramp` to `velocity`
/// (ramp 0: a step).
struct BeltChange {
  double t = 0.0;         ///< [s] start of the change
  double velocity = 0.0;  ///< [mm/s] velocity after the change (0: the belt stops)
  double ramp = 0.0;      ///< [s] duration of the linear change, >= 0
};

/// Periodic fluctuation of the belt velocity: v = v_profile (1 + amplitude sin(2 pi f t)).
struct BeltFluctuation {
  double amplitude = 0.0;  ///< [-] fraction of the velocity, 0 .. 1
  double frequency = 0.0;  ///< [Hz] > 0
};

/// Gaussian white noise on the conveyor axis's measured position, seeded.
struct BeltNoise {
  double sigma = 0.0;      ///< [mm] standard deviation, >= 0
  std::uint64_t seed = 1;  ///< seed of ncsim's own generator (same seed, same run)
};

/// The measuring unit.
enum class SensorKind {
  light_barrier,  ///< the signal is on while a workpiece blocks the beam (front edge .. rear edge)
  camera,         ///< one trigger pulse at each front edge (both edges there)
};

struct Sensor {
  SensorKind kind = SensorKind::light_barrier;
  std::optional<double> position;  ///< [mm] MCS X of the sensor; nullopt: P-CHAN-00368
  bool front_edge_rising = true;   ///< light barrier: the front edge makes a rising edge
  std::uint32_t queue = 16;        ///< PLC-side queue length of measured values (method 3)
};

/// One workpiece: its front edge passes the sensor at a belt travel or at a time.
struct Workpiece {
  std::optional<double> travel;  ///< [mm] conveyor axis position at the front edge's arrival
  std::optional<double> t;       ///< [s] time of the front edge's arrival (exactly one is set)
  double length = 100.0;         ///< [mm] front edge to rear edge along the belt, > 0
  std::vector<VeWrite> ve;       ///< V.E. values written when the workpiece is measured
  core::SourceLoc loc;           ///< its table in the file
};

/// `[conveyor.workpieces]`: `count` workpieces, the first at `first` (travel or time), then one
/// every `pitch` (travel or time, same kind as `first`).
struct WorkpieceSeries {
  Workpiece first;          ///< the first workpiece (travel or t), its length and V.E. values
  double pitch = 0.0;       ///< [mm] or [s] between consecutive front edges, > 0
  std::uint64_t count = 0;  ///< >= 1
  /// [mm] or [s] a random stream: each gap is pitch + scatter x u, u uniform in (0, 1] from
  /// SplitMix64(seed) (conveyor/noise.hpp); 0: every gap is pitch.
  double scatter = 0.0;
  std::uint64_t seed = 1;  ///< the stream's seed
};

/// `[conveyor]`: the conveyor world (docs/scenario.md, docs/conveyor.md "The world").
struct Conveyor {
  ConveyorMode mode = ConveyorMode::spindle;
  double velocity = 0.0;            ///< [mm/s] encoder belt velocity at t = 0
  std::vector<BeltChange> profile;  ///< encoder only; in time order, not overlapping
  std::optional<BeltFluctuation> fluctuation;
  std::optional<BeltNoise> noise;
  double dead_time = 0.0;  ///< [s] real belt -> its measured value, >= 0
  Sensor sensor;
  std::vector<Workpiece> workpieces;      ///< `[[conveyor.workpiece]]`, in file order
  std::optional<WorkpieceSeries> series;  ///< `[conveyor.workpieces]`
  core::SourceLoc loc;                    ///< the [conveyor] table
};

/// Largest override: 1000 % (docs/scenario.md "Decisions").
inline constexpr double kOverrideMax = 10.0;
/// Smallest override above 0: 0.1 % (docs/scenario.md "Decisions"); below it a path would
/// creep for ages (1e-300 % never ended, issue 34 item 7).
inline constexpr double kOverrideMin = 0.001;
/// Tolerance of time comparisons [s]: cycle times are sums of t_cycle, not exact decimals.
inline constexpr double kTimeEpsilon = kSameTime;

/// `[tech]`: a technology function's execution time, output -> acknowledgement (`M6 = 4.5`:
/// seconds), over the machine's NCSIM-CHAN-650..653 (docs/scenario.md "[tech]").
struct TechDuration {
  char kind = 'M';           ///< 'M', 'H', 'S' or 'T'
  std::uint32_t number = 0;  ///< M / H number 0 .. 999 (0 for S and T)
  double seconds = 0.0;      ///< [s] 0 .. 86400
};

/// The scenario: built only by load_scenario(); immutable afterwards.
struct Scenario {
  std::string file;                  ///< the file it was read from, as given
  std::string description;           ///< `description`, free text
  std::vector<VeInitial> ve;         ///< `[ve]`, in file order
  std::vector<Event> events;         ///< `[[event]]`, in file order
  StopConditions stop;               ///< `[stop]`
  std::optional<Conveyor> conveyor;  ///< `[conveyor]` (conveyor tracking, issue 14)
  std::vector<TechDuration> tech;    ///< `[tech]`, in key order
  /// A channel of a line with a station on the belt: the line's PLC writes V.E. values with
  /// every measured value (LINE_WORKPIECE, LINE_TRAVEL) and LINE_MORE (docs/lines.md).
  bool line_plc = false;

  /// True when something needs the channel loop (events or stop conditions), i.e. more than
  /// the V.E. initial values that decode-only commands (`check`, `trace`) read.
  bool needs_channel() const { return !events.empty() || stop.any() || workpiece_ve(); }
  /// True when a workpiece of `[conveyor]` carries V.E. values (written when it is measured).
  bool workpiece_ve() const {
    if (line_plc) return true;
    if (!conveyor) return false;
    for (const Workpiece& w : conveyor->workpieces)
      if (!w.ve.empty()) return true;
    return conveyor->series && !conveyor->series->first.ve.empty();
  }
  /// The V.E. initial value of `name` (upper case), if given.
  std::optional<double> ve_initial(std::string_view name) const;
};

}  // namespace ncsim::scenario
