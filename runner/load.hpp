#pragma once
// runner/load: a run's program, machine, scenario and conveyor world, loaded and validated.
//
// Purpose: the one place that turns a RunSpec into what a channel runs on. Inputs: the spec
// (program, machine folder, scenario, --cycle-us, --max-time, cycle files, sweep's and
// tune-delay's adjustments). Outputs: a Loaded, or the exit category with the messages a command
// prints (positioned diagnostics with their source lines, in the order they arose); nothing is
// printed here. Invariants: a Loaded's program has no syntax error, its cycle suits every
// interpolated axis's Kv (Kv x T <= 1), and its conveyor world exists exactly when the machine
// has a conveyor axis.

#include <exception>
#include <memory>
#include <optional>
#include <string>

#include "conveyor/port.hpp"
#include "core/source_file.hpp"
#include "interp/interpreter.hpp"
#include "machines/machine.hpp"
#include "runner/spec.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::runner {

/// What a run is assembled from. Owned by runner::Run at a fixed address (the interpreter and
/// the program source keep references into it).
struct Loaded {
  core::SourceFile file;
  machines::Machine machine;
  double t_cycle = 0.001;  ///< --cycle-us, else the channel's NCSIM-CHAN-610 [s]
  interp::Options interp;  ///< the scenario's V.E. initial values (barrier answers), cycles
  std::optional<scenario::Scenario> scenario;  ///< played by the channel when it has events
  /// The conveyor world (docs/conveyor.md "The world") on a machine with a conveyor axis.
  std::unique_ptr<conveyor::Port> port;
};

/// The outcome of runner::load.
struct LoadResult {
  std::unique_ptr<Loaded> loaded;  ///< null when the run cannot start
  Exit exit = Exit::ok;            ///< usage or program_errors when it cannot
  /// What the command prints on stderr, in order: the machine's and the scenario's diagnostics,
  /// the program's syntax errors, the reason it cannot start (each line ends in '\n').
  std::string messages;
  /// Why it cannot start in one line, for the headless runs (sweep, tune-delay); "" when loaded.
  std::string failure;
  /// An exception loading raised (a file that cannot be read): rethrown by the caller after it
  /// printed `messages`, as the command did before the runner existed.
  std::exception_ptr thrown;
  bool ok() const noexcept { return loaded != nullptr; }
};

/// Loads and validates everything `spec` names: program file, machine, scenario (with
/// --max-time, its [tech] times and V.E. values), syntax, the cycle against Kv, the conveyor
/// world (with spec.adjust and spec.wrap applied).
LoadResult load(const RunSpec& spec);

}  // namespace ncsim::runner
