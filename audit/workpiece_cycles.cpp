// audit/workpiece_cycles: the time per workpiece of a conveyor program (see the header).

#include "audit/workpiece_cycles.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/number_text.hpp"

namespace ncsim::audit {

namespace {

/// `"key":value`, the value the shortest text that reads back to the same double (null when
/// not finite: JSON has no inf / nan).
void field(std::string& out, const char* key, double v) {
  out += '"';
  out += key;
  out += "\":";
  out += core::json_num(v);
}

/// The five phases and their total, `"waiting_s":..,...,"total_s":..`.
void phases(std::string& out, const WorkpieceCycle& r) {
  field(out, "waiting_s", r.waiting);
  out += ',';
  field(out, "catch_up_s", r.catch_up);
  out += ',';
  field(out, "machining_s", r.machining);
  out += ',';
  field(out, "desync_s", r.desync);
  out += ',';
  field(out, "off_belt_s", r.off_belt);
  out += ',';
  field(out, "total_s", r.total);
}

}  // namespace

void append_json(std::string& out, const WorkpieceCycle& row) {
  out += "{\"index\":" + std::to_string(row.index) +
         ",\"workpiece\":" + std::to_string(row.workpiece) + ',';
  field(out, "t_start_s", row.t_start);
  out += ',';
  phases(out, row);
  out += std::string(",\"complete\":") + (row.complete ? "true" : "false") + '}';
}

void append_json(std::string& out, const WorkpieceSummary& summary) {
  out += "{\"workpieces\":" + std::to_string(summary.workpieces) +
         ",\"complete\":" + std::to_string(summary.complete) + ',';
  field(out, "lead_in_s", summary.lead_in);
  out += ',';
  phases(out, summary.sum);
  out += ',';
  field(out, "total_min_s", summary.total_min);
  out += ',';
  field(out, "total_max_s", summary.total_max);
  out += ',';
  field(out, "per_minute", summary.per_minute);
  out += '}';
}

WorkpieceCycles::WorkpieceCycles(double t_cycle, std::function<void(const WorkpieceCycle&)> on_row)
    : t_(t_cycle), on_row_(std::move(on_row)) {
  if (!(t_cycle > 0.0))
    throw std::invalid_argument("workpiece cycles: cycle time " + core::human(t_cycle) +
                                " s must be > 0");
}

void WorkpieceCycles::add(tracking::SyncPhase phase, std::uint64_t workpiece) noexcept {
  // A #SYNC IN: the phase becomes `waiting` (from any other). It also starts a row when the
  // measured value is already there and the phase passes `waiting` within the cycle.
  const bool entered =
      (phase == tracking::SyncPhase::waiting && last_ != tracking::SyncPhase::waiting) ||
      ((phase == tracking::SyncPhase::latched || phase == tracking::SyncPhase::catching_up) &&
       (last_ == tracking::SyncPhase::off || last_ == tracking::SyncPhase::leaving ||
        last_ == tracking::SyncPhase::departing));
  if (entered) {
    if (open_) close();
    open_ = true;
    complete_ = false;
    start_ = cycles_;
    row_ = Counts{};
    workpiece_ = 0;
  }
  ++cycles_;
  last_ = phase;
  if (!open_) {
    ++lead_in_;
    return;
  }
  if (phase != tracking::SyncPhase::waiting) workpiece_ = workpiece;  // the latch of this row
  switch (phase) {
    case tracking::SyncPhase::waiting:
      ++row_.waiting;
      break;
    case tracking::SyncPhase::latched:
    case tracking::SyncPhase::catching_up:
      ++row_.catch_up;
      break;
    case tracking::SyncPhase::tracking:
      ++row_.machining;
      break;
    case tracking::SyncPhase::leaving:
    case tracking::SyncPhase::departing:
      ++row_.desync;
      complete_ = true;
      break;
    case tracking::SyncPhase::off:
      ++row_.off_belt;
      // Back to off after tracking: #SYNC OUT with nothing moving with the belt.
      if (row_.machining > 0 || row_.desync > 0) complete_ = true;
      break;
  }
}

void WorkpieceCycles::close() {
  WorkpieceCycle r;
  r.index = sum_.workpieces + 1;
  r.workpiece = workpiece_;
  r.t_start = static_cast<double>(start_) * t_;
  r.waiting = static_cast<double>(row_.waiting) * t_;
  r.catch_up = static_cast<double>(row_.catch_up) * t_;
  r.machining = static_cast<double>(row_.machining) * t_;
  r.desync = static_cast<double>(row_.desync) * t_;
  r.off_belt = static_cast<double>(row_.off_belt) * t_;
  const std::uint64_t n =
      row_.waiting + row_.catch_up + row_.machining + row_.desync + row_.off_belt;
  r.total = static_cast<double>(n) * t_;
  r.complete = complete_;
  ++sum_.workpieces;
  sums_.waiting += row_.waiting;
  sums_.catch_up += row_.catch_up;
  sums_.machining += row_.machining;
  sums_.desync += row_.desync;
  sums_.off_belt += row_.off_belt;
  if (r.complete) {
    if (sum_.complete == 0 || r.total < sum_.total_min) sum_.total_min = r.total;
    if (sum_.complete == 0 || r.total > sum_.total_max) sum_.total_max = r.total;
    ++sum_.complete;
    complete_total_ += r.total;
  }
  open_ = false;
  if (on_row_) on_row_(r);
}

WorkpieceSummary WorkpieceCycles::finish() {
  if (open_) close();
  sum_.lead_in = static_cast<double>(lead_in_) * t_;
  sum_.sum.waiting = static_cast<double>(sums_.waiting) * t_;
  sum_.sum.catch_up = static_cast<double>(sums_.catch_up) * t_;
  sum_.sum.machining = static_cast<double>(sums_.machining) * t_;
  sum_.sum.desync = static_cast<double>(sums_.desync) * t_;
  sum_.sum.off_belt = static_cast<double>(sums_.off_belt) * t_;
  sum_.sum.total = static_cast<double>(sums_.waiting + sums_.catch_up + sums_.machining +
                                       sums_.desync + sums_.off_belt) *
                   t_;
  sum_.per_minute =
      complete_total_ > 0.0 ? 60.0 * static_cast<double>(sum_.complete) / complete_total_ : 0.0;
  WorkpieceSummary out = sum_;
  sum_ = WorkpieceSummary{};
  lead_in_ = 0;
  cycles_ = 0;
  sums_ = Counts{};
  complete_total_ = 0.0;
  last_ = tracking::SyncPhase::off;
  return out;
}

}  // namespace ncsim::audit
