#include "runner/load.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <variant>

#include "conveyor/world.hpp"
#include "core/diagnostic.hpp"
#include "core/number_text.hpp"
#include "grammar/check.hpp"
#include "machines/loader.hpp"
#include "program/program_source.hpp"
#include "runner/locate.hpp"

namespace ncsim::runner {
namespace {

namespace fs = std::filesystem;

// --max-time: the scenario's [stop] time, the earlier of both; without a scenario one that
// holds only this condition (its file name empty: printed as --max-time). Then the scenario's
// V.E. values and [tech] execution times over the machine's NCSIM-CHAN-650..653.
void apply_scenario(const ProgramSpec& spec, std::optional<scenario::Scenario>& s,
                    machines::Machine& machine, interp::Options& interp_options) {
  if (spec.max_time) {
    if (!s) s.emplace();
    if (!s->stop.time || *s->stop.time > *spec.max_time) s->stop.time = *spec.max_time;
  }
  if (!s) return;
  for (const scenario::VeInitial& v : s->ve)
    interp_options.external.emplace(v.name, v.value);
  machines::TechTable& tech = machine.channel.tech;
  for (const scenario::TechDuration& d : s->tech) {
    machines::TechFunction& f = d.kind == 'M'   ? tech.m[d.number]
                                : d.kind == 'H' ? tech.h[d.number]
                                : d.kind == 'S' ? tech.s
                                                : tech.t;
    f.duration = d.seconds;
  }
}

// The position controller needs Kv x T <= 1 (axes/control): a cycle too long for an axis's Kv
// is a usage error naming where the cycle came from, the axis and the longest cycle it takes,
// before the channel is built (issue 34: it failed there with Kv's message alone).
bool cycle_suits_kv(const machines::Machine& machine, double t,
                    const std::optional<std::uint64_t>& cycle_us, std::ostream& err) {
  using core::human;
  for (const std::uint8_t i : program::interpolated_axes(machine)) {
    const machines::AxisParams& a = machine.axes[i];
    if (a.control.kv * t <= 1.0) continue;
    err << "ncsim: error: "
        << (cycle_us ? "--cycle-us " + std::to_string(*cycle_us)
                     : std::string("the channel list's ncsim.cycle_time (NCSIM-CHAN-610) ") +
                           human(t * 1e6) + " us")
        << ": axis " << a.name << "'s Kv P-AXIS-00099 getriebe[0].kv = " << human(a.control.kv)
        << " 1/s takes a cycle of at most " << human(std::floor(1e6 / a.control.kv))
        << " us (Kv x cycle <= 1: the position controller's stability)\n";
    return false;
  }
  return true;
}

// The conveyor world of a machine with a conveyor axis (none otherwise); false and `why` when
// the machine's and scenario's conveyor do not make one.
bool make_world(Loaded& in, std::string& why) {
  in.port.reset();
  if (in.machine.conveyor_axis() == nullptr) return true;
  try {
    in.port = conveyor::make_port(in.machine, in.scenario ? &*in.scenario : nullptr, in.t_cycle);
  } catch (const std::invalid_argument& e) {
    why = e.what();
    return false;
  }
  return true;
}

// Program and machine, syntax-checked, with the world; the exit category on failure (the
// reason on `err`).
std::variant<std::unique_ptr<Loaded>, Exit> load_checked(const RunSpec& run, std::ostream& err) {
  const ProgramSpec& spec = run.program;
  if (!spec.external.empty()) {
    err << "ncsim: error: not supported: --ve with time / run (V.E. values come with the "
           "scenario)\n";
    return Exit::usage;
  }
  std::error_code ec;
  if (!fs::is_regular_file(spec.program, ec)) {
    err << "ncsim: error: no such file: '" << spec.program.string() << "'\n";
    return Exit::usage;
  }
  const std::optional<fs::path> dir = machine_folder(spec, err);
  if (!dir) return Exit::usage;
  machines::LoadResult machine = machines::load_machine(*dir);
  for (const core::Diagnostic& d : machine.diagnostics.items())
    err << core::format(d);
  if (!machine.machine) {
    err << "ncsim: error: machine '" << dir->string() << "' could not be loaded\n";
    return Exit::usage;
  }
  core::SourceFile file = core::SourceFile::load(spec.program);
  // Scenario (docs/scenario.md): its V.E. initial values answer the barriers; the channel
  // plays its V.E. writes, [stop], path and axis overrides and feed hold (overrides beyond the
  // machine's are refused by the loader: NC6102, NC6105).
  auto scenario = load_scenario_for(spec, file, *machine.machine, err);
  if (const Exit* status = std::get_if<Exit>(&scenario)) return *status;
  auto in = std::make_unique<Loaded>(Loaded{std::move(file),
                                            std::move(*machine.machine),
                                            program::kDefaultCycle,
                                            {},
                                            std::nullopt,
                                            nullptr});
  in->scenario = std::move(std::get<std::optional<scenario::Scenario>>(scenario));
  apply_cycle_options(spec, in->interp);
  in->interp.channels = std::vector<std::uint8_t>{1};  // a run alone is channel 1 (250008)
  apply_scenario(spec, in->scenario, in->machine, in->interp);
  const core::DiagnosticList syntax = grammar::check_program(in->file);
  for (const core::Diagnostic& d : syntax.items())
    err << core::format(d, in->file);
  if (syntax.error_count() > 0) return Exit::program_errors;
  // The channel list's NCSIM-CHAN-610 ncsim.cycle_time (default 1 ms), --cycle-us over it
  // (docs/ipo.md "The cycle time"); both whole microseconds, converted the same way.
  in->t_cycle =
      run.cycle_us ? static_cast<double>(*run.cycle_us) * 1e-6 : in->machine.channel.cycle_time;
  if (!cycle_suits_kv(in->machine, in->t_cycle, run.cycle_us, err)) return Exit::usage;
  std::string why;
  if (run.build_world && !make_world(*in, why)) {
    err << "ncsim: error: the conveyor of machine '" << dir->string() << "': " << why << '\n';
    return Exit::usage;
  }
  return in;
}

}  // namespace

LoadResult load(const RunSpec& spec) {
  LoadResult r;
  std::ostringstream err;
  try {
    auto loaded = load_checked(spec, err);
    r.messages = err.str();
    if (const Exit* status = std::get_if<Exit>(&loaded)) {
      r.exit = *status;
      r.failure = "the program, machine or scenario could not be loaded";
      return r;
    }
    r.loaded = std::move(std::get<std::unique_ptr<Loaded>>(loaded));
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    r.messages = err.str();
    r.exit = Exit::usage;
    r.thrown = std::current_exception();
    return r;
  }
  Loaded& in = *r.loaded;
  // sweep / tune-delay: the world changed after loading, then built again.
  if (spec.adjust) {
    spec.adjust(in.machine, in.scenario, in.t_cycle);
    std::string why;
    if (!make_world(in, why)) {
      r.loaded.reset();
      r.exit = Exit::usage;
      r.failure = "the conveyor: " + why;
      return r;
    }
  }
  if (spec.wrap && in.port) in.port = spec.wrap(std::move(in.port));
  if (spec.conv_vel) in.interp.conv_vel = spec.conv_vel;
  // Nothing else would end a program that runs endlessly on its own (docs/interp.md).
  in.interp.end_when_endless = !(in.scenario && in.scenario->stop.any());
  return r;
}

}  // namespace ncsim::runner
