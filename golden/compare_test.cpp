#include <doctest/doctest.h>

#include <sstream>

#include "golden/golden.hpp"
#include "golden/test_support.hpp"

namespace ncsim::golden {
namespace {

std::string bless(const std::string& csv_text, const Outcome& outcome = {}) {
  std::istringstream in(csv_text);
  RunCsv csv(in);
  std::ostringstream out;
  write_golden(csv, outcome, settings_for(csv.cycle_us(), std::nullopt), out);
  return out.str();
}

Comparison check(const std::string& csv_text, const std::string& golden,
                 const Outcome& outcome = {}) {
  std::istringstream in(csv_text);
  RunCsv csv(in);
  std::istringstream a(golden);
  std::istringstream b(golden);
  return compare(csv, outcome, a, b);
}

// Replaces the X value of the CSV row of cycle k (1 ms cycle) by `x`.
std::string with_x(std::string csv, std::uint64_t k, std::uint64_t line, double x) {
  const std::string key = "\n" + std::to_string(k) + "e-3," + std::to_string(line) + ",";
  const std::size_t at = csv.find(key);
  REQUIRE(at != std::string::npos);
  const std::size_t start = at + key.size();
  const std::size_t end = csv.find(',', start);
  csv.replace(start, end - start, std::to_string(x));
  return csv;
}

TEST_CASE("a run compares equal to its own golden") {
  const std::string csv = test::csv({{10, 70}, {20, 1}, {30, 40}});
  const Comparison c = check(csv, bless(csv));
  CHECK(c.ok());
  CHECK(c.rows == 5);  // samples at 50 and 100, block ends at 70, 71, 111
  CHECK(c.cycles == 111);
}

TEST_CASE("a position outside its tolerance is reported with time, line, axis, size, tolerance") {
  const std::string csv = test::csv({{10, 70}, {20, 40}});
  const std::string golden = bless(csv);
  // Cycle 50 is a sample row: X = 25 there.
  const Comparison c = check(with_x(csv, 50, 10, 25.0003), golden);
  REQUIRE(c.count == 1);
  const Deviation& d = c.deviations.front();
  CHECK(d.kind == Deviation::Kind::position);
  CHECK(d.cycle == 50);
  CHECK(d.line == 10);
  CHECK(d.axis == "X");
  CHECK(d.size == doctest::Approx(0.0003));
  CHECK(d.tolerance == 1e-4);
  CHECK(d.file_line > 0);
  CHECK(std::string(id_of(d.kind)) == "NC8001");
  // Within tolerance, and between golden rows: no deviation.
  CHECK(check(with_x(csv, 50, 10, 25.00009), golden).ok());
  CHECK(check(with_x(csv, 51, 10, 99.0), golden).ok());
}

TEST_CASE("a block end may move by tolerance_cycles, not further") {
  const std::string golden = bless(test::csv({{10, 70}, {20, 40}}));
  // Same positions, the line changes one cycle late: within tolerance.
  CHECK(check(test::csv({{10, 71}, {20, 39}}), golden).ok());
  const Comparison c = check(test::csv({{10, 72}, {20, 38}}), golden);
  REQUIRE(c.count == 1);
  CHECK(c.deviations.front().kind == Deviation::Kind::block);
  CHECK(c.deviations.front().size == 2.0);
  CHECK(c.deviations.front().cycle == 70);
  CHECK(c.deviations.front().line == 10);
}

TEST_CASE("a block more or less parts the sequence; reported once, where it parts") {
  const std::string golden = bless(test::csv({{10, 70}, {20, 40}, {30, 10}}));
  const Comparison c = check(test::csv({{10, 70}, {25, 5}, {20, 35}, {30, 10}}), golden);
  REQUIRE(c.count == 1);
  CHECK(c.deviations.front().kind == Deviation::Kind::block);
  CHECK(c.deviations.front().cycle == 75);
  CHECK(c.deviations.front().what.find("line 25") != std::string::npos);
  const Comparison less = check(test::csv({{10, 70}, {20, 50}}), golden);
  bool block = false;
  for (const auto& d : less.deviations)
    block = block || d.kind == Deviation::Kind::block;
  CHECK(block);
}

TEST_CASE("a longer or shorter run, another status or another error is an end deviation") {
  const std::string golden = bless(test::csv({{10, 70}, {20, 40}}));
  const Comparison longer = check(test::csv({{10, 70}, {20, 45}}), golden);
  CHECK_FALSE(longer.ok());
  bool end = false;
  for (const auto& d : longer.deviations)
    end = end || (d.kind == Deviation::Kind::end && d.size == 5.0);
  CHECK(end);

  Outcome failed;
  failed.status = 1;
  failed.error = RunError{"NC6001", 20, "x"};
  const Comparison status = check(test::csv({{10, 70}, {20, 40}}), golden, failed);
  REQUIRE(status.count == 1);
  CHECK(status.deviations.front().kind == Deviation::Kind::end);
  CHECK(status.deviations.front().what.find("NC6001") != std::string::npos);

  const std::string error_golden = bless(test::csv({{10, 70}}), failed);
  CHECK(check(test::csv({{10, 70}}), error_golden, failed).ok());
  Outcome other = failed;
  other.error->line = 21;
  CHECK_FALSE(check(test::csv({{10, 70}}), error_golden, other).ok());
  other = failed;
  other.error->id = "NC6002";
  CHECK_FALSE(check(test::csv({{10, 70}}), error_golden, other).ok());
}

TEST_CASE("other columns or another cycle are head deviations, reported first") {
  const std::string golden = bless(test::csv({{10, 70}}));
  std::string csv = test::csv({{10, 70}});
  csv.replace(csv.find("t,line,X,Y"), 10, "t,line,X,Z");
  const Comparison c = check(csv, golden);
  REQUIRE_FALSE(c.ok());
  CHECK(c.deviations.front().kind == Deviation::Kind::head);
  CHECK(c.deviations.front().cycle == 0);
}

TEST_CASE("deviations are listed earliest first, at most kListed, all counted") {
  const std::string csv = test::csv({{10, 2000}});
  const std::string golden = bless(csv);
  std::string moved = csv;
  for (std::uint64_t k = 1000; k >= 50; k -= 50)
    moved = with_x(moved, k, 10, -1.0);
  const Comparison c = check(moved, golden);
  CHECK(c.count == 20);
  REQUIRE(c.deviations.size() == Comparison::kListed);
  CHECK(c.deviations.front().cycle == 50);
  for (std::size_t i = 1; i < c.deviations.size(); ++i)
    CHECK(c.deviations[i - 1].cycle < c.deviations[i].cycle);
}

TEST_CASE("a golden whose sample rows were deleted does not pass") {
  const std::string csv = test::csv({{10, 70}, {20, 40}});
  std::string golden = bless(csv);
  // Delete every sample row (`s ...`), keep the block ends.
  std::string only_blocks;
  std::istringstream in(golden);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("s ", 0) != 0) only_blocks += line + '\n';
  REQUIRE(only_blocks != golden);
  const Comparison c = check(csv, only_blocks);
  REQUIRE_FALSE(c.ok());
  CHECK(c.deviations.front().kind == Deviation::Kind::position);
  CHECK(c.deviations.front().cycle == 50);
  CHECK(c.deviations.front().what.find("the golden has no row at t=0.05 s") != std::string::npos);
}

TEST_CASE("a sample row with a wrong line number does not pass") {
  const std::string csv = test::csv({{10, 70}, {20, 40}});
  std::string golden = bless(csv);
  const std::size_t at = golden.find("\ns 0.05 10 ");
  REQUIRE(at != std::string::npos);
  golden.replace(at, 11, "\ns 0.05 30 ");
  const Comparison c = check(csv, golden);
  REQUIRE(c.count == 1);
  CHECK(c.deviations.front().kind == Deviation::Kind::block);
  CHECK(c.deviations.front().cycle == 50);
  CHECK(c.deviations.front().line == 30);
  CHECK(c.deviations.front().what.find("line 30 in the golden, line 10 in the run") !=
        std::string::npos);
}

TEST_CASE("a sample row's line may be a neighbour block's when its end moved within tolerance") {
  // Cycle 50 is the last of line 10 in the golden and the first of line 20 in the run.
  const std::string golden = bless(test::csv({{10, 50}, {20, 60}}));
  CHECK(check(test::csv({{10, 49}, {20, 61}}), golden).ok());
}

}  // namespace
}  // namespace ncsim::golden
