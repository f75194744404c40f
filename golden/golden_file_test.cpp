#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>

#include "golden/golden.hpp"
#include "golden/test_support.hpp"

namespace ncsim::golden {
namespace {

std::string bless(const std::string& csv_text, const Outcome& outcome = {},
                  const std::optional<Settings>& kept = std::nullopt) {
  std::istringstream in(csv_text);
  RunCsv csv(in);
  std::ostringstream out;
  write_golden(csv, outcome, settings_for(csv.cycle_us(), kept), out);
  return out.str();
}

std::vector<GoldenRow> rows_of(const std::string& golden, End* end = nullptr) {
  std::istringstream in(golden);
  GoldenReader r(in);
  std::vector<GoldenRow> rows;
  GoldenRow row;
  while (r.next(row))
    rows.push_back(row);
  if (end) *end = r.end();
  return rows;
}

TEST_CASE("a golden keeps a sample every sample_cycles cycles and the last cycle of every block") {
  // Blocks end at cycles 30, 31, 120, 130; samples at 50 and 100 (1 ms cycle: 50 cycles).
  const std::string g = bless(test::csv({{10, 30}, {20, 1}, {30, 89}, {40, 10}}));
  End end;
  const auto rows = rows_of(g, &end);
  std::vector<std::uint64_t> cycles;
  std::vector<bool> kinds;
  for (const auto& r : rows) {
    cycles.push_back(r.row.cycle);
    kinds.push_back(r.block_end);
  }
  CHECK(cycles == std::vector<std::uint64_t>{30, 31, 50, 100, 120, 130});
  CHECK(kinds == std::vector<bool>{true, true, false, false, true, true});
  CHECK(rows[2].row.line == 30);
  CHECK(rows[2].row.values[0] == doctest::Approx(25.0));
  CHECK(end.cycle == 130);
  CHECK(end.status == 0);
  CHECK_FALSE(end.error);
}

TEST_CASE("a golden is the same bytes for the same run, readable text with exact times") {
  const std::string csv = test::csv({{10, 60}, {20, 45}});
  const std::string g = bless(csv);
  CHECK(g == bless(csv));
  CHECK(g.find("\ns 0.05 10 25 87.5\n") != std::string::npos);
  CHECK(g.find("\nb 0.06 10 30 85\n") != std::string::npos);
  CHECK(g.find("\nend t=0.105 cycles=105 status=0\n") != std::string::npos);
  CHECK(g.find("\ntolerance X=0.0001 Y=0.0001\n") != std::string::npos);
}

TEST_CASE("values are rounded to 1e-6 of their unit and never print as -0") {
  const std::string csv = "# machine: m\n# cycle: 0.001 s\nt,line,X,Y\n0.001,1,-1e-12,1.23456789\n";
  const std::string g = bless(csv);
  CHECK(g.find("\nb 0.001 1 0 1.234568\n") != std::string::npos);
}

TEST_CASE("a run that stops with an error keeps the error's id, line and time") {
  Outcome o;
  o.status = 1;
  o.error = RunError{"NC6001", 24, "p.nc:24:1: error: not supported: #SYNC IN [NC6001]"};
  const std::string g = bless(test::csv({{10, 7}}), o);
  CHECK(g.find("\nend t=0.007 cycles=7 status=1 error=NC6001 line=24\n"
               "# p.nc:24:1: error: not supported: #SYNC IN [NC6001]\n") != std::string::npos);
  End end;
  rows_of(g, &end);
  CHECK(end.status == 1);
  REQUIRE(end.error);
  CHECK(end.error->id == "NC6001");
  CHECK(end.error->line == 24);
}

TEST_CASE("a run that wrote nothing has a golden of its end alone") {
  Outcome o;
  o.status = 1;
  o.error = RunError{"20008", 3, "p.nc:3:1: error: no feed [20008]"};
  const std::string g = bless("", o);
  End end;
  CHECK(rows_of(g, &end).empty());
  CHECK(end.cycle == 0);
  CHECK(end.status == 1);
}

TEST_CASE("the sample interval follows the cycle; a kept golden's settings survive a re-bless") {
  CHECK(settings_for(1000, std::nullopt).sample_cycles == 50);
  CHECK(settings_for(250, std::nullopt).sample_cycles == 200);
  CHECK(settings_for(100000, std::nullopt).sample_cycles == 1);
  Settings kept;
  kept.sample_cycles = 7;
  kept.tolerance_cycles = 3;
  kept.axis_tolerance = {{"X", 0.01}};
  const std::string g = bless(test::csv({{10, 20}}), {}, kept);
  std::istringstream in(g);
  GoldenReader r(in);
  CHECK(r.head().settings.sample_cycles == 7);
  CHECK(r.head().settings.tolerance_cycles == 3);
  CHECK(r.head().settings.tolerance_for("X") == 0.01);
  CHECK(r.head().settings.tolerance_for("Y") == 1e-4);
  CHECK(r.head().machine == "portal_3x");
  CHECK(r.head().cycle_us == 1000);
}

TEST_CASE("a malformed golden is a FormatError naming its line") {
  const std::string good = bless(test::csv({{10, 3}}));
  const auto error_line = [](const std::string& text) -> std::size_t {
    try {
      rows_of(text);
    } catch (const FormatError& e) {
      return e.file_line();
    }
    return 0;
  };
  // No end record.
  const std::string no_end = good.substr(0, good.find("end "));
  CHECK(error_line(no_end) > 0);
  // A row with a value missing, on the line of the first row.
  std::string short_row = good;
  const std::size_t at = short_row.find("\nb 0.003 10 ");
  REQUIRE(at != std::string::npos);
  short_row.replace(at, std::string("\nb 0.003 10 1.5 99.25").size(), "\nb 0.003 10 1.5");
  const std::size_t row_line =
      static_cast<std::size_t>(std::count(good.begin(), good.begin() + at + 1, '\n')) + 1;
  CHECK(error_line(short_row) == row_line);
  // Unknown head key, a time off the cycle grid, rows out of order, an unknown format.
  CHECK(error_line("golden 1\nspeed 3\n") == 2);
  std::string off_grid = good;
  off_grid.replace(off_grid.find("b 0.003"), 7, "b 0.0035");
  CHECK(error_line(off_grid) > 0);
  CHECK(error_line("golden 2\n") == 1);
  std::string extra = good + "s 9 1 0 0\n";
  CHECK(error_line(extra) > 0);
}

TEST_CASE("an empty golden, a repeated head record: FormatErrors at the right line") {
  const auto error_of = [](const std::string& text) -> std::pair<std::size_t, std::string> {
    try {
      rows_of(text);
    } catch (const FormatError& e) {
      return {e.file_line(), e.what()};
    }
    return {0, ""};
  };
  const auto empty = error_of("");
  CHECK(empty.first == 1);
  CHECK(empty.second.find("the file is empty") != std::string::npos);
  CHECK(error_of("# only a comment\n\n").second.find("the file is empty") != std::string::npos);
  const std::string good = bless(test::csv({{10, 3}}));
  std::string twice = good;
  twice.insert(twice.find("program "), "golden 1\n");
  const std::size_t second = static_cast<std::size_t>(
      std::count(twice.begin(), twice.begin() + static_cast<long>(twice.find("program ")), '\n'));
  const auto dup = error_of(twice);
  CHECK(dup.first == second);
  CHECK(dup.second.find("'golden' given twice (first on line ") != std::string::npos);
  // A head value that is wrong only in view of the others: at the line that holds it.
  std::string zero_cycle = good;
  zero_cycle.replace(zero_cycle.find("cycle_us 1000"), 13, "cycle_us 0");
  const std::size_t cycle_line =
      static_cast<std::size_t>(
          std::count(zero_cycle.begin(),
                     zero_cycle.begin() + static_cast<long>(zero_cycle.find("cycle_us")), '\n')) +
      1;
  CHECK(error_of(zero_cycle).first == cycle_line);
  std::string no_tol = good;
  const std::size_t tol_at = no_tol.find("tolerance X=");
  no_tol.replace(no_tol.find(" Y=", tol_at), std::string(" Y=0.0001").size(), "");
  const std::size_t tol_line =
      static_cast<std::size_t>(
          std::count(no_tol.begin(), no_tol.begin() + static_cast<long>(tol_at), '\n')) +
      1;
  CHECK(error_of(no_tol).first == tol_line);
}

}  // namespace
}  // namespace ncsim::golden
