// cli/sweep_command: `ncsim sweep` (see the header).

#include "cli/sweep_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "cli/line_world.hpp"
#include "cli/number_format.hpp"
#include "cli/run_commands.hpp"
#include "runner/line.hpp"

namespace ncsim::cli {
namespace {

std::optional<double> parse_number(std::string_view s) {
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

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

// Every velocity of `vs` evaluated, at most `jobs` at a time; results in the order of `vs`.
std::vector<Candidate> evaluate_all(const SweepOptions& o, const std::vector<double>& vs,
                                    unsigned jobs) {
  std::vector<Candidate> out(vs.size());
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < vs.size(); i = next++)
      out[i] = evaluate(o, vs[i]);
  };
  const unsigned n = std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(vs.size())));
  std::vector<std::thread> threads;
  for (unsigned k = 1; k < n; ++k)
    threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads)
    t.join();
  return out;
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

}  // namespace

int run_sweep(const SweepOptions& o, std::ostream& out, std::ostream& err) {
  const std::string& r = o.belt_velocity;
  const auto colon = r.find(':');
  const std::optional<double> lo = colon == std::string::npos
                                       ? std::nullopt
                                       : parse_number(std::string_view(r).substr(0, colon));
  const std::optional<double> hi = colon == std::string::npos
                                       ? std::nullopt
                                       : parse_number(std::string_view(r).substr(colon + 1));
  if (!lo || !hi || *lo < 0.0 || !(*lo < *hi)) {
    err << "ncsim: error: sweep: --belt-velocity '" << r
        << "' must be LO:HI in mm/s with 0 <= LO < HI [" << kSweepRangeId << "]\n";
    return kExitUsage;
  }
  if (!(o.tolerance >= kSweepToleranceMin) || !std::isfinite(o.tolerance)) {
    err << "ncsim: error: sweep: --tolerance " << human(o.tolerance)
        << " mm/s must be a number >= " << human(kSweepToleranceMin) << " mm/s ["
        << kSweepToleranceId << "]\n";
    return kExitUsage;
  }
  const unsigned grid = std::max(1u, o.grid);
  const unsigned jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  // Round 0: both ends (also tells whether the machine can be swept at all).
  std::vector<Candidate> ends = evaluate_all(o, {*lo, *hi}, jobs);
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
  out << (o.conv_vel == "follow"
              ? "sweep: every #SYNC IN's CONV_VEL is the candidate (--conv-vel follow)\n"
              : "sweep: the program's CONV_VEL is kept (--conv-vel keep)\n");
  for (const Candidate& c : ends)
    print(c, 0, out);
  if (!ends[0].ok()) {
    out << "sweep: no belt velocity in " << human(*lo) << " .. " << human(*hi)
        << " mm/s runs through (the lowest fails)\n";
    return kExitProgramErrors;
  }
  Candidate best = ends[0];
  double fail = *hi;
  if (ends[1].ok()) {
    best = ends[1];
    fail = std::numeric_limits<double>::infinity();
  }
  unsigned round = 0;
  while (std::isfinite(fail) && fail - best.v > o.tolerance) {
    ++round;
    std::vector<double> vs;
    for (unsigned i = 1; i <= grid; ++i) {
      const double v = best.v + (fail - best.v) * i / (grid + 1);
      if (v > best.v && v < fail && (vs.empty() || v > vs.back())) vs.push_back(v);
    }
    // No double lies between the two any more (huge velocities): the interval cannot shrink,
    // so the sweep ends rather than trying the same candidates again (issue 34 item 6).
    if (vs.empty()) break;
    std::vector<Candidate> cs = evaluate_all(o, vs, jobs);
    for (const Candidate& c : cs)
      print(c, round, out);
    // The lowest failure bounds the interval; the highest pass below it is the new best.
    std::size_t k = cs.size();
    for (std::size_t i = 0; i < cs.size() && k == cs.size(); ++i)
      if (!cs[i].ok()) k = i;
    if (k < cs.size()) fail = cs[k].v;
    for (std::size_t i = 0; i < k; ++i)
      best = cs[i];
  }
  out << "sweep: highest belt velocity " << human(best.v) << " mm/s (" << human(best.v * 0.06)
      << " m/min)";
  if (std::isfinite(fail)) {
    out << ", " << human(fail) << " mm/s fails (tolerance " << human(o.tolerance) << " mm/s)";
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
