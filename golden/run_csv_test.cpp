#include <doctest/doctest.h>

#include <sstream>

#include "golden/golden.hpp"
#include "golden/test_support.hpp"

namespace ncsim::golden {
namespace {

TEST_CASE("the run CSV reader gives the head, one row per cycle and the closing error") {
  std::istringstream in(test::csv({{10, 3}, {20, 2}}, "# error: p.nc:20:1: error: x [NC6001]\n"));
  RunCsv csv(in);
  CHECK(csv.program() == "p.nc");
  CHECK(csv.machine() == "portal_3x");
  CHECK(csv.cycle_us() == 1000);
  CHECK(csv.columns() == std::vector<std::string>{"X", "Y"});
  Row row;
  std::vector<std::uint64_t> cycles;
  std::vector<std::uint64_t> lines;
  while (csv.next(row)) {
    cycles.push_back(row.cycle);
    lines.push_back(row.line);
    CHECK(row.values[0] == doctest::Approx(0.5 * static_cast<double>(row.cycle)));
  }
  CHECK(cycles == std::vector<std::uint64_t>{1, 2, 3, 4, 5});
  CHECK(lines == std::vector<std::uint64_t>{10, 10, 10, 20, 20});
  CHECK(csv.error_text() == "p.nc:20:1: error: x [NC6001]");
}

TEST_CASE("the run CSV reader refuses times off the cycle grid, rows out of order and short rows") {
  const std::string head = "# cycle: 0.001 s\nt,line,X\n";
  Row row;
  {
    std::istringstream in(head + "0.0015,1,0\n");
    RunCsv csv(in);
    CHECK_THROWS_WITH_AS(csv.next(row), doctest::Contains("not a whole cycle"), std::runtime_error);
  }
  {
    std::istringstream in(head + "0.002,1,0\n0.001,1,0\n");
    RunCsv csv(in);
    CHECK(csv.next(row));
    CHECK_THROWS_WITH_AS(csv.next(row), doctest::Contains("out of order"), std::runtime_error);
  }
  {
    std::istringstream in(head + "0.001,1\n");
    RunCsv csv(in);
    CHECK_THROWS_AS(csv.next(row), std::runtime_error);
  }
  {
    std::istringstream in("t,line,X\n");
    CHECK_THROWS_WITH_AS(RunCsv{in}, doctest::Contains("cycle"), std::runtime_error);
  }
}

TEST_CASE("an empty CSV is a run that wrote nothing") {
  std::istringstream in("");
  RunCsv csv(in);
  Row row;
  CHECK(csv.columns().empty());
  CHECK_FALSE(csv.next(row));
}

TEST_CASE("an error diagnostic gives its id and line; a message without position line 0") {
  const auto e =
      parse_error("laser.nc:24:5: error: not supported: #SYNC IN [NC6001]\nN240 #SYNC IN\n    ^\n");
  REQUIRE(e);
  CHECK(e->id == "NC6001");
  CHECK(e->line == 24);
  CHECK(e->text == "laser.nc:24:5: error: not supported: #SYNC IN [NC6001]");
  const auto bare = parse_error("ncsim: error: the interpolator stopped\n");
  REQUIRE(bare);
  CHECK(bare->id == "-");
  CHECK(bare->line == 0);
  const auto later = parse_error("audit: ok\nsub.nc:7:1: error: soft limit [20008]\n");
  REQUIRE(later);
  CHECK(later->id == "20008");
  CHECK(later->line == 7);
  CHECK_FALSE(parse_error("audit: ok\n"));
}

TEST_CASE("times are exact decimals of whole cycles") {
  CHECK(time_text(12345, 1000) == "12.345");
  CHECK(time_text(0, 1000) == "0");
  CHECK(time_text(3, 250) == "0.00075");
  CHECK(time_text(4000, 250) == "1");
  CHECK(time_text(30000001, 1000) == "30000.001");
}

}  // namespace
}  // namespace ncsim::golden
