// Decimation for display: bounded buckets, every series' extremes kept exactly and in the
// order they occurred, the toolpath within its tolerance; seeded property tests.

#include "report/decimate.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using namespace ncsim::report;

TEST_CASE("min/max decimation keeps each series' extremes with bounded buckets") {
  std::mt19937_64 rng(15);
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t series = 1 + rng() % 4;
    const std::size_t max_buckets = 2 * (1 + rng() % 50);
    const std::size_t n = rng() % 20000;
    MinMaxDecimator d(series, max_buckets);
    std::normal_distribution<double> g(0.0, 10.0);
    std::vector<double> lo(series, std::numeric_limits<double>::infinity());
    std::vector<double> hi(series, -std::numeric_limits<double>::infinity());
    std::vector<double> row(series);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t s = 0; s < series; ++s) {
        row[s] = g(rng);
        lo[s] = std::min(lo[s], row[s]);
        hi[s] = std::max(hi[s], row[s]);
      }
      d.add(0.001 * static_cast<double>(i), row);
    }
    const Decimated out = d.finish();
    CAPTURE(trial);
    CHECK(out.t.size() <= 2 * max_buckets);
    CHECK(std::is_sorted(out.t.begin(), out.t.end()));
    REQUIRE(out.series.size() == series);
    if (n == 0) {
      CHECK(out.t.empty());
      continue;
    }
    CHECK(out.t.front() == 0.0);
    CHECK(out.t.back() == 0.001 * static_cast<double>(n - 1));
    for (std::size_t s = 0; s < series; ++s) {
      REQUIRE(out.series[s].size() == out.t.size());
      CHECK(*std::min_element(out.series[s].begin(), out.series[s].end()) == lo[s]);
      CHECK(*std::max_element(out.series[s].begin(), out.series[s].end()) == hi[s]);
    }
  }
}

TEST_CASE("a bucket's two rows are its minimum and maximum in the order they occurred") {
  MinMaxDecimator d(1, 2);
  // Four samples: width doubles to 2 at the third; buckets {5, -1} then {-7, 3}.
  for (const double v : {5.0, -1.0, -7.0, 3.0})
    d.add(0.0, std::vector<double>{v});
  Decimated out = d.finish();
  REQUIRE(out.series[0].size() == 4);
  CHECK(out.series[0] == std::vector<double>{5.0, -1.0, -7.0, 3.0});
  CHECK(d.bucket_width() == 2);
  // A fifth: merged to one bucket of 4 (min -7 then max 5? max 5 came first) and one of 1.
  d.add(1.0, std::vector<double>{0.5});
  out = d.finish();
  CHECK(out.series[0] == std::vector<double>{5.0, -7.0, 0.5});
  CHECK(out.t == std::vector<double>{0.0, 0.0, 1.0});
}

TEST_CASE("NaN is no value; a bucket without values stays NaN; wrong width throws") {
  MinMaxDecimator d(2, 4);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  d.add(0.0, std::vector<double>{nan, 1.0});
  d.add(0.1, std::vector<double>{nan, 2.0});
  const Decimated out = d.finish();
  CHECK(std::isnan(out.series[0][0]));
  CHECK(out.series[1][0] == 1.0);
  CHECK_THROWS_AS(d.add(0.2, std::vector<double>{1.0}), std::invalid_argument);
  CHECK_THROWS_AS(MinMaxDecimator(1, 3), std::invalid_argument);
}

double max_norm(const double* a, const double* b, std::size_t dims) {
  double m = 0.0;
  for (std::size_t i = 0; i < dims; ++i)
    m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

TEST_CASE("the thinned toolpath keeps both ends and every point within twice its tolerance") {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 10; ++trial) {
    const std::size_t dims = 1 + rng() % 3;
    const std::size_t max_points = 8 + rng() % 200;
    PathThinner p(dims, max_points, 1e-3);
    std::normal_distribution<double> step(0.0, 0.05);
    std::vector<double> all, pt(dims, 0.0);
    const std::size_t n = 1 + rng() % 30000;
    for (std::size_t i = 0; i < n; ++i) {
      for (double& c : pt)
        c += step(rng);
      all.insert(all.end(), pt.begin(), pt.end());
      p.add(pt);
    }
    const std::vector<double> kept = p.finish();
    CAPTURE(trial);
    REQUIRE(kept.size() % dims == 0);
    CHECK(kept.size() / dims <= max_points + 1);
    CHECK(std::equal(kept.begin(), kept.begin() + static_cast<long>(dims), all.begin()));
    CHECK(std::equal(kept.end() - static_cast<long>(dims), kept.end(),
                     all.end() - static_cast<long>(dims)));
    // Every point is within 2 tolerance of a vertex (the last kept one before it).
    for (std::size_t i = 0; i < all.size(); i += dims) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t v = 0; v < kept.size(); v += dims)
        best = std::min(best, max_norm(&all[i], &kept[v], dims));
      REQUIRE(best <= 2.0 * p.tolerance() + 1e-12);
    }
  }
}

TEST_CASE("path thinning rejects unusable settings") {
  CHECK_THROWS_AS(PathThinner(0), std::invalid_argument);
  CHECK_THROWS_AS(PathThinner(4), std::invalid_argument);
  CHECK_THROWS_AS(PathThinner(2, 3), std::invalid_argument);
  CHECK_THROWS_AS(PathThinner(2, 100, 0.0), std::invalid_argument);
}

}  // namespace
