#pragma once
// cli/workpiece_report: the time per workpiece in `ncsim time`'s text and JSON output (issue 14
// "Finding the line's limits"; docs/conveyor.md "Time per workpiece").
//
// Purpose: print the rows of audit::WorkpieceCycles after the run's totals without holding them
// in memory: the rows arrive during the run (interleaved with --blocks' records), so they are
// spooled to an anonymous temporary file and copied out at the end.
// Inputs: the rows (on_row()), the summary (finish()). Outputs: text lines
//   workpiece N [#W]: waiting .. s, catch-up .. s, machining .. s, desync .. s, off belt .. s,
//   total .. s
//   workpieces: C complete of N; lead-in .. s; per workpiece .. to .. s; .. per minute
// or the JSON members "workpieces":[{...}] and "workpiece_summary":{...}.
// Invariants: memory O(1) whatever the number of workpieces; numbers in JSON round-trip exactly.

#include <cstdio>
#include <memory>
#include <ostream>

#include "audit/workpiece_cycles.hpp"

namespace ncsim::cli {

class WorkpieceReport {
 public:
  /// `json`: rows as JSON objects. Throws std::runtime_error when no temporary file can be made.
  explicit WorkpieceReport(bool json);
  /// Spools one row.
  void on_row(const audit::WorkpieceCycle& row);
  /// Writes the rows and the summary to `out` (text lines, or the JSON members with a leading
  /// comma); nothing when no #SYNC IN ran. False on a spool read/write error.
  bool finish(const audit::WorkpieceSummary& summary, std::ostream& out);

 private:
  struct Close {
    void operator()(std::FILE* f) const noexcept { std::fclose(f); }
  };
  bool json_;
  std::unique_ptr<std::FILE, Close> spool_;
  bool failed_ = false;
  std::uint64_t rows_ = 0;
};

}  // namespace ncsim::cli
