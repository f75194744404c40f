#include "runner/locate.hpp"

#include <fstream>
#include <limits>
#include <ostream>
#include <system_error>

#include "core/diagnostic.hpp"
#include "interp/interpreter.hpp"
#include "machines/loader.hpp"
#include "scenario/loader.hpp"

namespace ncsim::runner {
namespace {

namespace fs = std::filesystem;

// Where the bundled machines are: the source tree this command was built from.
fs::path source_root() {
  return NCSIM_SOURCE_ROOT;
}

// `-` names standard input.
bool is_stdin(const fs::path& path) {
  return path == "-";
}

}  // namespace

void apply_cycle_options(const ProgramSpec& spec, interp::Options& interp) {
  interp.cycle_dirs = spec.cycle_dirs;
  interp.skip_missing_cycles = spec.missing_cycles == "skip";
}

fs::path bundled_machine(std::string_view name) {
  return machines::bundled_machine_dir(source_root(), name);
}

std::optional<fs::path> scenario_file(const ProgramSpec& spec) {
  if (spec.scenario) return *spec.scenario;
  if (!spec.scenario_lookup) return std::nullopt;
  const fs::path named = (is_stdin(spec.program) ? fs::path(".") : spec.program.parent_path()) /
                         scenario::kDefaultScenarioFile;
  std::error_code ec;
  if (fs::is_regular_file(named, ec)) return named;
  return std::nullopt;
}

std::variant<std::optional<scenario::Scenario>, Exit> load_scenario_for(
    const ProgramSpec& spec, const core::SourceFile& program, const machines::Machine& machine,
    std::ostream& err) {
  const std::optional<fs::path> path = scenario_file(spec);
  if (!path) return std::optional<scenario::Scenario>{};
  std::error_code ec;
  if (!fs::exists(*path, ec)) {
    err << "ncsim: error: no such scenario file: '" << path->string() << "'\n";
    return Exit::usage;
  }
  scenario::Context context;
  context.program = &program;
  context.conveyor_wired = true;  // run / time play the conveyor world (docs/conveyor.md)
  context.conveyor_axis = machine.conveyor_axis() != nullptr;  // NC7019
  // NC6102, NC6105 at their values: check refuses the overrides time / run cannot play.
  context.path_override_max =
      machine.channel.path_override_type == machines::PathOverrideType::reduced_above_100
          ? scenario::kOverrideMax
          : 1.0;
  context.axis_override_max = 1.0;  // 002 2.2: an INDP axis takes 0 .. 100 %
  // NC7020: an axis override of a path axis. The path axes as program::interpolated_axes has them
  // (check and trace do not link the interpolator): not a spindle, an encoder or the conveyor.
  context.path_axes.emplace();
  for (const machines::AxisParams& a : machine.axes) {
    if (a.kind != machines::AxisKind::spindle && !a.encoder_only && &a != machine.conveyor_axis())
      context.path_axes->push_back(a.name);
  }
  context.axes.emplace();
  for (const machines::AxisParams& axis : machine.axes)
    context.axes->push_back(axis.name);
  std::optional<core::SourceFile> file;
  try {
    // No pipe or device: refused before anything is read (docs/scenario.md).
    file.emplace(core::SourceFile::load_regular(*path, std::numeric_limits<std::size_t>::max()));
  } catch (const std::exception& e) {
    err << "ncsim: error: cannot read the scenario '" << path->string() << "': " << e.what()
        << '\n';
    return Exit::usage;
  }
  scenario::LoadResult loaded = scenario::parse_scenario(*file, context);
  for (const core::Diagnostic& d : loaded.diagnostics.items())
    err << core::format(d, *file);
  if (!loaded.scenario) {
    err << "ncsim: error: scenario '" << path->string() << "': " << loaded.diagnostics.error_count()
        << " error" << (loaded.diagnostics.error_count() == 1 ? "" : "s") << '\n';
    return Exit::usage;
  }
  return std::move(loaded.scenario);
}

std::optional<fs::path> machine_folder(const ProgramSpec& spec, std::ostream& err) {
  if (spec.machine_dir) return *spec.machine_dir;
  const fs::path named =
      (is_stdin(spec.program) ? fs::path(".") : spec.program.parent_path()) / "machine";
  std::string name(machines::kDefaultMachine);
  if (fs::is_regular_file(named)) {
    std::ifstream in(named);
    std::string line;
    std::getline(in, line);
    const auto first = line.find_first_not_of(" \t\r");
    const auto last = line.find_last_not_of(" \t\r");
    if (first == std::string::npos) {
      err << "ncsim: error: " << named.string() << " names no machine\n";
      return std::nullopt;
    }
    name = line.substr(first, last - first + 1);
  }
  return machines::bundled_machine_dir(source_root(), name);
}

}  // namespace ncsim::runner
