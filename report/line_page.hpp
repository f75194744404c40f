#pragma once
// report/line_page: the HTML page of a production line (issue 37 step 4; docs/report.md "The
// line page", docs/lines.md "ncsim line report").
//
// Purpose: one self-contained page for a line run: the line's summary (the very object of
// `ncsim line time --json`: per channel its end, waiting, utilisation, workpieces; the belt's
// counts and every workpiece's fate), the belt over time, the timeline of which channel took
// which workpiece when (and the missed ones), each channel's activity (running, waiting for a
// signal), then per channel the sections of a run report (its paths in MCS and PCS1, its axis
// charts, audit, conveyor, workpieces: report::Recorder's ReportData, one per channel).
// Inputs: per line cycle the belt's real position and velocity and each channel's state
// (LineRecorder::add); at the end the summary JSON and the channels' ReportData.
// Outputs: the page (report/html's shell, report/page.js draws it: the run page's sections are
// one function called per channel).
// Invariants: memory bounded (the line's series decimated as a run's, report::MinMaxDecimator;
// each channel's as its recorder's); byte-identical output for identical data; no data string
// can close the script element.

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "core/output_file.hpp"
#include "report/decimate.hpp"
#include "report/recorder.hpp"

namespace ncsim::report {

/// What a channel of the line did in a cycle (its lane on the activity chart).
enum class LaneState : std::uint8_t {
  ended,    ///< not running any more
  running,  ///< stepped and not waiting
  waiting,  ///< stood at a #WAIT / #WAIT SYN not answered
};

/// Everything the line page shows.
struct LineReportData {
  std::string line;         ///< the line file as given
  std::string description;  ///< the line file's description
  /// `ncsim line time --json`'s object (cli/line_report), embedded as it is.
  std::string summary_json;
  bool belt = false;  ///< the line has a conveyor world (the belt series are recorded)
  /// Rows of the line's series: belt position [mm], belt velocity [mm/s] (NaN without a belt),
  /// then per channel k at 2 + 2 k running and 2 + 2 k + 1 waiting (0/1 indicators).
  Decimated time;
  std::uint64_t bucket_width = 1;    ///< cycles per decimation bucket
  std::vector<ReportData> channels;  ///< per channel (line order) its run report's data
};

/// The line's own series, cycle by cycle, decimated like a run's (Recorder::kBuckets).
class LineRecorder {
 public:
  /// `channels` lanes; `belt`: the line has a conveyor world.
  LineRecorder(std::size_t channels, bool belt);
  /// One line cycle ending at `t` [s]: the real belt's position [mm] and velocity [mm/s]
  /// (ignored without a belt) and each channel's state (`lanes.size()` == channels).
  void add(double t, double belt_pos, double belt_v, std::span<const LaneState> lanes);
  /// The page's data with the line's series filled in; the recorder is spent afterwards.
  LineReportData finish(std::string line, std::string description, std::string summary_json,
                        std::vector<ReportData> channels) const;

 private:
  std::size_t channels_;
  bool belt_;
  MinMaxDecimator series_;
  std::vector<double> row_;
};

/// Writes the line page of `data` to `os`.
void write_line_html(const LineReportData& data, std::ostream& os);

/// Writes the line page to `out` (opened before the run) and commits it; false with the reason
/// in `why` (NC8100) on a write error.
bool write_line_html_file(const LineReportData& data, core::OutputFile& out, std::string& why);

}  // namespace ncsim::report
