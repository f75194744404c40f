#pragma once
// scenario/loader: reads and validates a scenario TOML file (docs/scenario.md) into a
// Scenario.
//
// Inputs: the file (path or text with its name) and, optionally, what the file is checked
// against: the program's line count and the machine's axis names. Outputs: LoadResult with the
// Scenario when there are no errors, and every diagnostic found: a TOML syntax error (toml++
// stops at the first one, NC7001), then every unknown key (with "did you mean"), wrong type,
// out-of-range value, bad combination and out-of-order event of the whole file, each naming
// file, line, column and the key (`event[2].override`). Ids NC7001..NC7099
// (docs/diagnostics.md). Never throws for bad input.
// Invariants: a returned Scenario satisfies the invariants listed in scenario.hpp.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::scenario {

/// What a scenario is checked against besides its own rules (all optional).
struct Context {
  /// The main program: `line` keys beyond its last line are NC7012 (its lines are counted
  /// only when the scenario names a line).
  const core::SourceFile* program = nullptr;
  std::optional<std::vector<std::string>> axes;  ///< the machine's axis names (NC7011)
  /// True once the channel loop plays the conveyor world: until then `[conveyor]` and the
  /// event key `reduced_filter` are validated and then refused as not supported (NC7007).
  bool conveyor_wired = false;
  /// Whether the machine has a conveyor axis (the CLI sets it): when false, a `[conveyor]`
  /// table is warning NC7019 at its header and is not played; unset, not checked.
  std::optional<bool> conveyor_axis;
  /// Largest path override the machine's override type accepts (NCSIM-CHAN-630; fraction):
  /// an `override` above it is NC6102 at its value, so `check` refuses what `time` would.
  std::optional<double> path_override_max;
  /// Largest axis override of an INDP axis (002 2.2: 1.0, 100 %): above it NC6105 at its value.
  std::optional<double> axis_override_max;
  /// The machine's path (interpolated) axes: an `axis_override` of one is warning NC7020 (it
  /// acts on the axis's INDP motions only, never on the path's blocks).
  std::optional<std::vector<std::string>> path_axes;
};

struct LoadResult {
  std::optional<Scenario> scenario;  ///< set when diagnostics has no errors
  core::DiagnosticList diagnostics;  ///< every error and warning of the file
};

/// Name of the scenario file a program folder may hold (used by default).
inline constexpr const char* kDefaultScenarioFile = "scenario.toml";

/// Largest scenario file (the parsed tree is held in memory): 16 MiB, NC7010 beyond.
inline constexpr std::size_t kMaxScenarioBytes = std::size_t{16} << 20;

/// Validates `file` (its name is the one diagnostics show).
LoadResult parse_scenario(const core::SourceFile& file, const Context& context = {});

/// Loads and validates the file at `path`; a file that cannot be read is NC7010.
LoadResult load_scenario(const std::filesystem::path& path, const Context& context = {});

}  // namespace ncsim::scenario
