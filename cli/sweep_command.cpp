// cli/sweep_command: `ncsim sweep` (see the header).

#include "cli/sweep_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>
#include <utility>
#include <vector>

#include "cli/line_world.hpp"
#include "cli/number_format.hpp"
#include "cli/run_commands.hpp"
#include "runner/line.hpp"

namespace ncsim::cli {
namespace {

struct Candidate {
  double v = 0.0;  ///< [mm/s]
  runner::LineOutcome outcome;
  std::string load_errors;  ///< what loading printed (configuration errors)
  WorkspaceMargin margin;
  BeltSetting belt;  ///< how the velocity was applied
  bool ok() const { return outcome.status == runner::Exit::ok; }
};

// One candidate: the program at belt velocity `v`, with the workspace margin watched.
Candidate evaluate(const SweepOptions& o, double v) {
  Candidate c;
  c.v = v;
  std::ostringstream err;
  WorkspaceWatch watch;
  runner::RunSpec run = line_spec(o.program, o.cycle_us);
  run.adjust = [&](machines::Machine& m, std::optional<scenario::Scenario>& s, double) {
    c.belt = set_belt_velocity(m, s, v);
    watch.configure(m);
  };
  run.wrap = [&](std::unique_ptr<conveyor::Port> port) {
    return override_belt(std::move(port), v);
  };
  if (o.conv_vel == "follow") run.conv_vel = v;
  c.outcome = runner::run_line(
      run, [&](const channel::Channel& ch) { watch.on_cycle(ch); }, err);
  c.load_errors = err.str();
  c.margin = watch.margin();
  return c;
}

void print(const Candidate& c, unsigned round, std::ostream& out) {
  out << "round " << round << ": " << human(c.v) << " mm/s (" << human(c.v * 0.06) << " m/min): ";
  if (c.ok()) {
    out << "ok";
    if (c.margin.valid) out << ", workspace margin " << human(c.margin.distance) << " mm";
  } else {
    out << "fails";
    if (!c.outcome.id.empty()) out << " [" << c.outcome.id << "]";
    out << ": " << c.outcome.error;
  }
  out << '\n';
}

// Round 0's candidates: whether the machine and world can be swept at all (the exit status,
// reported on `err`, when not).
std::optional<int> sweepable(const std::vector<Candidate>& ends, std::ostream& err) {
  for (const Candidate& c : ends) {
    if (c.outcome.status == runner::Exit::usage) {
      err << c.load_errors;
      if (!c.outcome.error.empty()) err << "ncsim: error: sweep: " << c.outcome.error << '\n';
      return kExitUsage;
    }
  }
  if (!ends[0].belt.conveyor) {
    err << "ncsim: error: sweep: the machine has no conveyor axis with conveyor tracking (FCT_DLM "
           "and conv_sync.is_master): no belt velocity to sweep ["
        << kSweepNoConveyorId << "]\n";
    return kExitUsage;
  }
  if (ends[0].belt.encoder_zero) {
    err << "ncsim: error: sweep: the scenario's encoder belt has velocity 0 at t = 0: no velocity "
           "to scale (give [conveyor] velocity > 0) ["
        << kSweepEncoderZeroId << "]\n";
    return kExitUsage;
  }
  return std::nullopt;
}

}  // namespace

int run_sweep(const SweepOptions& o, std::ostream& out, std::ostream& err) {
  const std::optional<SweepRange> range =
      parse_sweep_range(o.belt_velocity, o.tolerance, o.grid, "sweep", err);
  if (!range) return kExitUsage;
  std::vector<Candidate> all;  // every candidate run, for the result's margin
  int status = kExitOk;
  const SweepBounds b = sweep_search(
      *range,
      [&](unsigned round, const std::vector<double>& vs) -> std::optional<std::vector<bool>> {
        std::vector<Candidate> cs =
            evaluate_all<Candidate>(vs, o.jobs, [&](double v) { return evaluate(o, v); });
        if (round == 0) {
          if (const auto s = sweepable(cs, err)) {
            status = *s;
            return std::nullopt;
          }
          out << (o.conv_vel == "follow"
                      ? "sweep: every #SYNC IN's CONV_VEL is the candidate (--conv-vel follow)\n"
                      : "sweep: the program's CONV_VEL is kept (--conv-vel keep)\n");
        }
        std::vector<bool> passed;
        for (Candidate& c : cs) {
          print(c, round, out);
          passed.push_back(c.ok());
          all.push_back(std::move(c));
        }
        return passed;
      });
  if (b.stopped) return status;
  if (b.none) {
    out << "sweep: no belt velocity in " << human(range->lo) << " .. " << human(range->hi)
        << " mm/s runs through (the lowest fails)\n";
    return kExitProgramErrors;
  }
  const Candidate& best =
      *std::find_if(all.begin(), all.end(), [&](const Candidate& c) { return c.v == b.best; });
  out << "sweep: highest belt velocity " << human(best.v) << " mm/s (" << human(best.v * 0.06)
      << " m/min)";
  if (std::isfinite(b.fail)) {
    out << ", " << human(b.fail) << " mm/s fails (tolerance " << human(o.tolerance) << " mm/s)";
  } else {
    out << " = HI: the limit is above the range";
  }
  out << '\n';
  if (best.margin.valid) {
    out << "sweep: margin to the workspace's conveying face at " << human(best.v)
        << " mm/s: " << human(best.margin.distance) << " mm (t=" << human(best.margin.t)
        << " s, line " << best.margin.line << ")\n";
  } else {
    out << "sweep: the program never synchronised at " << human(best.v)
        << " mm/s: no workspace margin\n";
  }
  return kExitOk;
}

SweepCommand::SweepCommand(CLI::App& app) {
  cmd_ = app.add_subcommand("sweep",
                            "Highest belt velocity at which a conveyor program runs through "
                            "(docs/conveyor.md \"The line's limits offline\")");
  add_run_program_options(*cmd_, options_.program);
  cmd_->add_option("--belt-velocity", options_.belt_velocity, "LO:HI belt velocities [mm/s]")
      ->required();
  cmd_->add_option("--conv-vel", options_.conv_vel,
                   "follow: every #SYNC IN's CONV_VEL is the candidate (default); keep: the "
                   "program's")
      ->check(CLI::IsMember({"follow", "keep"}));
  cmd_->add_option("--tolerance", options_.tolerance,
                   "Resolution of the result [mm/s] (default 1)");
  cmd_->add_option("--grid", options_.grid, "Candidates per round (default 3)")
      ->check(CLI::Range(1u, 64u));
  cmd_->add_option("--jobs", options_.jobs, "Threads (default: the cores)")
      ->check(CLI::Range(1u, 256u));
  add_cycle_us_option(*cmd_, options_.cycle_us);
}

std::optional<int> SweepCommand::dispatch(std::ostream& out, std::ostream& err) const {
  if (!cmd_->parsed()) return std::nullopt;
  return run_sweep(options_, out, err);
}

}  // namespace ncsim::cli
