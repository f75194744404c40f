// Path limits from axis limits: projections on lines, G00 (000 l.360), F capping, G93, E,
// centripetal limits on circles, and a seeded property test: any motion inside the path
// limits keeps every axis inside its v, a and j limits.

#include "planner/limits.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "planner/test_support.hpp"

namespace {

using namespace ncsim::planner;
using test::axis;
using test::vec;

Move line(AxisVec a, AxisVec b, double feed, SlopeType slope = SlopeType::trapez) {
  Move m;
  m.start = a;
  m.end = b;
  m.feed = feed;
  m.slope = slope;
  return m;
}

Move circle(double r, double feed) {
  Move m = line(vec(r, 0), vec(r, 0), feed);
  m.arc = Arc{0, 1, 0.0, 0.0, false, true};
  return m;
}

}  // namespace

TEST_CASE("a line along X is limited by X alone, at the programmed feed") {
  const std::array<AxisLimits, 3> ax = {axis(100, 1000, 1e5), axis(50, 500, 1e4), axis(10, 10, 10)};
  const Move m = line(vec(0, 0), vec(20, 0), 40.0);
  const PathLimits pl = path_limits(Segment::from_move(m), m, ax);
  CHECK(pl.v_max == doctest::Approx(40.0));
  CHECK(pl.limit == VelocityLimit::programmed);
  CHECK(pl.a_max == doctest::Approx(1000.0));
  CHECK(pl.d_max == doctest::Approx(1000.0));
  CHECK(pl.j_max == doctest::Approx(1e5));
}

TEST_CASE("F above what the axes allow is capped and noted") {
  const std::array<AxisLimits, 3> ax = {axis(100, 1000, 1e5), axis(100, 1000, 1e5),
                                        axis(100, 1000, 1e5)};
  const Move m = line(vec(0, 0), vec(10, 10), 500.0);
  const PathLimits pl = path_limits(Segment::from_move(m), m, ax);
  CHECK(pl.v_programmed == doctest::Approx(500.0));
  CHECK(pl.v_max == doctest::Approx(100.0 * std::sqrt(2.0)));
  CHECK(pl.feed_capped());
  CHECK(pl.a_max == doctest::Approx(1000.0 * std::sqrt(2.0)));
}

TEST_CASE("the reference velocity is an extra upper limit (000 l.75)") {
  std::array<AxisLimits, 3> ax = {axis(100, 1000, 1e5), axis(100, 1000, 1e5), axis(100, 1000, 1e5)};
  ax[0].v_reference = 60.0;
  const Move m = line(vec(0, 0), vec(10, 0), 80.0);
  const PathLimits pl = path_limits(Segment::from_move(m), m, ax);
  CHECK(pl.v_max == doctest::Approx(60.0));
  CHECK(pl.limiting_axis == 0);
}

TEST_CASE("G00: each axis at MIN(rapid, reference, max), the slowest axis sets the time") {
  std::array<AxisLimits, 3> ax = {axis(600, 1000, 1e5), axis(600, 1000, 1e5), axis(600, 1000, 1e5)};
  ax[0].v_rapid = 500.0;
  ax[0].v_reference = 400.0;  // X: 400
  ax[1].v_rapid = 100.0;      // Y: 100
  Move m = line(vec(0, 0), vec(100, 50), 0.0);
  m.rapid = true;
  const Segment seg = Segment::from_move(m);
  const PathLimits pl = path_limits(seg, m, ax);
  // X needs 100/400 = 0.25 s, Y 50/100 = 0.5 s: Y sets the time.
  CHECK(pl.v_max == doctest::Approx(seg.length() / 0.5));
  CHECK(pl.v_programmed == doctest::Approx(seg.length() / 0.5));
  CHECK_FALSE(pl.feed_capped());
}

TEST_CASE("G93: the block time gives the path velocity L / t") {
  const std::array<AxisLimits, 3> ax = {axis(100, 1000, 1e5), axis(100, 1000, 1e5),
                                        axis(100, 1000, 1e5)};
  Move m = line(vec(0, 0), vec(30, 40), 0.0);
  m.block_time = 2.0;
  const PathLimits pl = path_limits(Segment::from_move(m), m, ax);
  CHECK(pl.v_programmed == doctest::Approx(25.0));
  CHECK(pl.v_max == doctest::Approx(25.0));
}

TEST_CASE("E caps the velocity at the block end") {
  const std::array<AxisLimits, 3> ax = {axis(100, 1000, 1e5), axis(100, 1000, 1e5),
                                        axis(100, 1000, 1e5)};
  Move m = line(vec(0, 0), vec(30, 0), 50.0);
  m.end_feed = 10.0;
  const PathLimits pl = path_limits(Segment::from_move(m), m, ax);
  CHECK(pl.v_max == doctest::Approx(50.0));
  CHECK(pl.v_end == doctest::Approx(10.0));
}

TEST_CASE("a circle is limited by centripetal acceleration: v^2 / R <= 3/4 a") {
  const std::array<AxisLimits, 3> ax = {axis(1000, 1000, 1e9), axis(1000, 1000, 1e9),
                                        axis(1000, 1000, 1e9)};
  const Move m = circle(10.0, 500.0);
  // The projection at the standard share (path_limits may pick another: best_share).
  const PathLimits pl = limits_from_bounds(Segment::from_move(m).bounds(), ax, 500.0, false);
  CHECK(pl.limit == VelocityLimit::centripetal);
  CHECK(pl.v_max == doctest::Approx(std::sqrt(kCentripetalShare * 1000.0 * 10.0)));
  // What is left for the path acceleration: the tangential and the centripetal part are
  // orthogonal, so an axis sees at most sqrt(a^2 + (v^2/R)^2) <= 1000: a = sqrt(1 - 0.75^2) 1000
  // (the sum |a| + v^2/R would leave only 250).
  CHECK(pl.a_max == doctest::Approx(1000.0 * std::sqrt(1 - kCentripetalShare * kCentripetalShare)));
  CHECK(pl.d_max == doctest::Approx(pl.a_max));
}

TEST_CASE("an arc takes the centripetal share its length favours: a short arc more acceleration") {
  const std::array<AxisLimits, 3> ax = {axis(1000, 1000, 1e9), axis(1000, 1000, 1e9),
                                        axis(1000, 1000, 1e9)};
  const double r = 5.0;
  const auto arc = [&](double sweep) {
    Move m = line(vec(r, 0), vec(r * std::cos(sweep), r * std::sin(sweep)), 6000.0);
    m.arc = Arc{0, 1, 0.0, 0.0, false, false};
    return m;
  };
  const Move long_arc = circle(r, 6000.0);
  const Move short_arc = arc(0.3);
  const PathLimits pl = path_limits(Segment::from_move(long_arc), long_arc, ax);
  const PathLimits ps = path_limits(Segment::from_move(short_arc), short_arc, ax);
  CHECK(pl.limit == VelocityLimit::centripetal);
  CHECK(ps.limit == VelocityLimit::centripetal);
  // The full circle runs at its cap most of the way: a share above 3/4.
  CHECK(pl.v_max > std::sqrt(kCentripetalShare * 1000.0 * r));
  // 1.5 mm of arc is mostly ramps: a share below the circle's, more path acceleration.
  CHECK(ps.v_max < pl.v_max);
  CHECK(ps.a_max > pl.a_max);
}

TEST_CASE("a small circle under a jerk-limited slope is limited by the change of curvature") {
  const std::array<AxisLimits, 3> ax = {axis(1000, 1e6, 1e5), axis(1000, 1e6, 1e5),
                                        axis(1000, 1e6, 1e5)};
  const Move m = circle(1.0, 500.0);
  const PathLimits pl = path_limits(Segment::from_move(m), m, ax);
  CHECK(pl.limit == VelocityLimit::curvature_jerk);
  // |x'''| = 1 / R^2 on a circle: v^3 / R^2 <= j / 2.
  CHECK(pl.v_max == doctest::Approx(std::cbrt(kCurvatureJerkShare * 1e5)));
  Move step = m;
  step.slope = SlopeType::step;
  const PathLimits ps = path_limits(Segment::from_move(step), step, ax);
  CHECK(ps.limit != VelocityLimit::curvature_jerk);
  CHECK(std::isinf(ps.j_max));
}

TEST_CASE("too few axis limits for a segment is API misuse") {
  const std::array<AxisLimits, 2> ax = {axis(100, 1000, 1e5), axis(100, 1000, 1e5)};
  const Move m = line(vec(0, 0), vec(1, 0), 10.0);
  CHECK_THROWS_AS(path_limits(Segment::from_move(m), m, ax), std::invalid_argument);
}

TEST_CASE("property: any motion inside the path limits keeps every axis inside its limits") {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto range = [&](double lo, double hi) { return lo * std::pow(hi / lo, u(rng)); };
  int curved = 0;
  int plane_circles = 0;
  for (int n = 0; n < 300; ++n) {
    std::array<AxisLimits, 4> ax{};
    for (auto& a : ax) {
      a = axis(range(10, 1000), range(100, 1e4), range(1e3, 1e6));
      a.d_max = range(100, 1e4);
    }
    Move m;
    m.axis_count = 4;
    m.feed = range(1, 2000);
    m.slope = n % 3 == 0 ? SlopeType::step : SlopeType::trapez;
    for (std::size_t i = 0; i < 4; ++i) {
      m.start[i] = range(1, 100) * (u(rng) - 0.5);
      m.end[i] = range(1, 100) * (u(rng) - 0.5);
    }
    if (n % 2 == 0) {
      const double r = range(0.5, 50);
      const double a0 = 6.28 * u(rng);
      const double a1 = 6.28 * u(rng);
      m.arc = Arc{0,          1,    m.start[0] - r * std::cos(a0), m.start[1] - r * std::sin(a0),
                  n % 4 == 0, false};
      m.end[0] = m.arc->centre_1 + r * std::cos(a1);
      m.end[1] = m.arc->centre_2 + r * std::sin(a1);
      ++curved;
      if (n % 4 == 2) {  // a plane circle: the orthogonal jerk bound (circle_jerk) applies
        m.end[2] = m.start[2];
        m.end[3] = m.start[3];
        ++plane_circles;
      }
    }
    const Segment seg = Segment::from_move(m);
    const PathLimits pl = path_limits(seg, m, ax);
    REQUIRE(pl.v_max > 0.0);
    REQUIRE(pl.a_max > 0.0);
    REQUIRE(pl.d_max > 0.0);
    REQUIRE(pl.j_max > 0.0);
    for (int k = 0; k <= 50; ++k) {
      const PathPoint p = seg.at(seg.length() * k / 50.0);
      // Extreme corners of the allowed (v, a, j) box.
      for (const double v : {pl.v_max, 0.9 * pl.v_max, 0.5 * pl.v_max}) {
        for (const double a : {pl.a_max, -pl.d_max}) {
          for (const double j : {1.0, -1.0}) {
            const double jp = std::isinf(pl.j_max) ? 0.0 : j * pl.j_max;
            for (std::size_t i = 0; i < 4; ++i) {
              const double vi = p.d1[i] * v;
              const double ai = p.d2[i] * v * v + p.d1[i] * a;
              const double ji = p.d3[i] * v * v * v + 3 * p.d2[i] * v * a + p.d1[i] * jp;
              CHECK(std::abs(vi) <= std::min(ax[i].v_max, ax[i].v_reference) * (1 + 1e-9));
              // Speeding up (a_i along v_i) is bounded by A+, slowing down by A-.
              const double lim = ai * vi >= 0.0 ? ax[i].a_max : ax[i].d_max;
              CHECK(std::abs(ai) <= lim * (1 + 1e-9) + 1e-9);
              if (!std::isinf(pl.j_max)) CHECK(std::abs(ji) <= ax[i].j_max * (1 + 1e-9));
            }
          }
        }
      }
    }
  }
  CHECK(curved == 150);
  CHECK(plane_circles == 75);
}
