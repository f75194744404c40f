#pragma once
// runner/locate: where a program's machine and scenario are, and the scenario loaded against
// them (design.md §5, docs/scenario.md). Shared by every program-reading command: check and
// trace call these directly, runner::load for the runs.
//
// Inputs: a ProgramSpec. Outputs: a folder, a file, a validated scenario; problems as text on
// `err` (positioned diagnostics with their source lines) and the exit status Exit::usage.

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string_view>
#include <variant>

#include "core/source_file.hpp"
#include "machines/machine.hpp"
#include "runner/spec.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::interp {
struct Options;
}

namespace ncsim::runner {

/// The interpreter options `--cycles` and `--missing-cycles` give (interp::Options).
void apply_cycle_options(const ProgramSpec& spec, interp::Options& interp);

/// The machine folder a program runs on (design.md §5): --machine, else the bundled machine
/// named in the program folder's `machine` file, else the default bundled machine; nothing
/// (reported on `err`) when that file names none.
std::optional<std::filesystem::path> machine_folder(const ProgramSpec& spec, std::ostream& err);

/// The scenario file a program runs under (docs/scenario.md): --scenario, else the program
/// folder's `scenario.toml` (the current folder's for `-`) when it exists, else none.
std::optional<std::filesystem::path> scenario_file(const ProgramSpec& spec);
/// The folder of bundled machine `name` in the source tree this command was built from.
std::filesystem::path bundled_machine(std::string_view name);

/// Loads and validates the scenario of `spec` (scenario_file) against `program`'s lines and
/// `machine`'s axis names. No scenario: nullopt. A missing --scenario file or any error in it:
/// every diagnostic written on `err` (with its source line) and Exit::usage.
std::variant<std::optional<scenario::Scenario>, Exit> load_scenario_for(
    const ProgramSpec& spec, const core::SourceFile& program, const machines::Machine& machine,
    std::ostream& err);

}  // namespace ncsim::runner
