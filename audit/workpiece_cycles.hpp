#pragma once
// audit/workpiece_cycles: the time per workpiece of a conveyor program (`ncsim time`, the report;
// issue 14 "Finding the line's limits"; docs/conveyor.md "Time per workpiece").
//
// Purpose: split a looping conveyor program's time into one row per workpiece: waiting for the
// measured value, catch-up, machining (synchronised), desynchronisation, time off the belt,
// and the total; then workpieces per minute.
// Inputs: once per channel cycle the ConveyorSync phase after the cycle (add()), the Port's
// workpiece number of the last latch, the cycle time T.
// Outputs: a WorkpieceCycle row through the callback each time a workpiece's cycle ends (at the
// next #SYNC IN, or at finish()); finish() returns the WorkpieceSummary (lead-in before the
// first #SYNC IN, sums, shortest and longest cycle, workpieces per minute).
// Method: a workpiece's cycle starts in the cycle whose phase becomes `waiting` (a #SYNC IN)
// and ends when the next one starts. Each cycle's T goes to exactly one field of the open row
// by the phase after the cycle: waiting -> waiting; latched, catching_up -> catch_up (from the
// measured value until the catch-up has met the workpiece); tracking -> machining; leaving,
// departing -> desync (from #SYNC OUT until the departure has ended); off -> off_belt (MCS
// moves, INDP, dwell until the next #SYNC IN). Cycles before the first #SYNC IN are the
// lead-in. Time is counted in cycles and multiplied by T once (no rounding drift).
// Invariants: lead_in + sum of every row's total == cycles added * T (to rounding); a row's
// total == waiting + catch_up + machining + desync + off_belt. Memory is O(1): rows stream
// out through the callback and are never stored, whatever the number of workpieces.
// JSON: append_json() is the one form of a row and of the summary, in `ncsim time --json` and
// in the report's data (times in s with an `_s` suffix, shortest round-trip numbers).

#include <cstdint>
#include <functional>
#include <string>

#include "tracking/sync_phase.hpp"

namespace ncsim::audit {

/// One workpiece's cycle, from its #SYNC IN to the next #SYNC IN (or the end) [s].
struct WorkpieceCycle {
  std::uint64_t index = 0;      ///< 1-based, in order of #SYNC IN
  std::uint64_t workpiece = 0;  ///< the Port's workpiece number of the latch (0: unknown)
  double t_start = 0.0;         ///< [s] start of the cycle whose phase became `waiting`
  double waiting = 0.0;         ///< [s] #SYNC IN until the measured value
  double catch_up = 0.0;        ///< [s] measured value until the catch-up met the workpiece
  double machining = 0.0;       ///< [s] synchronised: PCS1 blocks on the moving frame
  double desync = 0.0;          ///< [s] #SYNC OUT until the departure ended
  double off_belt = 0.0;        ///< [s] not tracking until the next #SYNC IN (MCS moves, INDP)
  double total = 0.0;           ///< [s] the sum of the five
  /// The cycle reached #SYNC OUT (false: the run ended or failed before, or no motion ran).
  bool complete = false;
};

/// The whole run.
struct WorkpieceSummary {
  std::uint64_t workpieces = 0;  ///< rows (every #SYNC IN)
  std::uint64_t complete = 0;    ///< rows that reached #SYNC OUT
  double lead_in = 0.0;          ///< [s] before the first #SYNC IN
  /// Sums over every row [s] (index, workpiece, t_start and complete unused).
  WorkpieceCycle sum;
  double total_min = 0.0;  ///< [s] shortest complete row's total (0: none)
  double total_max = 0.0;  ///< [s] longest complete row's total (0: none)
  /// 60 x complete / (sum of the complete rows' totals) [1/min]; 0 without a complete row.
  double per_minute = 0.0;
};

/// Appends the row as a JSON object: {"index", "workpiece", "t_start_s", "waiting_s",
/// "catch_up_s", "machining_s", "desync_s", "off_belt_s", "total_s", "complete"}.
void append_json(std::string& out, const WorkpieceCycle& row);
/// Appends the summary as a JSON object: {"workpieces", "complete", "lead_in_s", "waiting_s",
/// "catch_up_s", "machining_s", "desync_s", "off_belt_s", "total_s" (the sums), "total_min_s",
/// "total_max_s", "per_minute"}.
void append_json(std::string& out, const WorkpieceSummary& summary);

class WorkpieceCycles {
 public:
  /// `t_cycle` [s] > 0 (std::invalid_argument otherwise); `on_row` sees every row as it ends.
  explicit WorkpieceCycles(double t_cycle, std::function<void(const WorkpieceCycle&)> on_row = {});
  /// Counts one cycle: `phase` is the tracking phase after it, `workpiece` the Port's
  /// LatchInfo::workpiece (0 when unknown).
  void add(tracking::SyncPhase phase, std::uint64_t workpiece) noexcept;
  /// Closes the open row (through the callback) and returns the summary.
  WorkpieceSummary finish();

 private:
  struct Counts {  // cycles per field of the open row
    std::uint64_t waiting = 0, catch_up = 0, machining = 0, desync = 0, off_belt = 0;
  };
  void close();

  double t_ = 0.0;
  std::function<void(const WorkpieceCycle&)> on_row_;
  std::uint64_t cycles_ = 0;   ///< cycles added
  std::uint64_t lead_in_ = 0;  ///< cycles before the first #SYNC IN
  bool open_ = false;
  bool complete_ = false;
  std::uint64_t start_ = 0;  ///< the open row's first cycle
  std::uint64_t workpiece_ = 0;
  tracking::SyncPhase last_ = tracking::SyncPhase::off;
  Counts row_;
  Counts sums_;  ///< cycles per field over every row (summed exactly, multiplied once)
  WorkpieceSummary sum_;
  double complete_total_ = 0.0;  ///< sum of the complete rows' totals [s]
};

}  // namespace ncsim::audit
