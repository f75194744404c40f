// cli/tune_delay: `ncsim tune-delay` (see the header).

#include "cli/tune_delay.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <ostream>
#include <string>

#include "cli/number_format.hpp"
#include "cli/run_commands.hpp"
#include "program/program_source.hpp"
#include "runner/line.hpp"
#include "tracking/synchro_lag.hpp"

namespace ncsim::cli {
namespace {

machines::ConveyorAxisParams* conveyor_params(machines::Machine& m) {
  for (machines::AxisParams& a : m.axes)
    if (a.conveyor) return &*a.conveyor;
  return nullptr;
}

// One synchronised cycle's contour error on the real workpiece (ContourStats); c2, p2 the sums
// of squares. Under #TRAFO ON the axes are joints: the commanded TCP (Channel::tcp(), the PCS1
// offset included) against the forward transform of the joints' actual positions, as
// synchro_lag there (tracking::cycle_lag); a cycle whose actual joints do not map is left out.
void contour_cycle(const channel::Channel& ch, const tracking::ConveyorSync& sync,
                   ContourStats& out, double& c2, double& p2) {
  const ipo::Cycle& c = ch.cycle();
  if (c.activity != ipo::Activity::motion || c.rapid || !(c.path.v > 0.0)) return;
  planner::AxisVec x_actual{};   // [mm] the axes' actual positions, or the actual TCP
  planner::AxisVec x_command{};  // [mm] the axes' setpoints, or the commanded TCP
  const std::size_t axis_count = ch.axis_count();
  for (std::size_t i = 0; i < axis_count; ++i) {
    x_actual[i] = ch.axes().actual[i];
    x_command[i] = ch.transformed() ? ch.tcp()[i].p : ch.setpoints()[i].p;
  }
  if (ch.transformed()) {
    const planner::AxisVec q = x_actual;
    if (!ch.forward() || !ch.forward()(q, x_actual)) return;
  }
  Eigen::Vector3d actual = Eigen::Vector3d::Zero();
  Eigen::Vector3d command = Eigen::Vector3d::Zero();
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();  // the path's direction (T0 applied)
  for (std::size_t i = 0; i < axis_count; ++i) {
    if (const int k = sync.xyz(i); k >= 0) {
      actual[k] = x_actual[i];
      command[k] = x_command[i];
      tangent[k] = c.v[i];
    }
  }
  // The commanded PCS1 point, and the actual point on the real workpiece, in PCS1.
  const Eigen::Vector3d pcs1 = sync.frame().to_pcs1(command, sync.travel());
  const Eigen::Vector3d on_workpiece = sync.frame().to_pcs1(actual, tracking::real_travel(sync));
  const Eigen::Vector3d e = on_workpiece - pcs1;
  Eigen::Vector3d normal = e;
  if (const double n = tangent.norm(); n > 0.0) {
    const Eigen::Vector3d t = sync.frame().t0().rotation.transpose() * (tangent / n);
    normal = e - e.dot(t) * t;
  }
  const double ce = normal.norm(), pe = e.norm();
  ++out.cycles;
  c2 += ce * ce;
  p2 += pe * pe;
  out.contour_max = std::max(out.contour_max, ce);
  out.position_max = std::max(out.position_max, pe);
}

struct Pass {
  runner::LineOutcome outcome;
  LagStats lag;
  ContourStats contour;
  bool conveyor = false;
  double delay = 0.0;         ///< [s] the P-AXIS-00626 the run used
  double dead_time = 0.0;     ///< [s] the scenario's
  double filter_delay = 0.0;  ///< [s] the position filter's (n - 1) T / 2
};

// One run with P-AXIS-00626 = `delay` (nullopt: the machine's).
Pass pass(const TuneDelayOptions& o, std::optional<double> delay, std::ostream& err) {
  Pass p;
  double sum = 0.0, sum2 = 0.0, v_sum = 0.0, c2 = 0.0, p2 = 0.0;
  runner::RunSpec run = line_spec(o.program, o.cycle_us);
  run.audit = false;
  run.adjust = [&](machines::Machine& m, std::optional<scenario::Scenario>& s, double t) {
    machines::ConveyorAxisParams* c = conveyor_params(m);
    p.conveyor = c != nullptr && m.channel.conveyor.has_value();
    if (c == nullptr) return;
    if (delay) c->delay_time = *delay;
    p.delay = c->delay_time;
    if (c->enable_filter && c->order_pos_filter > 1)
      p.filter_delay = (c->order_pos_filter - 1) * t / 2.0;
    if (s && s->conveyor) p.dead_time = s->conveyor->dead_time;
  };
  const auto on_cycle = [&](const channel::Channel& ch) {
    const tracking::ConveyorSync* sync = ch.conveyor_sync();
    if (sync == nullptr || sync->phase() != tracking::SyncPhase::tracking || !sync->synchronised())
      return;
    contour_cycle(ch, *sync, p.contour, c2, p2);
    const tracking::MasterDisplay d = ch.master_display();
    if (d.v_master_comp == 0.0) return;  // a standing belt tells nothing about the delay
    const double lag = d.synchro_lag;    // under #TRAFO ON the TCP's (tracking::cycle_lag)
    LagStats& l = p.lag;
    l.min = l.cycles == 0 ? lag : std::min(l.min, lag);
    l.max = l.cycles == 0 ? lag : std::max(l.max, lag);
    ++l.cycles;
    sum += lag;
    sum2 += lag * lag;
    v_sum += d.v_master_comp;
  };
  p.outcome = runner::run_line(run, on_cycle, err);
  if (p.lag.cycles > 0) {
    const double n = static_cast<double>(p.lag.cycles);
    p.lag.mean = sum / n;
    p.lag.rms = std::sqrt(sum2 / n);
    p.lag.v_mean = v_sum / n;
  }
  if (p.contour.cycles > 0) {
    const double n = static_cast<double>(p.contour.cycles);
    p.contour.contour_rms = std::sqrt(c2 / n);
    p.contour.position_rms = std::sqrt(p2 / n);
  }
  return p;
}

void print(const Pass& p, const char* what, bool contour, std::ostream& out) {
  out << "tune-delay: " << what << " P-AXIS-00626 = " << human(std::round(p.delay * 1e6))
      << " us: synchro_lag mean " << human(p.lag.mean) << " mm (static part), min "
      << human(p.lag.min) << ", max " << human(p.lag.max) << ", rms " << human(p.lag.rms)
      << " mm over " << p.lag.cycles << " synchronised cycles at a mean belt velocity of "
      << human(p.lag.v_mean) << " mm/s\n";
  if (contour)
    out << "tune-delay: " << what << " P-AXIS-00626 = " << human(std::round(p.delay * 1e6))
        << " us: contour error on the real workpiece rms " << human(p.contour.contour_rms)
        << " mm, max " << human(p.contour.contour_max) << " mm; position error rms "
        << human(p.contour.position_rms) << " mm, max " << human(p.contour.position_max)
        << " mm over " << p.contour.cycles << " synchronised feed cycles\n";
}

}  // namespace

int run_tune_delay(const TuneDelayOptions& o, std::ostream& out, std::ostream& err) {
  const Pass first = pass(o, std::nullopt, err);
  if (first.outcome.status == runner::Exit::usage) return kExitUsage;
  if (!first.conveyor) {
    err << "ncsim: error: tune-delay: the machine has no conveyor axis with conveyor tracking "
           "(FCT_DLM and conv_sync.is_master) ["
        << kTuneNoConveyorId << "]\n";
    return kExitUsage;
  }
  if (first.outcome.status == runner::Exit::program_errors && first.lag.cycles == 0) {
    err << first.outcome.error << '\n';
    return kExitProgramErrors;
  }
  if (first.lag.cycles == 0 || first.lag.v_mean == 0.0) {
    err << "ncsim: error: tune-delay: the program never ran synchronised with a moving belt: no "
           "synchro_lag to tune on (the scenario must move the belt and bring a workpiece) ["
        << kTuneNoLagId << "]\n";
    return kExitProgramErrors;
  }
  // A run that stops (the laser listing as printed leaves the workspace on its 20th pass) still
  // tells the lag of the cycles it ran synchronised: said, and used.
  if (first.outcome.status == runner::Exit::program_errors)
    out << "tune-delay: note: the run stopped: " << first.outcome.error
        << "; the statistics are of the cycles before\n";
  print(first, "with the machine's", o.contour, out);
  const double proposed =
      std::max(0.0, std::round((first.delay - first.lag.mean / first.lag.v_mean) * 1e6)) * 1e-6;
  const Pass check = pass(o, proposed, err);
  if (check.outcome.status == runner::Exit::usage || check.lag.cycles == 0) {
    err << check.outcome.error << '\n';
    return kExitProgramErrors;
  }
  out << "tune-delay: proposed P-AXIS-00626 conv_sync.delay_time = " << human(proposed * 1e6)
      << " us (the mean synchro_lag / the mean belt velocity, rounded to 1 us)\n";
  // A program that sets the delay time itself overrides the list's value from that line on:
  // both runs then track with the program's value there, and the check cannot show the
  // proposal's effect (issue 34 item 21).
  if (const auto lines = runner::machine_data_lines(o.program, "P-AXIS-00626"); !lines.empty()) {
    out << "tune-delay: note: the program sets P-AXIS-00626 itself (#MACHINE DATA at line";
    for (std::size_t i = 0; i < lines.size(); ++i)
      out << (i == 0 ? " " : ", ") << lines[i];
    out << "): from there on both runs use the program's value, so the statistics mix it with "
           "the list's and the check shows the proposal only before that line; tune with a "
           "program that leaves P-AXIS-00626 to the list\n";
  }
  print(check, "check with", o.contour, out);
  out << "tune-delay: for reference: the scenario's dead time " << human(first.dead_time * 1e6)
      << " us + the position filter's delay " << human(first.filter_delay * 1e6)
      << " us = " << human((first.dead_time + first.filter_delay) * 1e6) << " us\n";
  return kExitOk;
}

TuneDelayCommand::TuneDelayCommand(CLI::App& app) {
  cmd_ = app.add_subcommand("tune-delay",
                            "Propose the delay time P-AXIS-00626 that zeroes the mean synchro_lag "
                            "(docs/conveyor.md \"Tuning the delay time offline\")");
  add_run_program_options(*cmd_, options_.program);
  add_cycle_us_option(*cmd_, options_.cycle_us);
  cmd_->add_flag("--contour", options_.contour,
                 "Also the contour error on the real workpiece (rms, max) of each run");
}

std::optional<int> TuneDelayCommand::dispatch(std::ostream& out, std::ostream& err) const {
  if (!cmd_->parsed()) return std::nullopt;
  return run_tune_delay(options_, out, err);
}

}  // namespace ncsim::cli
