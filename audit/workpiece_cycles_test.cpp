// The time per workpiece (audit/workpiece_cycles.hpp) on phase sequences: rows split at each
// #SYNC IN, each cycle counted once, sums adding up to the run, workpieces per minute, a run
// ending mid-workpiece, and a seeded property over random sequences.

#include "audit/workpiece_cycles.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using ncsim::audit::append_json;
using ncsim::audit::WorkpieceCycle;
using ncsim::audit::WorkpieceCycles;
using ncsim::audit::WorkpieceSummary;
using ncsim::tracking::SyncPhase;

constexpr double kT = 0.001;

void feed(WorkpieceCycles& w, SyncPhase p, int cycles, std::uint64_t workpiece = 0) {
  for (int i = 0; i < cycles; ++i)
    w.add(p, workpiece);
}

// One workpiece: wait, latch, catch up, machine, leave, depart, move off the belt.
void workpiece(WorkpieceCycles& w, std::uint64_t n, int wait, int machine) {
  feed(w, SyncPhase::waiting, wait);
  feed(w, SyncPhase::latched, 2, n);
  feed(w, SyncPhase::catching_up, 300, n);
  feed(w, SyncPhase::tracking, machine, n);
  feed(w, SyncPhase::leaving, 1, n);
  feed(w, SyncPhase::departing, 200, n);
  feed(w, SyncPhase::off, 50, n);
}

}  // namespace

TEST_CASE("workpiece cycles: one row per #SYNC IN, each phase in its column, totals add up") {
  std::vector<WorkpieceCycle> rows;
  WorkpieceCycles w(kT, [&](const WorkpieceCycle& r) { rows.push_back(r); });
  feed(w, SyncPhase::off, 700);  // lead-in: start the belt, position
  workpiece(w, 7, 400, 2000);
  workpiece(w, 8, 100, 2000);
  workpiece(w, 9, 100, 2000);
  const auto s = w.finish();
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].index == 1);
  CHECK(rows[0].workpiece == 7);
  CHECK(rows[2].workpiece == 9);
  CHECK(rows[0].t_start == doctest::Approx(0.7));
  CHECK(rows[0].waiting == doctest::Approx(0.4));
  CHECK(rows[0].catch_up == doctest::Approx(0.302));
  CHECK(rows[0].machining == doctest::Approx(2.0));
  CHECK(rows[0].desync == doctest::Approx(0.201));
  CHECK(rows[0].off_belt == doctest::Approx(0.05));
  CHECK(rows[0].total == doctest::Approx(0.4 + 0.302 + 2.0 + 0.201 + 0.05));
  CHECK(rows[1].t_start == doctest::Approx(0.7 + rows[0].total));
  for (const auto& r : rows)
    CHECK(r.complete);
  CHECK(s.workpieces == 3);
  CHECK(s.complete == 3);
  CHECK(s.lead_in == doctest::Approx(0.7));
  const double cycles = 700 + (400 + 2553) + 2 * (100 + 2553);
  CHECK(s.lead_in + s.sum.total == doctest::Approx(cycles * kT));
  CHECK(s.total_min == doctest::Approx(rows[1].total));
  CHECK(s.total_max == doctest::Approx(rows[0].total));
  CHECK(s.per_minute == doctest::Approx(60.0 * 3.0 / s.sum.total));
}

TEST_CASE("workpiece cycles: a run ending while machining leaves an incomplete last row") {
  std::vector<WorkpieceCycle> rows;
  WorkpieceCycles w(kT, [&](const WorkpieceCycle& r) { rows.push_back(r); });
  workpiece(w, 1, 10, 100);
  feed(w, SyncPhase::waiting, 20);
  feed(w, SyncPhase::catching_up, 30, 2);
  feed(w, SyncPhase::tracking, 40, 2);
  const auto s = w.finish();
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].complete);
  CHECK_FALSE(rows[1].complete);
  CHECK(rows[1].machining == doctest::Approx(0.04));
  CHECK(s.complete == 1);
  CHECK(s.per_minute == doctest::Approx(60.0 / rows[0].total));
}

TEST_CASE("workpiece cycles: an interruptible departure cut short by the next #SYNC IN") {
  std::vector<WorkpieceCycle> rows;
  WorkpieceCycles w(kT, [&](const WorkpieceCycle& r) { rows.push_back(r); });
  feed(w, SyncPhase::waiting, 5);
  feed(w, SyncPhase::catching_up, 5, 1);
  feed(w, SyncPhase::tracking, 5, 1);
  feed(w, SyncPhase::leaving, 5, 1);
  feed(w, SyncPhase::waiting, 5);  // the next #SYNC IN from the moving state
  feed(w, SyncPhase::tracking, 5, 2);
  const auto s = w.finish();
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].desync == doctest::Approx(0.005));
  CHECK(rows[0].total == doctest::Approx(0.02));
  CHECK(rows[1].waiting == doctest::Approx(0.005));
  CHECK(s.lead_in == 0.0);
}

TEST_CASE("workpiece cycles: no #SYNC IN is all lead-in, no rows, 0 per minute") {
  int rows = 0;
  WorkpieceCycles w(kT, [&](const WorkpieceCycle&) { ++rows; });
  feed(w, SyncPhase::off, 1234);
  const auto s = w.finish();
  CHECK(rows == 0);
  CHECK(s.workpieces == 0);
  CHECK(s.lead_in == doctest::Approx(1.234));
  CHECK(s.per_minute == 0.0);
  CHECK_THROWS_AS(WorkpieceCycles(0.0), std::invalid_argument);
}

TEST_CASE("workpiece cycles (seeded property): every cycle is counted once, in one row") {
  std::mt19937_64 rng(20261123);
  for (int run = 0; run < 200; ++run) {
    double rows_total = 0.0;
    std::uint64_t rows = 0;
    WorkpieceCycles w(kT, [&](const WorkpieceCycle& r) {
      ++rows;
      CHECK(r.total ==
            doctest::Approx(r.waiting + r.catch_up + r.machining + r.desync + r.off_belt));
      rows_total += r.total;
    });
    std::uniform_int_distribution<int> phase(0, 6), len(1, 50);
    std::uint64_t cycles = 0;
    for (int k = 0; k < 40; ++k) {
      const int n = len(rng);
      feed(w, static_cast<SyncPhase>(phase(rng)), n, 1);
      cycles += static_cast<std::uint64_t>(n);
    }
    const auto s = w.finish();
    CHECK(s.workpieces == rows);
    CHECK(s.lead_in + rows_total == doctest::Approx(static_cast<double>(cycles) * kT));
    CHECK(s.sum.total == doctest::Approx(rows_total));
  }
}

TEST_CASE("workpiece cycles: the JSON of a row and of the summary, exact numbers, null for inf") {
  WorkpieceCycle r;
  r.index = 2;
  r.workpiece = 7;
  r.t_start = 0.1;
  r.waiting = 0.25;
  r.catch_up = 1.0 / 3.0;
  r.machining = 6.0;
  r.total = 0.25 + 1.0 / 3.0 + 6.0;
  r.complete = true;
  std::string s;
  append_json(s, r);
  CHECK(s ==
        "{\"index\":2,\"workpiece\":7,\"t_start_s\":0.1,\"waiting_s\":0.25,"
        "\"catch_up_s\":0.3333333333333333,\"machining_s\":6,\"desync_s\":0,\"off_belt_s\":0,"
        "\"total_s\":6.583333333333333,\"complete\":true}");
  WorkpieceSummary w;
  w.workpieces = 3;
  w.complete = 2;
  w.lead_in = 0.5;
  w.sum = r;
  w.total_min = 5.0;
  w.total_max = 6.583333333333333;
  w.per_minute = std::numeric_limits<double>::infinity();
  s.clear();
  append_json(s, w);
  CHECK(s ==
        "{\"workpieces\":3,\"complete\":2,\"lead_in_s\":0.5,\"waiting_s\":0.25,"
        "\"catch_up_s\":0.3333333333333333,\"machining_s\":6,\"desync_s\":0,\"off_belt_s\":0,"
        "\"total_s\":6.583333333333333,\"total_min_s\":5,\"total_max_s\":6.583333333333333,"
        "\"per_minute\":null}");
}
