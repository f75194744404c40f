#pragma once
// cli/line_page: the HTML page of `ncsim line report` / `line run --report` (docs/lines.md
// "ncsim line report", docs/report.md "The line page"): report/'s recorders wired to a line.
//
// Purpose: one report::Recorder per channel (made and wired as `run --report` makes and wires
// its one: cli/run_commands.hpp), fed by the line's cycles; one report::LineRecorder for the
// belt and the channels' lanes; at the end the page's data with the line's summary as
// `line time --json` prints it (cli/line_report).
// Inputs: the LineRun before start() (sinks()), after start() (wire()), after every cycle
// (on_cycle()), after the run (finish()). Outputs: report::LineReportData.
// Invariants: one pass: the page's channels saw the same cycles as the CSVs and the times.

#include <memory>
#include <vector>

#include "report/line_page.hpp"
#include "report/recorder.hpp"
#include "runner/line_run.hpp"

namespace ncsim::cli {

class LinePage {
 public:
  /// The recorders of `line`'s channels (before line.start()).
  explicit LinePage(const runner::LineRun& line);
  /// Channel k's sink: its recorder.
  ipo::Sink* sink(std::size_t k) const noexcept { return recorders_[k].get(); }
  /// After line.start(): each recorder sees its channel's state.
  void wire(const runner::LineRun& line);
  /// After every line cycle (LineRun::run's after_cycle).
  void on_cycle(const runner::LineRun& line);
  /// The page's data after the run (LineRun::run returned).
  report::LineReportData finish(const runner::LineRun& line);

 private:
  std::vector<std::unique_ptr<report::Recorder>> recorders_;
  report::LineRecorder lanes_;
  std::vector<report::LaneState> state_;
};

}  // namespace ncsim::cli
