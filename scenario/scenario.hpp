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

/// One effect of an event; a Player yields these in order.
using Action = std::variant<PathOverride, AxisOverride, FeedHold, VeWrite>;

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
enum class StopReason { program_end, error, time, cycles, line_passes };

/// "program end", "error", "stop.time", "stop.cycles", "stop.passes".
std::string_view to_string(StopReason reason);

/// A V.E. initial value of `[ve]`.
struct VeInitial {
  std::string name;  ///< upper case, without "V.E."
  double value = 0.0;
  core::SourceLoc loc;
};

/// Largest override: 1000 % (docs/scenario.md "Decisions").
inline constexpr double kOverrideMax = 10.0;
/// Tolerance of time comparisons [s]: cycle times are sums of t_cycle, not exact decimals.
inline constexpr double kTimeEpsilon = 1e-9;

/// The scenario: built only by load_scenario(); immutable afterwards.
struct Scenario {
  std::string file;           ///< the file it was read from, as given
  std::string description;    ///< `description`, free text
  std::vector<VeInitial> ve;  ///< `[ve]`, in file order
  std::vector<Event> events;  ///< `[[event]]`, in file order
  StopConditions stop;        ///< `[stop]`

  /// True when something needs the channel loop (events or stop conditions), i.e. more than
  /// the V.E. initial values that decode-only commands (`check`, `trace`) read.
  bool needs_channel() const { return !events.empty() || stop.any(); }
  /// The V.E. initial value of `name` (upper case), if given.
  std::optional<double> ve_initial(std::string_view name) const;
};

}  // namespace ncsim::scenario
