// golden/compare: a run against its golden (golden.hpp; rules in docs/golden.md "Check").
//
// Three comparisons over one pass of the run CSV:
// - positions: each golden row against the run's row of the same cycle, per column within its
//   tolerance (one deviation per row: the column furthest outside, relative to its tolerance);
// - blocks: the run's block ends (line changes, and its last row) against the golden's `b`
//   rows as a sequence: equal lines, cycles within tolerance_cycles; once the sequences part
//   (a block more or less), the first place is reported and the rest of the sequence is not;
// - end: cycles run (within tolerance_cycles), exit status, error id and line.
#include <algorithm>
#include <cmath>
#include <deque>
#include <istream>

#include "core/number_text.hpp"
#include "golden/golden.hpp"

namespace ncsim::golden {
namespace {

using core::human;

std::string outcome_text(int status, const std::optional<RunError>& e) {
  std::string s = "status " + std::to_string(status);
  if (e) s += " (error " + e->id + " at line " + std::to_string(e->line) + ")";
  return s;
}

// Keeps the earliest Comparison::kListed deviations and counts them all.
class Collector {
 public:
  explicit Collector(Comparison& c) : c_(c) {}
  void add(Deviation d) {
    ++c_.count;
    auto& list = c_.deviations;
    if (list.size() == Comparison::kListed && list.back().cycle <= d.cycle) return;
    const auto at =
        std::upper_bound(list.begin(), list.end(), d.cycle,
                         [](std::uint64_t cycle, const Deviation& x) { return cycle < x.cycle; });
    list.insert(at, std::move(d));
    if (list.size() > Comparison::kListed) list.pop_back();
  }

 private:
  Comparison& c_;
};

// The next block-end row of a golden; false at its end.
bool next_block(GoldenReader& g, GoldenRow& row) {
  while (g.next(row))
    if (row.block_end) return true;
  return false;
}

std::uint64_t cycle_distance(std::uint64_t a, std::uint64_t b) {
  return a > b ? a - b : b - a;
}

// Most cycles a golden row's line may be from the run's block of that line (the window of
// run rows kept: memory stays bounded whatever tolerance_cycles a golden states).
constexpr std::uint64_t kLineWindowMax = 1000;

}  // namespace

const char* id_of(Deviation::Kind kind) {
  switch (kind) {
    case Deviation::Kind::position:
      return "NC8001";
    case Deviation::Kind::block:
      return "NC8002";
    case Deviation::Kind::end:
      return "NC8003";
    case Deviation::Kind::head:
      return "NC8004";
  }
  return "NC8001";
}

Comparison compare(RunCsv& csv, const Outcome& outcome, std::istream& positions,
                   std::istream& blocks) {
  GoldenReader gp(positions);
  GoldenReader gb(blocks);
  const Head& h = gp.head();
  const std::uint64_t us = h.cycle_us;
  const std::uint64_t tol_cycles = h.settings.tolerance_cycles;
  Comparison result;
  result.cycle_us = us;
  Collector out(result);
  const auto at = [&](std::uint64_t cycle) { return time_text(cycle, us); };

  const auto head_deviation = [&](const std::string& what) {
    Deviation d;
    d.kind = Deviation::Kind::head;
    d.what = what;
    out.add(std::move(d));
  };
  if (csv.machine() != (h.machine == "-" ? std::string() : h.machine)) {
    head_deviation("the run is on machine '" + csv.machine() + "', the golden on '" + h.machine +
                   "'");
  }
  const bool same_cycle = csv.cycle_us() == us || csv.columns().empty() || h.columns.empty();
  if (!same_cycle) {
    head_deviation("the run's cycle is " + std::to_string(csv.cycle_us()) + " us, the golden's " +
                   std::to_string(us) + " us");
  }
  if (csv.columns() != h.columns) {
    std::string a;
    std::string b;
    for (const auto& c : csv.columns())
      a += ' ' + c;
    for (const auto& c : h.columns)
      b += ' ' + c;
    head_deviation("the run's columns are" + a + ", the golden's" + b);
  }
  const bool rows_comparable = same_cycle && csv.columns() == h.columns;

  std::vector<double> tol;
  for (const std::string& c : h.columns)
    tol.push_back(h.settings.tolerance_for(c));

  // The lines of golden rows: the golden's line at cycle k must be the run's line at a cycle
  // within tolerance_cycles of k (a block end may move that far; bounded window).
  const std::uint64_t window = std::min<std::uint64_t>(tol_cycles, kLineWindowMax);
  std::deque<std::pair<std::uint64_t, std::uint64_t>> recent;  // the run's (cycle, line)
  std::deque<GoldenRow> pending_lines;                         // golden rows to settle
  const auto settle_lines = [&](bool all) {
    while (!pending_lines.empty() &&
           (all ||
            (!recent.empty() && pending_lines.front().row.cycle + window <= recent.back().first))) {
      const GoldenRow& g = pending_lines.front();
      bool found = false;
      std::uint64_t run_line = 0;
      for (const auto& [cycle, line] : recent) {
        if (cycle == g.row.cycle) run_line = line;
        found = found || (cycle_distance(cycle, g.row.cycle) <= window && line == g.row.line);
      }
      if (!found) {
        Deviation d;
        d.kind = Deviation::Kind::block;
        d.cycle = g.row.cycle;
        d.line = g.row.line;
        d.file_line = g.file_line;
        d.tolerance = static_cast<double>(tol_cycles);
        d.what = "at t=" + at(g.row.cycle) + " s the block is line " + std::to_string(g.row.line) +
                 " in the golden, line " + std::to_string(run_line) +
                 " in the run (no block end within " + std::to_string(tol_cycles) + " cycles)";
        out.add(std::move(d));
      }
      pending_lines.pop_front();
    }
    while (recent.size() > 2 * window + 2)
      recent.pop_front();
  };

  GoldenRow gpos;
  bool gpos_ok = gp.next(gpos);
  GoldenRow gblk;
  bool gblk_ok = next_block(gb, gblk);
  bool aligned = rows_comparable;

  const auto on_block_end = [&](const Row& r) {
    if (!aligned) return;
    Deviation d;
    d.kind = Deviation::Kind::block;
    d.tolerance = static_cast<double>(tol_cycles);
    if (!gblk_ok) {
      d.cycle = r.cycle;
      d.line = r.line;
      d.what = "the run has a block more: line " + std::to_string(r.line) +
               " ending at t=" + at(r.cycle) + " s, after the golden's last block";
      aligned = false;
      out.add(std::move(d));
      return;
    }
    d.file_line = gblk.file_line;
    d.line = gblk.row.line;
    if (gblk.row.line != r.line) {
      d.cycle = std::min(gblk.row.cycle, r.cycle);
      d.what = "the block sequence parts: the golden's next block is line " +
               std::to_string(gblk.row.line) + " ending at t=" + at(gblk.row.cycle) +
               " s, the run's is line " + std::to_string(r.line) + " ending at t=" + at(r.cycle) +
               " s";
      aligned = false;
      out.add(std::move(d));
      return;
    }
    const std::uint64_t dk = cycle_distance(r.cycle, gblk.row.cycle);
    if (dk > tol_cycles) {
      d.cycle = std::min(gblk.row.cycle, r.cycle);
      d.size = static_cast<double>(dk);
      d.what = "block line " + std::to_string(r.line) + " ends at t=" + at(r.cycle) +
               " s in the run, t=" + at(gblk.row.cycle) +
               " s in the golden: " + std::to_string(dk) + " cycles apart (tolerance " +
               std::to_string(tol_cycles) + ")";
      out.add(std::move(d));
    }
    gblk_ok = next_block(gb, gblk);
  };

  Row row;
  Row prev;
  bool have = false;
  if (rows_comparable) {
    while (csv.next(row)) {
      while (gpos_ok && gpos.row.cycle < row.cycle) {
        // The run has no row at this golden row's cycle (it started later).
        Deviation d;
        d.kind = Deviation::Kind::position;
        d.cycle = gpos.row.cycle;
        d.line = gpos.row.line;
        d.file_line = gpos.file_line;
        d.what = "the run has no row at t=" + at(gpos.row.cycle) + " s";
        out.add(std::move(d));
        gpos_ok = gp.next(gpos);
      }
      if (gpos_ok && gpos.row.cycle > row.cycle && row.cycle % h.settings.sample_cycles == 0) {
        // bless writes a row at every sample cycle: a missing one was removed from the file.
        Deviation d;
        d.kind = Deviation::Kind::position;
        d.cycle = row.cycle;
        d.line = row.line;
        d.file_line = gpos.file_line;
        d.what = "the golden has no row at t=" + at(row.cycle) + " s, a sample cycle (every " +
                 std::to_string(h.settings.sample_cycles) +
                 " cycles): a row was removed from the golden";
        out.add(std::move(d));
      }
      recent.emplace_back(row.cycle, row.line);
      if (gpos_ok && gpos.row.cycle == row.cycle) {
        pending_lines.push_back(gpos);
        ++result.rows;
        std::size_t worst = h.columns.size();
        double worst_ratio = 1.0;
        for (std::size_t i = 0; i < h.columns.size(); ++i) {
          const double diff = std::abs(row.values[i] - gpos.row.values[i]);
          const double ratio = tol[i] > 0.0 ? diff / tol[i] : (diff > 0.0 ? INFINITY : 0.0);
          if (diff > tol[i] && (ratio > worst_ratio || worst == h.columns.size())) {
            worst = i;
            worst_ratio = ratio;
          }
        }
        if (worst < h.columns.size()) {
          Deviation d;
          d.kind = Deviation::Kind::position;
          d.cycle = row.cycle;
          d.line = gpos.row.line;
          d.axis = h.columns[worst];
          d.size = std::abs(row.values[worst] - gpos.row.values[worst]);
          d.tolerance = tol[worst];
          d.file_line = gpos.file_line;
          d.what = d.axis + " is " + human(row.values[worst]) + " in the run, " +
                   human(gpos.row.values[worst]) + " in the golden: off by " + human(d.size) +
                   " (tolerance " + human(d.tolerance) + ")";
          out.add(std::move(d));
        }
        gpos_ok = gp.next(gpos);
      }
      settle_lines(false);
      if (have && row.line != prev.line) on_block_end(prev);
      std::swap(prev, row);
      have = true;
    }
    settle_lines(true);
    if (have) on_block_end(prev);
  } else {
    while (csv.next(row)) {
      prev = row;
      have = true;
    }
  }
  const std::uint64_t run_cycles = have ? prev.cycle : 0;
  result.cycles = run_cycles;
  if (aligned && gblk_ok) {
    Deviation d;
    d.kind = Deviation::Kind::block;
    d.cycle = std::min(gblk.row.cycle, run_cycles);
    d.line = gblk.row.line;
    d.file_line = gblk.file_line;
    d.what = "the run has a block less: the golden's block line " + std::to_string(gblk.row.line) +
             " ending at t=" + at(gblk.row.cycle) + " s is not in the run";
    out.add(std::move(d));
  }
  while (gpos_ok)
    gpos_ok = gp.next(gpos);
  const End& e = gp.end();

  const auto end_deviation = [&](std::uint64_t cycle, double size, double tolerance,
                                 const std::string& what) {
    Deviation d;
    d.kind = Deviation::Kind::end;
    d.cycle = cycle;
    d.line = e.error ? e.error->line : 0;
    d.size = size;
    d.tolerance = tolerance;
    d.file_line = e.file_line;
    d.what = what;
    out.add(std::move(d));
  };
  const std::uint64_t dk = cycle_distance(run_cycles, e.cycle);
  if (rows_comparable && dk > tol_cycles) {
    end_deviation(
        std::min(run_cycles, e.cycle), static_cast<double>(dk), static_cast<double>(tol_cycles),
        "the run ends at t=" + at(run_cycles) + " s, the golden at t=" + at(e.cycle) + " s: " +
            std::to_string(dk) + " cycles apart (tolerance " + std::to_string(tol_cycles) + ")");
  }
  const bool same_error = outcome.error.has_value() == e.error.has_value() &&
                          (!outcome.error || *outcome.error == *e.error);
  if (outcome.status != e.status || !same_error) {
    end_deviation(std::min(run_cycles, e.cycle), 0.0, 0.0,
                  "the run ends with " + outcome_text(outcome.status, outcome.error) +
                      ", the golden with " + outcome_text(e.status, e.error));
  }
  return result;
}

}  // namespace ncsim::golden
