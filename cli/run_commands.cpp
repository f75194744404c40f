#include "cli/run_commands.hpp"

#include <CLI/CLI.hpp>
#include <exception>
#include <ostream>

#include "cli/cycle_option.hpp"

namespace ncsim::cli {

std::variant<std::unique_ptr<runner::Loaded>, int> load_run(const runner::RunSpec& spec,
                                                            std::ostream& err) {
  runner::LoadResult r = runner::load(spec);
  err << r.messages;
  if (r.thrown) std::rethrow_exception(r.thrown);
  if (!r.ok()) return static_cast<int>(r.exit);
  return std::move(r.loaded);
}

runner::RunSpec line_spec(const ProgramOptions& program, std::optional<std::uint64_t> cycle_us) {
  runner::RunSpec spec;
  spec.program = program;
  spec.cycle_us = cycle_us;
  spec.audit = true;
  spec.answer_positions = false;
  return spec;
}

int run_report(const ReportOptions& options, std::ostream& out, std::ostream& err) {
  RunOptions run;
  run.program = options.program;
  run.cycle_us = options.cycle_us;
  run.report = options.output;
  run.csv = false;
  if (run.report.empty()) {
    err << "ncsim: error: report: -o needs a file name [NC8101]\n";
    return kExitUsage;
  }
  return run_run(run, out, err);
}

void add_run_program_options(CLI::App& cmd, ProgramOptions& program) {
  cmd.add_option("program", program.program, "NC program file (.nc)")->required();
  cmd.add_option("--machine", program.machine_dir,
                 "Machine folder (parameter lists); default: the program folder's 'machine' "
                 "file, else the bundled portal_3x");
  cmd.add_option("--scenario", program.scenario,
                 "Scenario TOML file (docs/scenario.md); default: the program folder's "
                 "scenario.toml");
  add_cycle_options(cmd, program);
  cmd.add_option("--max-time", program.max_time,
                 "Stop the run after S seconds of machine time (an endless production loop), "
                 "like a scenario's [stop] time; the reason is printed")
      ->check(CLI::Range(1e-6, 1e9));
}

void add_cycle_options(CLI::App& cmd, ProgramOptions& program) {
  cmd.add_option("--cycles", program.cycle_dirs,
                 "Folder of the machine builder's cycle files (G80-G89, G800-G839, L CYCLE), "
                 "looked in before the machine folder's cycles/ and the program's folder "
                 "(repeatable)")
      ->check(CLI::ExistingDirectory);
  cmd.add_option("--missing-cycles", program.missing_cycles,
                 "A cycle whose file is not configured or not found: error (default) or skip "
                 "(a zero-time step with warning NC4307 once per G code)")
      ->check(CLI::IsMember({"error", "skip"}));
}

void add_cycle_us_option(CLI::App& cmd, std::optional<std::uint64_t>& cycle_us) {
  cmd.add_option("--cycle-us", cycle_us,
                 "Interpolation cycle [us], 1 .. 1000000 (default: the channel list's "
                 "ncsim.cycle_time, 1000 when it has none)")
      ->check(CLI::Validator([](const std::string& text) { return cycle_us_error(text); }, "US",
                             "cycle"));
}

RunCommands::RunCommands(CLI::App& app) {
  time_cmd_ = app.add_subcommand("time", "Machining time, total and per block");
  add_run_program_options(*time_cmd_, time_.program);
  time_cmd_->add_flag("--blocks", time_.blocks, "Per executed block: time, distance, feeds, split");
  time_cmd_->add_flag("--json", time_.json, "JSON instead of text");
  time_cmd_->add_flag("--audit", time_.audit, "Check every limit; exit 3 on a violation");
  time_cmd_->add_flag("--audit-steps", time_.audit_steps,
                      "As --audit, and list every documented step (the first 1000)");
  add_cycle_us_option(*time_cmd_, time_.cycle_us);

  run_cmd_ = app.add_subcommand("run", "Run on the path interpolator and write the CSV trajectory");
  add_run_program_options(*run_cmd_, run_.program);
  run_cmd_->add_option("-o,--output", run_.output, "CSV file, '-' for stdout (default)");
  run_cmd_
      ->add_option("--every", run_.every, "One row every N cycles, and the last cycle (default 1)")
      ->check(
          CLI::Validator([](const std::string& text) { return every_error(text); }, "N", "every"));
  add_cycle_us_option(*run_cmd_, run_.cycle_us);
  run_cmd_->add_flag("--audit", run_.audit, "Check every limit (verdict on stderr); exit 3");
  run_cmd_->add_flag("--audit-steps", run_.audit_steps,
                     "As --audit, and list every documented step (the first 1000)");
  run_cmd_->add_flag(
      "--detail", run_.detail,
      "Add each axis's v and a, the path velocity, the programmed feed and each axis's "
      "following error");
  run_cmd_->add_option("--report", run_.report,
                       "Also write the HTML run report of the same pass (docs/report.md)");

  report_cmd_ = app.add_subcommand(
      "report", "Run on the path interpolator and write the HTML run report (docs/report.md)");
  add_run_program_options(*report_cmd_, report_.program);
  report_cmd_->add_option("-o,--output", report_.output, "HTML file (default report.html)");
  add_cycle_us_option(*report_cmd_, report_.cycle_us);
}

std::optional<int> RunCommands::dispatch(std::ostream& out, std::ostream& err) const {
  if (time_cmd_->parsed()) return run_time(time_, out, err);
  if (run_cmd_->parsed()) return run_run(run_, out, err);
  if (report_cmd_->parsed()) return run_report(report_, out, err);
  return std::nullopt;
}

}  // namespace ncsim::cli
