#pragma once
// runner/spec: what to run, as one value (the CLI fills it from its options; sweep and
// tune-delay add their adjustments of the world).
//
// Purpose: everything runner::load needs to load and validate a run: the program, its machine
// folder and scenario, the cycle, the audit, --max-time, the cycle files, V.E. values. Inputs:
// the caller's choices. Outputs: none (a value). Invariants: none beyond the fields' ranges,
// which the loader checks (a bad value is a usage error with its message, never a throw).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "machines/machine.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::conveyor {
class Port;
}
namespace ncsim::channel {
class Channel;
}

namespace ncsim::runner {

/// How a run ended, as the command's exit status: 0 ok, 1 program errors (syntax, semantic or
/// run-time), 2 usage, configuration or write errors, 3 audit violations.
enum class Exit : int { ok = 0, program_errors = 1, usage = 2, audit = 3 };

/// The program and its world: what every program-reading command takes (check, trace, time,
/// run, report, sweep, tune-delay, golden).
struct ProgramSpec {
  std::filesystem::path program;                     ///< NC program file ("-": standard input)
  std::optional<std::filesystem::path> machine_dir;  ///< --machine
  std::optional<std::filesystem::path> scenario;     ///< --scenario
  /// Without `scenario`: the program folder's scenario.toml, if there is one (false: none; a
  /// line's channel runs the scenario its line file names, docs/lines.md)
  bool scenario_lookup = true;
  std::vector<std::string> external;              ///< --ve NAME=value (V.E. variables)
  std::vector<std::filesystem::path> cycle_dirs;  ///< --cycles DIR (cycle files, in order)
  std::string missing_cycles = "error";           ///< --missing-cycles error|skip
  /// --max-time S (time, run, report): the run stops at S seconds of machine time like a
  /// scenario's `[stop] time` (the earlier of both); for programs that run endlessly
  std::optional<double> max_time;
};

/// Changes the loaded machine and scenario before the conveyor world is built (may be empty);
/// the third argument is the run's interpolation cycle [s] (--cycle-us or the default).
using AdjustWorld =
    std::function<void(machines::Machine&, std::optional<scenario::Scenario>&, double t_cycle)>;
/// Wraps the conveyor world (may be empty): e.g. a belt velocity override.
using WrapPort = std::function<std::unique_ptr<conveyor::Port>(std::unique_ptr<conveyor::Port>)>;

/// One run of a program on the channel loop.
struct RunSpec {
  ProgramSpec program;
  std::optional<std::uint64_t> cycle_us;  ///< --cycle-us [us]; nullopt: NCSIM-CHAN-610
  bool audit = false;                     ///< the audit sink on the axes' setpoints
  /// The channel answers position barriers from its set positions (time, run, report); the
  /// headless runs of sweep and tune-delay decode as they always did, without.
  bool answer_positions = true;
  /// [mm/s] replaces every #SYNC IN's CONV_VEL (interp::Options::conv_vel); nullopt: the
  /// program's (sweep --conv-vel follow / keep).
  std::optional<double> conv_vel;
  AdjustWorld adjust;  ///< sweep / tune-delay: the machine and scenario changed (may be empty)
  WrapPort wrap;       ///< sweep: the conveyor world wrapped (may be empty)
  /// Build the conveyor world at load; false: the caller gives the channel its Port (a line's
  /// channels share the line's belt, docs/lines.md).
  bool build_world = true;
};

}  // namespace ncsim::runner
