#pragma once
// cli/run_commands: `ncsim time`, `ncsim run` and `ncsim report` on the channel loop
// (design.md §5): their options, then a runner::RunSpec for runner/ (which loads and assembles
// the run), then the printing (cli/time_command.cpp, cli/run_command.cpp).
//
// Purpose: the end-to-end pipeline program -> interpreter -> planner -> interpolator -> axes.
// Inputs: the program, its machine (--machine, the program folder's `machine` file, else the
// bundled default), the options below. Outputs: `time`: total and per-block times on `out`;
// `run`: the CSV trajectory (and with --report the HTML page, `report` the page alone) (stdout or a
// file written to `<file>.tmp` and renamed when complete). Exit statuses: 0 ok, 1 program errors
// (file:line:col; `not supported: ...` is NC6001; run-time errors: file:line:col, the time and the
// id), 2 usage, configuration or write errors, 3 audit violations (--audit). A run-time error keeps
// the CSV up to the stop with a closing `# error: ...` comment. Invariants: memory does not grow
// with the program (blocks and rows are streamed); reruns are byte-identical (shortest round-trip
// number formatting; the wall clock only decides whether the progress bar is shown on a terminal,
// cli/run_progress.hpp).

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cli/commands.hpp"
#include "report/recorder.hpp"
#include "runner/load.hpp"
#include "runner/run.hpp"
#include "runner/spec.hpp"

namespace CLI {
class App;
}

namespace ncsim::cli {

inline constexpr int kExitAudit = 3;

struct TimeOptions {
  ProgramOptions program;
  bool blocks = false;                    ///< --blocks: one record per executed block
  bool json = false;                      ///< --json
  bool audit = false;                     ///< --audit: the audit sink in the same pass
  bool audit_steps = false;               ///< --audit-steps: --audit, every step listed
  std::optional<std::uint64_t> cycle_us;  ///< --cycle-us: interpolation cycle [us]
};

struct RunOptions {
  ProgramOptions program;
  std::string output = "-";  ///< -o: CSV file, "-" for stdout
  std::uint64_t every = 1;   ///< --every N: one row per N cycles
  std::optional<std::uint64_t> cycle_us;
  bool audit = false;        ///< --audit: the verdict on stderr, exit 3 on a violation
  bool audit_steps = false;  ///< --audit-steps: --audit, every documented step listed
  bool detail = false;  ///< --detail: per-axis v and a, path velocity, programmed feed, per-axis
                        ///< following error (`<axis>.ferr`, mm | deg)
  // The HTML run report of the same pass (docs/report.md)
  std::string report;  ///< --report FILE: also write the report page ("" none)
  bool csv = true;     ///< false for `ncsim report`: no CSV at all
};

// `ncsim report PROG.nc -o FILE` (docs/report.md)
struct ReportOptions {
  ProgramOptions program;
  std::string output = "report.html";  ///< -o: the page
  std::optional<std::uint64_t> cycle_us;
};

/// `ncsim time`.
int run_time(const TimeOptions& options, std::ostream& out, std::ostream& err);
/// `ncsim run`; with output "-" the CSV goes to the process's stdout (a FILE*, after `out`
/// is flushed), the audit verdict to `err`.
int run_run(const RunOptions& options, std::ostream& out, std::ostream& err);
/// `ncsim report`: run_run without CSV, with the report page (exit statuses as run).
int run_report(const ReportOptions& options, std::ostream& out, std::ostream& err);

/// Loads `spec` with the runner (runner/load.hpp) and prints what loading said on `err`: the
/// loaded run, or the exit status when it cannot start (an exception loading raised is
/// rethrown after its messages).
std::variant<std::unique_ptr<runner::Loaded>, int> load_run(const runner::RunSpec& spec,
                                                            std::ostream& err);

/// The RunSpec of one headless run (sweep, tune-delay; runner/line.hpp): the pass of
/// `time --audit` without position answers, as these runs always decoded.
runner::RunSpec line_spec(const ProgramOptions& program, std::optional<std::uint64_t> cycle_us);

/// The report page's recorder of `run` (report/recorder.hpp), sized from its configuration
/// before start(): `names` its axes; on a kinematic machine the MCS toolpath before #TRAFO ON
/// is the joints' TCP.
std::unique_ptr<report::Recorder> make_recorder(const runner::Run& run,
                                                const std::vector<std::string>& names);
/// After start(): the recorder sees the channel's setpoints, belt share, TCP, conveyor
/// tracking and axes (as `run --report` wires it).
void wire_recorder(const runner::Run& run, report::Recorder& recorder);

/// The `time` and `run` subcommands of `app`: the hook main.cpp calls.
/// The program, --machine and --scenario options of the subcommands that run a program on the
/// channel (time, run, report, sweep, tune-delay).
void add_run_program_options(CLI::App& cmd, ProgramOptions& program);
/// `--cycles DIR` (repeatable) and `--missing-cycles error|skip` (docs/interp.md "Cycles").
void add_cycle_options(CLI::App& cmd, ProgramOptions& program);
/// Adds `--cycle-us` to `cmd`: the interpolation cycle [us], a whole number 1 .. 1000000
/// (cli/cycle_option.hpp); anything else is a usage error naming the option and why (exit 2).
void add_cycle_us_option(CLI::App& cmd, std::optional<std::uint64_t>& cycle_us);

class RunCommands {
 public:
  explicit RunCommands(CLI::App& app);
  /// The exit status when `time` or `run` was parsed; nullopt otherwise.
  std::optional<int> dispatch(std::ostream& out, std::ostream& err) const;

 private:
  TimeOptions time_;
  RunOptions run_;
  ReportOptions report_;
  CLI::App* time_cmd_ = nullptr;
  CLI::App* run_cmd_ = nullptr;
  CLI::App* report_cmd_ = nullptr;
};

}  // namespace ncsim::cli
