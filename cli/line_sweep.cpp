// cli/line_sweep: `ncsim line sweep` (see the header).

#include "cli/line_sweep.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/line_report.hpp"
#include "cli/line_world.hpp"
#include "cli/number_format.hpp"
#include "cli/run_commands.hpp"
#include "cli/sweep_command.hpp"
#include "cli/sweep_search.hpp"
#include "runner/line.hpp"
#include "runner/line_run.hpp"
#include "runner/texts.hpp"

namespace ncsim::cli {
namespace {

// One line run at one belt velocity.
struct LineCandidate {
  double v = 0.0;                        ///< [mm/s]
  runner::Exit load = runner::Exit::ok;  ///< the line's load (usage: it cannot run)
  std::string load_errors;               ///< what loading printed
  bool belt = false;                     ///< the line has a belt
  bool encoder_zero = false;             ///< an encoder belt standing at t = 0
  std::vector<std::string> reasons;      ///< why it fails; empty: it runs clean
  std::string figures;                   ///< what it achieved (taken, per minute, utilisation)
  bool ok() const { return load == runner::Exit::ok && reasons.empty(); }
};

std::string channel_label(const scenario::LineChannel& c) {
  return "channel " + std::to_string(c.number) +
         (c.name == "channel " + std::to_string(c.number) ? "" : " (" + c.name + ")");
}

// Why the run of `line` is not clean: missed workpieces, channel errors, audit violations.
std::vector<std::string> reasons(const runner::LineRun& line) {
  std::vector<std::string> why;
  if (const conveyor::LineWorld* b = line.belt(); b != nullptr) {
    if (b->missed() > 0) {
      std::string r =
          std::to_string(b->missed()) + " workpiece" + (b->missed() == 1 ? "" : "s") + " missed";
      for (const conveyor::WorkpieceFate& f : b->fates()) {
        if (f.fate != conveyor::Fate::missed) continue;
        r += " (the first: workpiece " + std::to_string(f.workpiece) + ", past the belt's end at " +
             human(f.t) + " s)";
        break;
      }
      why.push_back(r);
    }
    if (b->on_belt() > 0)
      why.push_back(std::to_string(b->on_belt()) + " workpiece" + (b->on_belt() == 1 ? "" : "s") +
                    " left on the belt at the end");
  }
  for (std::size_t k = 0; k < line.size(); ++k) {
    const runner::Run& run = line.channel(k);
    const runner::Ending end = run.ending(line.status(k));
    const std::string who = channel_label(line.channel_spec(k));
    if (end.failed) {
      const std::string id = runner::error_id(run);
      why.push_back(who + (id.empty() ? "" : " [" + id + "]") + ": " +
                    runner::first_line(end.error_text));
    }
    if (const audit::Audit* a = run.audit(); a != nullptr && !a->verdict().ok())
      why.push_back(who + " " + runner::first_violation(run) + " (" +
                    std::to_string(a->verdict().violation_count) + " violation" +
                    (a->verdict().violation_count == 1 ? "" : "s") + ")");
  }
  return why;
}

// What the run achieved: the workpieces taken, per minute, each channel's utilisation.
std::string figures(const runner::LineRun& line) {
  std::string s;
  if (const conveyor::LineWorld* b = line.belt(); b != nullptr)
    s = std::to_string(b->taken_total()) + " of " + std::to_string(b->arrived()) +
        " workpieces taken, " +
        human(std::round(line_per_minute(b->taken_total(), line.t_end()) * 100.0) / 100.0) +
        " per minute; ";
  s += "end " + human(line.t_end()) + " s";
  for (std::size_t k = 0; k < line.size(); ++k)
    s += ", " + channel_label(line.channel_spec(k)) + " " + human(line_utilisation(line, k)) + " %";
  return s;
}

LineCandidate evaluate(const LineOptions& o, double v) {
  LineCandidate c;
  c.v = v;
  runner::LineSpec spec;
  spec.file = o.file;
  spec.cycle_us = o.cycle_us;
  spec.max_time = o.max_time;
  spec.audit = true;
  spec.adjust_conveyor = [&](scenario::Conveyor& conveyor) {
    if (conveyor.mode == scenario::ConveyorMode::encoder)
      c.encoder_zero = !scale_encoder_belt(conveyor, v);
  };
  spec.wrap = [v](std::unique_ptr<conveyor::Port> port) {
    return override_belt(std::move(port), v);
  };
  if (o.conv_vel == "follow") spec.conv_vel = v;
  runner::LineLoadResult loaded = runner::load_line_run(spec);
  c.load_errors = loaded.messages;
  if (!loaded.ok()) {
    c.load = loaded.exit;
    return c;
  }
  runner::LineRun& line = *loaded.line;
  c.belt = line.belt() != nullptr;
  if (!c.belt || c.encoder_zero) return c;  // nothing to sweep: reported by the caller
  line.start();
  line.run();
  c.reasons = reasons(line);
  c.figures = figures(line);
  return c;
}

std::string joined(const std::vector<std::string>& reasons) {
  std::string s;
  for (const std::string& r : reasons)
    s += (s.empty() ? "" : "; ") + r;
  return s;
}

void print(const LineCandidate& c, unsigned round, std::ostream& out) {
  out << "round " << round << ": " << human(c.v) << " mm/s (" << human(c.v * 0.06) << " m/min): ";
  if (c.ok()) {
    out << "ok, " << c.figures << '\n';
  } else if (c.load != runner::Exit::ok) {
    out << "fails: the line does not load\n";
  } else {
    out << "fails: " << joined(c.reasons) << '\n';
  }
}

// Round 0: whether the line can be swept at all (the exit status, reported, when not).
std::optional<int> sweepable(const std::vector<LineCandidate>& ends, std::ostream& err) {
  for (const LineCandidate& c : ends) {
    if (c.load != runner::Exit::ok) {
      err << c.load_errors;
      return c.load == runner::Exit::usage ? kExitUsage : kExitProgramErrors;
    }
  }
  if (!ends[0].belt) {
    err << "ncsim: error: line sweep: the line has no belt (a [conveyor] on a channel's machine "
           "with a conveyor axis): no belt velocity to sweep ["
        << kSweepNoConveyorId << "]\n";
    return kExitUsage;
  }
  if (ends[0].encoder_zero) {
    err << "ncsim: error: line sweep: the line's encoder belt has velocity 0 at t = 0: no "
           "velocity to scale (give [conveyor] velocity > 0) ["
        << kSweepEncoderZeroId << "]\n";
    return kExitUsage;
  }
  return std::nullopt;
}

}  // namespace

int run_line_sweep(const LineOptions& o, std::ostream& out, std::ostream& err) {
  if (o.belt_velocity.empty()) {
    err << "ncsim: error: line sweep needs --belt-velocity LO:HI [" << kSweepRangeId << "]\n";
    return kExitUsage;
  }
  const std::optional<SweepRange> range =
      parse_sweep_range(o.belt_velocity, o.tolerance, o.grid, "line sweep", err);
  if (!range) return kExitUsage;
  std::vector<LineCandidate> all;
  int status = kExitOk;
  const SweepBounds b = sweep_search(
      *range,
      [&](unsigned round, const std::vector<double>& vs) -> std::optional<std::vector<bool>> {
        std::vector<LineCandidate> cs =
            evaluate_all<LineCandidate>(vs, o.jobs, [&](double v) { return evaluate(o, v); });
        if (round == 0) {
          if (const auto s = sweepable(cs, err)) {
            status = *s;
            return std::nullopt;
          }
          err << cs[0].load_errors;  // the line's warnings, once
          out << (o.conv_vel == "follow"
                      ? "line sweep: every channel's #SYNC IN CONV_VEL is the candidate "
                        "(--conv-vel "
                        "follow)\n"
                      : "line sweep: the programs' CONV_VEL is kept (--conv-vel keep)\n");
        }
        std::vector<bool> passed;
        for (LineCandidate& c : cs) {
          print(c, round, out);
          passed.push_back(c.ok());
          all.push_back(std::move(c));
        }
        return passed;
      });
  if (b.stopped) return status;
  const auto at = [&](double v) {
    return *std::find_if(all.begin(), all.end(), [&](const LineCandidate& c) { return c.v == v; });
  };
  if (b.none) {
    out << "line sweep: no belt velocity in " << human(range->lo) << " .. " << human(range->hi)
        << " mm/s runs the line clean; at " << human(range->lo)
        << " mm/s: " << joined(at(range->lo).reasons) << '\n';
    return kExitProgramErrors;
  }
  const LineCandidate best = at(b.best);
  out << "line sweep: highest belt velocity " << human(best.v) << " mm/s (" << human(best.v * 0.06)
      << " m/min)";
  if (std::isfinite(b.fail)) {
    out << ", " << human(b.fail) << " mm/s fails (tolerance " << human(o.tolerance) << " mm/s)";
  } else {
    out << " = HI: the limit is above the range";
  }
  out << "\nline sweep: at " << human(best.v) << " mm/s: " << best.figures << '\n';
  if (std::isfinite(b.fail)) {
    out << "line sweep: binding constraint at " << human(b.fail)
        << " mm/s: " << joined(at(b.fail).reasons) << '\n';
  } else {
    out << "line sweep: no constraint binds up to " << human(range->hi) << " mm/s\n";
  }
  return kExitOk;
}

void add_line_sweep_options(CLI::App& cmd, LineOptions& o) {
  cmd.add_option("--belt-velocity", o.belt_velocity, "sweep: LO:HI belt velocities [mm/s]");
  cmd.add_option("--conv-vel", o.conv_vel,
                 "sweep: follow: every #SYNC IN's CONV_VEL is the candidate (default); keep: "
                 "the programs'")
      ->check(CLI::IsMember({"follow", "keep"}));
  cmd.add_option("--tolerance", o.tolerance, "sweep: resolution of the result [mm/s] (default 1)");
  cmd.add_option("--grid", o.grid, "sweep: candidates per round (default 3)")
      ->check(CLI::Range(1u, 64u));
  cmd.add_option("--jobs", o.jobs, "sweep: threads (default: the cores)")
      ->check(CLI::Range(1u, 256u));
}

}  // namespace ncsim::cli
