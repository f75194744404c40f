// #CAXTRACK (isg-language.md §5.7, PROG-207450507; seed 004 §4.10): tangent angle, OFFSET,
// ROTMODE, ANGLIMIT at block joints, arcs and splines (docs/caxtrack.md).

#include "tracking/caxtrack.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

namespace {

using ncsim::planner::Move;
using ncsim::tracking::CaxTracker;
using ncsim::tracking::CaxTrackParams;

constexpr int kX = 0, kY = 1, kC = 3;

Move line(double x0, double y0, double x1, double y1) {
  Move m;
  m.axis_count = 4;
  m.path_axes = 0b111;
  m.start[kX] = x0;
  m.start[kY] = y0;
  m.end[kX] = x1;
  m.end[kY] = y1;
  m.feed = 100.0;
  return m;
}

Move spline(std::array<double, 4> xs, std::array<double, 4> ys) {
  Move m = line(xs[0], ys[0], xs[3], ys[3]);
  auto c = std::make_shared<ncsim::planner::SplineControl>();
  c->c1[kX] = xs[1];
  c->c2[kX] = xs[2];
  c->c1[kY] = ys[1];
  c->c2[kY] = ys[2];
  m.spline = std::move(c);
  return m;
}

double bezier(const Move& m, std::size_t i, double u) {
  const double w = 1.0 - u;
  return w * w * w * m.start[i] + 3 * w * w * u * m.spline->c1[i] +
         3 * w * u * u * m.spline->c2[i] + u * u * u * m.end[i];
}

double d1(const Move& m, std::size_t i, double u) {
  const double w = 1.0 - u;
  return 3 *
         (w * w * (m.spline->c1[i] - m.start[i]) + 2 * w * u * (m.spline->c2[i] - m.spline->c1[i]) +
          u * u * (m.end[i] - m.spline->c2[i]));
}

}  // namespace

TEST_CASE("the tangent angle is atan2 of the XY direction in degrees; no XY motion has none") {
  CHECK(*ncsim::tracking::tangent_angle(1.0, 0.0) == doctest::Approx(0.0));
  CHECK(*ncsim::tracking::tangent_angle(0.0, 2.0) == doctest::Approx(90.0));
  CHECK(*ncsim::tracking::tangent_angle(-1.0, 0.0) == doctest::Approx(180.0));
  CHECK(*ncsim::tracking::tangent_angle(-1.0, -1.0) == doctest::Approx(-135.0));
  CHECK_FALSE(ncsim::tracking::tangent_angle(0.0, 0.0).has_value());
}

TEST_CASE("unwrapping picks the equal angle nearest to the axis") {
  CHECK(ncsim::tracking::unwrap_near(-170.0, 170.0) == doctest::Approx(190.0));
  CHECK(ncsim::tracking::unwrap_near(360.0, 0.0) == doctest::Approx(0.0));
  CHECK(ncsim::tracking::unwrap_near(10.0, 725.0) == doctest::Approx(730.0));
}

TEST_CASE("OFFSET adds to the tangent (ROTMODE 0); ROTMODE 1 turns the workpiece the other way") {
  CHECK(ncsim::tracking::tracking_value({3.0, 180.0, 0}, 30.0) == doctest::Approx(210.0));
  CHECK(ncsim::tracking::tracking_value({3.0, 180.0, 1}, 30.0) == doctest::Approx(150.0));
}

TEST_CASE("the static saw's start: a -X line with OFFSET 180 keeps C at 0, no turn block") {
  CaxTracker t({3.0, 180.0, 0}, kX, kY, kC, 0.0);
  const auto o = t.track(line(0, 0, -50, 0));
  REQUIRE(o.error.empty());
  REQUIRE(o.moves.size() == 1);
  CHECK_FALSE(o.turned);
  CHECK(o.moves[0].start[kC] == doctest::Approx(0.0));
  CHECK(o.moves[0].end[kC] == doctest::Approx(0.0));
}

TEST_CASE("a joint turn above ANGLIMIT inserts a C-only rapid turn block that stops") {
  CaxTracker t({3.0, 0.0, 0}, kX, kY, kC, 0.0);
  REQUIRE(t.track(line(0, 0, 10, 0)).moves.size() == 1);
  const auto o = t.track(line(10, 0, 10, 10));  // 90 degree corner
  REQUIRE(o.moves.size() == 2);
  CHECK(o.turned);
  CHECK(o.joint_turn == doctest::Approx(90.0));
  const Move& turn = o.moves[0];
  CHECK(turn.rapid);
  CHECK(turn.transition == ncsim::planner::Transition::stop_at_end);
  CHECK(turn.start[kX] == turn.end[kX]);
  CHECK(turn.start[kY] == turn.end[kY]);
  CHECK(turn.start[kC] == doctest::Approx(0.0));
  CHECK(turn.end[kC] == doctest::Approx(90.0));
  CHECK(o.moves[1].start[kC] == doctest::Approx(90.0));
  CHECK(o.moves[1].end[kC] == doctest::Approx(90.0));
}

TEST_CASE("a joint turn within ANGLIMIT is turned through during the next block") {
  CaxTracker t({3.0, 0.0, 0}, kX, kY, kC, 0.0);
  t.track(line(0, 0, 10, 0));
  const double two = std::atan(std::tan(2.0 * std::numbers::pi / 180.0)) * 180.0 / std::numbers::pi;
  const auto o = t.track(line(10, 0, 20, 10 * std::tan(2.0 * std::numbers::pi / 180.0)));
  REQUIRE(o.moves.size() == 1);
  CHECK_FALSE(o.turned);
  CHECK(o.moves[0].start[kC] == doctest::Approx(0.0));
  CHECK(o.moves[0].end[kC] == doctest::Approx(two));
  CHECK(t.current() == doctest::Approx(two));
}

TEST_CASE("C unwraps across +-180: a -X line after a C of 179 goes on at 180, not -180") {
  CaxTracker t({0.0, 0.0, 0}, kX, kY, kC, 179.0);
  const auto o = t.track(line(0, 0, 10, -0.1));  // tangent just below 0: a big turn
  CHECK(o.turned);
  CaxTracker u({0.0, 0.0, 0}, kX, kY, kC, 179.5);
  const auto p = u.track(line(0, 0, -10, -0.0));
  REQUIRE(p.moves.size() == 2);  // 0.5 degree > ANGLIMIT 0
  CHECK(p.moves.back().end[kC] == doctest::Approx(180.0));
  CaxTracker w({0.0, 0.0, 0}, kX, kY, kC, -179.5);
  CHECK(w.track(line(0, 0, -10, 0)).moves.back().end[kC] == doctest::Approx(-180.0));
}

TEST_CASE("an arc in G17 turns C linearly with the arc angle, exactly the tangent") {
  CaxTracker t({0.0, 0.0, 0}, kX, kY, kC, 90.0);
  Move a = line(10, 0, 0, 10);  // quarter circle CCW about the origin
  a.arc = ncsim::planner::Arc{0, 1, 0.0, 0.0, false, false};
  const auto o = t.track(a);
  REQUIRE(o.moves.size() == 1);
  CHECK(o.moves[0].start[kC] == doctest::Approx(90.0));
  CHECK(o.moves[0].end[kC] == doctest::Approx(180.0));
  Move b = line(0, 10, 10, 0);  // back CW: tangent 0 at (0, 10), -90 at (10, 0)
  b.arc = ncsim::planner::Arc{0, 1, 0.0, 0.0, true, false};
  const auto p = t.track(b);
  CHECK(p.turned);  // 180 -> 0: a reversal
  CHECK(p.moves.back().end[kC] - p.moves.back().start[kC] == doctest::Approx(-90.0));
}

TEST_CASE("an arc outside the XY plane is not supported") {
  CaxTracker t({0.0, 0.0, 0}, kX, kY, kC, 0.0);
  Move a = line(10, 0, 0, 10);
  a.arc = ncsim::planner::Arc{0, 2, 0.0, 0.0, false, false};
  CHECK_FALSE(t.track(a).error.empty());
}

TEST_CASE("a block without XY motion keeps C") {
  CaxTracker t({0.0, 0.0, 0}, kX, kY, kC, 42.0);
  Move z = line(1, 1, 1, 1);
  z.end[2] = -5.0;
  const auto o = t.track(z);
  REQUIRE(o.moves.size() == 1);
  CHECK(o.moves[0].start[kC] == 42.0);
  CHECK(o.moves[0].end[kC] == 42.0);
}

TEST_CASE("splitting a spline piece keeps the curve (de Casteljau)") {
  const Move m = spline({0, -50, -150, -200}, {0, 0, -40, -30});
  const auto [a, b] = ncsim::tracking::split_spline(m);
  for (double u : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    for (std::size_t i : {std::size_t{0}, std::size_t{1}}) {
      const double v = u < 0.5 ? bezier(a, i, 2 * u) : bezier(b, i, 2 * u - 1);
      CHECK(v == doctest::Approx(bezier(m, i, u)));
    }
  }
}

TEST_CASE("seeded: on random spline pieces C stays within the fit tolerance of the tangent") {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> d(-60.0, 60.0);
  for (int n = 0; n < 50; ++n) {
    // X runs -100 per piece (monotone), Y wanders: the static saw's kind of contour.
    const Move m =
        spline({0, -33 + d(rng) / 4, -66 + d(rng) / 4, -100}, {0, d(rng), d(rng), d(rng)});
    const double theta0 = std::atan2(d1(m, 1, 1e-4), d1(m, 0, 1e-4)) * 180.0 / std::numbers::pi;
    CaxTracker t({1.0, 0.0, 0}, kX, kY, kC, theta0);
    const auto o = t.track(m);
    REQUIRE(o.error.empty());
    REQUIRE_FALSE(o.turned);
    double prev_end = o.moves.front().start[kC];
    for (const Move& part : o.moves) {
      CHECK(part.start[kC] == doctest::Approx(prev_end).epsilon(1e-9));  // continuous
      prev_end = part.end[kC];
      for (double u = 0.05; u < 1.0; u += 0.1) {
        const double theta = std::atan2(d1(part, 1, u), d1(part, 0, u)) * 180.0 / std::numbers::pi;
        const double c = bezier(part, kC, u);
        CHECK(std::fabs(ncsim::tracking::unwrap_near(theta, c) - c) < 0.05);
      }
    }
  }
}

TEST_CASE(
    "seeded: C is C1 along a spline: its slope at every piece end is the tangent's turn rate") {
  // dC/du = d theta / du = (x' y'' - y' x'') / (x'^2 + y'^2) at both ends of every fitted
  // piece (Hermite ends), so the halves of a split piece join without a knee of C: before
  // session 31 a fit through four angles left knees whose curvature steps the C0 rule let
  // pass unbounded (docs/caxtrack.md, docs/planner.md "Corners").
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> d(-60.0, 60.0);
  const auto d2 = [](const Move& m, std::size_t i, double u) {
    return 6 * ((1 - u) * (m.spline->c2[i] - 2 * m.spline->c1[i] + m.start[i]) +
                u * (m.end[i] - 2 * m.spline->c2[i] + m.spline->c1[i]));
  };
  int joints = 0;
  for (int n = 0; n < 50; ++n) {
    const Move m =
        spline({0, -33 + d(rng) / 4, -66 + d(rng) / 4, -100}, {0, d(rng), d(rng), d(rng)});
    // Started on the tangent: no joint turn shared out over the block (its slope would add).
    const double theta0 = std::atan2(d1(m, 1, 0.0), d1(m, 0, 0.0)) * 180.0 / std::numbers::pi;
    for (const int rotmode : {0, 1}) {
      CaxTracker t({1.0, 0.0, rotmode}, kX, kY, kC, rotmode == 1 ? -theta0 : theta0);
      const auto o = t.track(m);
      REQUIRE(o.error.empty());
      for (const Move& part : o.moves) {
        for (const double u : {0.0, 1.0}) {
          const double dx = d1(part, kX, u), dy = d1(part, kY, u);
          const double rate = (dx * d2(part, kY, u) - dy * d2(part, kX, u)) / (dx * dx + dy * dy) *
                              180.0 / std::numbers::pi;
          const double slope = u == 0.0 ? 3 * (part.spline->c1[kC] - part.start[kC])
                                        : 3 * (part.end[kC] - part.spline->c2[kC]);
          CHECK(slope == doctest::Approx(rotmode == 1 ? -rate : rate).epsilon(1e-9).scale(1.0));
        }
      }
      joints += static_cast<int>(o.moves.size()) - 1;
    }
  }
  CHECK(joints > 20);  // pieces were split: the joints between halves were checked
}
