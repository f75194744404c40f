// The belt velocity search of sweep and line sweep: the answer of a known threshold to the
// tolerance, the same candidates whatever the threads, round 0's stop and LO failing.

#include "cli/sweep_search.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <vector>

namespace {

using namespace ncsim::cli;

// The search on "passes iff v <= limit", every candidate recorded in order.
SweepBounds search(const SweepRange& r, double limit, std::vector<double>& tried, unsigned jobs) {
  return sweep_search(r, [&](unsigned, const std::vector<double>& vs) {
    const std::vector<double> got =
        evaluate_all<double>(vs, jobs, [](double v) { return v; });  // in the order of vs
    tried.insert(tried.end(), got.begin(), got.end());
    std::vector<bool> passed;
    for (const double v : vs)
      passed.push_back(v <= limit);
    return std::optional<std::vector<bool>>(passed);
  });
}

TEST_CASE("the search brackets a known limit within the tolerance") {
  for (const double limit : {50.0, 123.4, 399.9}) {
    std::vector<double> tried;
    const SweepBounds b = search({10.0, 400.0, 0.5, 3}, limit, tried, 2);
    CHECK_FALSE(b.stopped);
    CHECK_FALSE(b.none);
    CHECK(b.best <= limit);
    CHECK(b.fail > limit);
    CHECK(b.fail - b.best <= 0.5);
  }
}

TEST_CASE("the candidates depend on the range, never on the threads") {
  std::vector<double> one, four;
  search({0.0, 1000.0, 1.0, 5}, 321.0, one, 1);
  search({0.0, 1000.0, 1.0, 5}, 321.0, four, 4);
  CHECK(one == four);
  CHECK(one.front() == 0.0);
  CHECK(one[1] == 1000.0);
}

TEST_CASE("HI passing, LO failing and a stopped round") {
  std::vector<double> tried;
  const SweepBounds all = search({10.0, 20.0, 1.0, 3}, 25.0, tried, 1);
  CHECK(all.best == 20.0);
  CHECK(std::isinf(all.fail));
  CHECK(tried.size() == 2);  // round 0 only
  CHECK(search({10.0, 20.0, 1.0, 3}, 5.0, tried, 1).none);
  const SweepBounds stopped = sweep_search(
      {10.0, 20.0, 1.0, 3}, [](unsigned, const std::vector<double>&) { return std::nullopt; });
  CHECK(stopped.stopped);
}

TEST_CASE("the range and tolerance are checked with their ids") {
  std::ostringstream err;
  CHECK_FALSE(parse_sweep_range("20:10", 1.0, 3, "line sweep", err));
  CHECK(err.str().find("line sweep: --belt-velocity '20:10'") != std::string::npos);
  CHECK(err.str().find("[NC9120]") != std::string::npos);
  CHECK_FALSE(parse_sweep_range("10:20", 0.0, 3, "sweep", err));
  CHECK(err.str().find("[NC9121]") != std::string::npos);
  const auto r = parse_sweep_range("10:20.5", 2.0, 0, "sweep", err);
  REQUIRE(r);
  CHECK(r->hi == 20.5);
  CHECK(r->grid == 1);
}

}  // namespace
