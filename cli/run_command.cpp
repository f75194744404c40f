// `ncsim run` and `ncsim report` (cli/run_commands.hpp): the run from runner/, its cycles
// written as CSV (cli/csv_sink.hpp) and recorded for the HTML page (report/), the outputs
// opened before the run and committed after it (core/output_file.hpp).

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <ostream>

#include "cli/audit_print.hpp"
#include "cli/csv_sink.hpp"
#include "cli/number_format.hpp"
#include "cli/run_commands.hpp"
#include "cli/run_progress.hpp"
#include "core/output_file.hpp"
#include "program/trafo.hpp"
#include "report/html.hpp"
#include "report/recorder.hpp"
#include "runner/run.hpp"
#include "runner/texts.hpp"

namespace ncsim::cli {
namespace {

// The run's output files, opened before the run: an unwritable one is reported at once.
// stdout through `out`'s buffer is avoided: the CSV goes through a FILE*. "-" writes to stdout;
// a file goes through core::OutputFile (a unique temporary file renamed when complete; a pipe or
// device written in place; docs/design.md "Output files").
struct Outputs {
  bool to_stdout = false;
  std::optional<core::OutputFile> csv_file;
  std::optional<core::OutputFile> page_file;
  std::FILE* f = nullptr;  ///< where the CSV goes (null: no CSV)
};

// Opens the outputs of `options`; the exit status (reported on `err`) when one cannot be.
std::optional<int> open_outputs(const RunOptions& options, Outputs& o, std::ostream& out,
                                std::ostream& err) {
  o.to_stdout = options.output == "-";
  if (options.csv && !o.to_stdout) {
    auto opened = core::OutputFile::open(options.output);
    if (const auto* why = std::get_if<std::string>(&opened)) {
      err << "ncsim: error: " << *why << " [NC9150]\n";
      return kExitUsage;
    }
    o.csv_file.emplace(std::move(std::get<core::OutputFile>(opened)));
  }
  if (!options.report.empty()) {
    auto opened = core::OutputFile::open(options.report);
    if (const auto* why = std::get_if<std::string>(&opened)) {
      err << "ncsim: error: the report: " << *why << " [NC8100]\n";
      return kExitUsage;
    }
    o.page_file.emplace(std::move(std::get<core::OutputFile>(opened)));
  }
  if (o.to_stdout && options.csv) {
    out.flush();
    o.f = stdout;
  } else if (o.csv_file) {
    o.f = o.csv_file->stream();
  }
  return std::nullopt;
}

// The CSV's head: comments, then the columns (without the conveyor's and the newline).
std::string csv_head(const runner::Loaded& in, const std::vector<std::string>& names, bool detail) {
  std::string head = "# ncsim run\n# program: " + in.file.name() +
                     "\n# machine: " + in.machine.name + "\n# cycle: " + num(in.t_cycle) +
                     " s\n# units: mm | deg, s; v [mm/s], a [mm/s^2]\nt,line";
  for (const std::string& n : names)
    head += ',' + n;
  if (detail) {
    for (const std::string& n : names)
      head += ',' + n + ".v," + n + ".a";
    head += ",v_path,feed";
    for (const std::string& n : names)
      head += ',' + n + ".ferr";
  }
  return head;
}

// The sinks see the channel's state: the CSV its axes, setpoints and (--detail on a channel
// that tracks a conveyor) display variables, the recorder its parts; writes the CSV head.
void wire_sinks(const RunOptions& options, const runner::Run& run, std::string head, CsvSink& csv,
                report::Recorder* recorder) {
  const channel::Channel& channel = run.channel();
  if (recorder) wire_recorder(run, *recorder);
  // The conveyor display variables (seed 004 §6; docs/conveyor.md) with --detail on a channel
  // that tracks a conveyor: mm, mm/s, mm/s^2, 0 before the first measurement; synchro_lag
  // [mm] machine minus real workpiece (tracking/synchro_lag.hpp), 0 unless the frame moves.
  if (options.detail && run.loaded().port != nullptr && channel.conveyor_sync() != nullptr) {
    head +=
        ",current_pos_master,current_v_master,current_a_master,pos_master_comp,v_master_comp,"
        "a_master_comp,synchro_lag";  // synchro_lag
    csv.set_conveyor(&channel);
  }
  head += '\n';
  csv.text(head);
  csv.set_axes(&channel.axes());
  csv.set_setpoints(&channel.setpoints());
}

// The channel stepped to its end (or to a CSV write error); the last status.
ipo::Status run_cycles(runner::Run& run, CsvSink& csv, report::Recorder* recorder,
                       std::ostream& err) {
  const channel::Channel& channel = run.channel();
  Progress progress(err);
  ipo::Status s;
  while ((s = run.step()) == ipo::Status::running && !csv.failed()) {
    if (recorder && channel.transformed()) recorder->on_joints(channel.cycle(), channel.joints());
    progress.update(channel.cycle().t, channel.cycle().line);
    write_tech(channel, csv);
  }
  csv.write_last();          // --every N: the run's last cycle, whatever its index
  write_tech(channel, csv);  // those of the program's final wait
  progress.finish();
  return s;
}

// The CSV's end: the error or stop comments, flushed and committed; the exit status (reported
// on `err`) when it cannot be written. `error_text` gains the note after an error.
std::optional<int> close_csv(runner::Run& run, ipo::Status s, runner::Ending& end, CsvSink& csv,
                             Outputs& o, std::ostream& err) {
  const channel::Channel& channel = run.channel();
  if (end.failed) {
    csv.text("# error: " + runner::first_line(end.error_text) + "\n");
    // An error while synchronised: the motion after it (004 §2.3)
    if (const std::string note = channel.after_error_note(); !note.empty()) {
      csv.text("# after the error: " + note + "\n");
      end.error_text += "ncsim: note: " + note + "\n";
    }
  } else if (const auto& stop = channel.scenario_stop()) {
    err << "ncsim: run stopped (" << runner::stop_source(*run.loaded().scenario)
        << "): " << scenario::to_string(*stop) << " at t=" << seconds(channel.cycle().t) << " s\n";
  }
  // The closing comment: why the run ended (program end, error, stop.time, ...), when it did
  // (not after a write error, which ends the loop early).
  if (s != ipo::Status::running) csv.text("# stop: " + end.stop + "\n");
  csv.flush();
  if (o.to_stdout && !csv.failed() && std::fflush(o.f) != 0) csv.set_failed(errno);
  if (csv.failed()) {
    err << "ncsim: error: cannot write '"
        << (o.to_stdout ? std::string("stdout") : o.csv_file->written().string())
        << "': " << std::strerror(csv.error_number()) << " [NC9151]\n";
    return kExitUsage;  // the temporary file goes with csv_file
  }
  if (o.csv_file) {
    std::string why;
    if (!o.csv_file->commit(why)) {
      err << "ncsim: error: " << why << " [NC9151]\n";
      return kExitUsage;
    }
  }
  return std::nullopt;
}

// The page, also after a run-time error (it shows it); the exit status (reported on
// `err`) when it cannot be written.
std::optional<int> write_page(const RunOptions& options, const runner::Run& run,
                              const runner::Ending& end, report::Recorder& recorder, Outputs& o,
                              std::ostream& out, std::ostream& err) {
  const auto& stop = run.channel().scenario_stop();
  const report::ReportData data = recorder.finish(
      {run.loaded().file.name(), run.loaded().machine.name,
       stop ? std::string(scenario::to_string(*stop)) : std::string(), end.error_text});
  std::string why;
  if (!report::write_html_file(data, *o.page_file, why)) {
    err << "ncsim: error: " << why << '\n';
    return kExitUsage;
  }
  (options.csv ? err : out) << "report: " << options.report << '\n';
  return std::nullopt;
}

}  // namespace

std::unique_ptr<report::Recorder> make_recorder(const runner::Run& run,
                                                const std::vector<std::string>& names) {
  const channel::ChannelConfig& cfg = run.config();
  auto recorder = std::make_unique<report::Recorder>(names, cfg.path.axes, cfg.path.channel.t_cycle,
                                                     cfg.path.start);
  recorder->set_limits(cfg);
  // On a kinematic machine the MCS toolpath before #TRAFO ON is the joints' TCP.
  if (cfg.path.joints) {
    if (const auto trafo = program::machine_trafo(run.loaded().machine, cfg.path))
      recorder->set_forward(program::forward_map(trafo->kinematics, trafo->slots));
  }
  return recorder;
}

void wire_recorder(const runner::Run& run, report::Recorder& recorder) {
  const channel::Channel& channel = run.channel();
  recorder.set_setpoints(&channel.setpoints());
  recorder.set_belt(&channel.belt_share());
  recorder.set_tcp(&channel.tcp());
  recorder.set_conveyor(channel.conveyor_sync());
  recorder.set_axes(&channel.axes());
}

int run_run(const RunOptions& options, std::ostream& out, std::ostream& err) {
  if (options.every == 0) {
    err << "ncsim: error: --every must be at least 1\n";
    return kExitUsage;
  }
  runner::RunSpec spec;
  spec.program = options.program;
  spec.cycle_us = options.cycle_us;
  spec.audit = options.audit || options.audit_steps;
  auto loaded = load_run(spec, err);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  Outputs o;
  if (const auto status = open_outputs(options, o, out, err)) return *status;

  runner::Run run(std::move(std::get<std::unique_ptr<runner::Loaded>>(loaded)), spec);
  const std::vector<std::string> names = runner::axis_names(run.loaded().machine);
  CsvSink csv(o.f, names.size(), options.every, options.detail);
  std::unique_ptr<report::Recorder> recorder;  // the same joints and cycles
  if (!options.report.empty()) recorder = make_recorder(run, names);
  std::vector<ipo::Sink*> sinks;
  if (options.csv) sinks.push_back(&csv);
  if (recorder) sinks.push_back(recorder.get());
  run.start(sinks);
  wire_sinks(options, run, csv_head(run.loaded(), names, options.detail), csv, recorder.get());
  const ipo::Status s = run_cycles(run, csv, recorder.get(), err);
  runner::Ending end = run.ending(s);
  if (const auto status = close_csv(run, s, end, csv, o, err)) return *status;
  if (recorder) {
    if (const auto status = write_page(options, run, end, *recorder, o, out, err)) return *status;
  }
  err << runner::warnings_text(run) << runner::endless_note(end);
  if (!end.failed && !run.channel().scenario_stop()) err << runner::still_moving_text(run);
  if (!end.error_text.empty()) err << end.error_text;
  // The audit covers every cycle that was run, whatever ended the run (issue 36 item 4); a
  // run-time error keeps its exit status 1 over the audit's 3.
  if (const audit::Audit* audit = run.audit()) {
    print_audit(audit->verdict(), names, runner::axis_units(run.loaded().machine),
                run.interpreter(), err, options.audit_steps);
    if (end.error_text.empty() && !audit->verdict().ok()) return kExitAudit;
  }
  return end.error_text.empty() ? kExitOk : kExitProgramErrors;
}

}  // namespace ncsim::cli
