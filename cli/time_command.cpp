// `ncsim time` (cli/run_commands.hpp): the run from runner/, the machining time printed as text
// or JSON, with --blocks one record per block, on a conveyor the time per workpiece.

#include <array>
#include <cstdio>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "cli/audit_print.hpp"
#include "cli/json_text.hpp"
#include "cli/number_format.hpp"
#include "cli/run_commands.hpp"
#include "cli/run_progress.hpp"
#include "cli/workpiece_report.hpp"
#include "runner/run.hpp"
#include "runner/texts.hpp"

namespace ncsim::cli {
namespace {

void json_split(std::ostream& os, const audit::TimeSplit& s) {
  os << "{\"rapid\":" << json_num(s.rapid) << ",\"feed\":" << json_num(s.feed)
     << ",\"dwell\":" << json_num(s.dwell) << ",\"tech\":" << json_num(s.tech)
     << ",\"exact_stop\":" << json_num(s.exact_stop) << ",\"waiting\":" << json_num(s.starved)
     << ",\"held\":" << json_num(s.held) << '}';
}

// The head of the output: the JSON object's first members, or the --blocks column line.
void print_time_head(const TimeOptions& options, const runner::Loaded& in, std::ostream& out) {
  if (options.json) {
    out << "{\"program\":";
    json_string(out, in.file.name());
    out << ",\"machine\":";
    json_string(out, in.machine.name);
    out << ",\"cycle_s\":" << json_num(in.t_cycle);
    if (options.blocks) out << ",\"blocks\":[";
  } else if (options.blocks) {
    out << "# line time_s distance_mm feed_programmed_mm_min feed_reached_mm_min rapid_s feed_s "
           "dwell_s tech_s exact_stop_s waiting_s held_s lost_s feed_cap_mm_min\n";
  }
}

// --blocks: one record per executed block, as it closes.
class BlockPrinter {
 public:
  BlockPrinter(const TimeOptions& options, const interp::Interpreter& interp, std::ostream& out)
      : options_(options), interp_(interp), out_(out) {}
  void operator()(const audit::BlockTime& b) {
    if (!options_.blocks) return;
    if (options_.json) {
      json(b);
    } else {
      text(b);
    }
    first_ = false;
  }

 private:
  void json(const audit::BlockTime& b) {
    out_ << (first_ ? "" : ",") << "{\"line\":" << b.line;
    if (b.file != 0) {  // A block of a subroutine file
      out_ << ",\"file\":";
      json_string(out_, interp_.file_name(b.file));
    }
    out_ << ",\"time_s\":" << json_num(b.time) << ",\"distance_mm\":" << json_num(b.distance)
         << ",\"feed_programmed_mm_min\":" << json_num(b.feed_programmed * 60.0)
         << ",\"feed_reached_mm_min\":" << json_num(b.feed_reached * 60.0);
    if (b.feed_cap > 0.0) out_ << ",\"feed_cap_mm_min\":" << json_num(b.feed_cap * 60.0);
    out_ << ",\"lost_s\":" << json_num(b.lost) << ",\"split_s\":";
    json_split(out_, b.split);
    out_ << '}';
  }
  void text(const audit::BlockTime& b) {
    out_ << runner::block_where(interp_, b.file, b.line) << ' ' << num(b.time) << ' '
         << num(b.distance) << ' ' << num(b.feed_programmed * 60.0) << ' '
         << num(b.feed_reached * 60.0) << ' ' << num(b.split.rapid) << ' ' << num(b.split.feed)
         << ' ' << num(b.split.dwell) << ' ' << num(b.split.tech) << ' ' << num(b.split.exact_stop)
         << ' ' << num(b.split.starved) << ' ' << num(b.split.held) << ' ' << num(b.lost) << ' ';
    if (b.feed_cap > 0.0)
      out_ << num(b.feed_cap * 60.0) << '\n';
    else
      out_ << "-\n";
  }

  const TimeOptions& options_;
  const interp::Interpreter& interp_;
  std::ostream& out_;
  bool first_ = true;
};

// The totals after the run (text or JSON), the workpiece rows among them; false when the
// workpiece rows' spool could not be read back.
bool print_time_total(const TimeOptions& options, runner::Run& run, const runner::Ending& end,
                      std::optional<WorkpieceReport>& rows, std::ostream& out) {
  const audit::TimeResult r = run.time_result();
  const runner::Loaded& in = run.loaded();
  const auto& stop = run.channel().scenario_stop();
  bool spooled = true;  // the workpiece rows were copied out
  const auto workpieces = [&] {
    if (const auto summary = run.workpiece_summary()) spooled = rows->finish(*summary, out);
  };
  if (options.json) {
    if (options.blocks) out << ']';
    out << ",\"status\":" << (end.failed ? "\"error\"" : "\"ok\"");
    if (end.failed) {
      out << ",\"error\":";
      json_string(out, runner::first_line(end.error_text));
    }
    out << ",\"cycles\":" << r.cycles << ",\"total_s\":" << json_num(r.total)
        << ",\"distance_mm\":" << json_num(r.distance) << ",\"lost_s\":" << json_num(r.lost)
        << ",\"split_s\":";
    json_split(out, r.split);
    workpieces();  // before "stop"
    out << ",\"stop\":";
    json_string(out, end.stop);
    out << "}\n";
    return spooled;
  }
  out << in.file.name() << ": " << (end.failed ? "stopped after " : "") << seconds(r.total)
      << " s (" << r.cycles << " cycles of " << num(in.t_cycle * 1e3) << " ms), path "
      << human(r.distance) << " mm; rapid " << human(r.split.rapid) << " s, feed "
      << human(r.split.feed) << " s, dwell " << human(r.split.dwell) << " s, tech "
      << human(r.split.tech) << " s, exact stop " << human(r.split.exact_stop) << " s, waiting "
      << human(r.split.starved) << " s, held " << human(r.split.held) << " s";
  // Under a scenario: the time lost to override and holds (docs/ipo.md "Time lost").
  if (run.plays()) out << "; lost to override and holds " << human(r.lost) << " s";
  out << '\n';
  workpieces();
  if (stop)
    out << "stop: " << scenario::to_string(*stop) << " (" << runner::stop_source(*in.scenario)
        << ") at " << seconds(r.total) << " s\n";
  else if (end.endless_from)
    out << "stop: endless (from line " << *end.endless_from << ", NC4904) at " << seconds(r.total)
        << " s\n";
  return spooled;
}

}  // namespace

int run_time(const TimeOptions& options, std::ostream& out, std::ostream& err) {
  runner::RunSpec spec;
  spec.program = options.program;
  spec.cycle_us = options.cycle_us;
  spec.audit = options.audit || options.audit_steps;
  auto loaded = load_run(spec, err);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  runner::Run run(std::move(std::get<std::unique_ptr<runner::Loaded>>(loaded)), spec);
  print_time_head(options, run.loaded(), out);
  // The channel loop of `run` with the sinks off (the audit sink with --audit, in the same
  // pass): the same cycles, so the total equals run's last t to the cycle.
  run.start();
  run.count_time(BlockPrinter(options, run.interpreter(), out));
  // The time per workpiece on a channel that tracks a conveyor (cli/workpiece_report)
  std::optional<WorkpieceReport> rows;
  if (run.tracks_conveyor()) {
    try {
      rows.emplace(options.json);
    } catch (const std::runtime_error& e) {
      err << "ncsim: error: " << e.what() << '\n';
      return kExitUsage;
    }
    run.count_workpieces([&rows](const audit::WorkpieceCycle& r) { rows->on_row(r); });
  }
  Progress progress(err);
  const ipo::Status status = run.run(
      [&progress](const channel::Channel& ch) { progress.update(ch.cycle().t, ch.cycle().line); });
  progress.finish();
  const runner::Ending end = run.ending(status);
  if (!print_time_total(options, run, end, rows, out)) {
    err << "ncsim: error: cannot read back the workpiece rows' temporary file\n";
    return kExitUsage;
  }
  err << runner::warnings_text(run) << runner::endless_note(end);
  if (!end.failed && !run.channel().scenario_stop()) err << runner::still_moving_text(run);
  if (end.failed) err << end.error_text;
  // The audit covers every cycle that was run, whatever ended the run (issue 36 item 4); a
  // run-time error keeps its exit status 1 over the audit's 3.
  if (const audit::Audit* audit = run.audit()) {
    const audit::Verdict& v = audit->verdict();
    print_audit(v, runner::axis_names(run.loaded().machine),
                runner::axis_units(run.loaded().machine), run.interpreter(),
                options.json ? err : out, options.audit_steps);
    if (!end.failed && !v.ok()) return kExitAudit;
  }
  return end.failed ? kExitProgramErrors : kExitOk;
}

}  // namespace ncsim::cli
