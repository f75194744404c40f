// Splines (#SPLINE, isg-language.md §5.4): Akima through the points with C1 joints, clamped
// cubic B-spline with C2 joints starting and ending at its end control points, arc length
// against a fine polyline, streaming in a fixed window, and the path-limits property on
// spline pieces.

#include "planner/spline.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "planner/limits.hpp"
#include "planner/prepare.hpp"

namespace {

using namespace ncsim::planner;

std::vector<SplineVertex> random_points(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<SplineVertex> pts;
  AxisVec p{};
  for (int k = 0; k < count; ++k) {
    SplineVertex v;
    v.point = p;
    v.line = static_cast<std::uint32_t>(10 + k);
    v.feed = 20.0 + k;
    pts.push_back(v);
    // Mostly forward with wiggles, steps 0.1 .. 5 mm, as CAM output looks.
    const double step = 0.1 * std::pow(50.0, 0.5 * (u(rng) + 1.0));
    p[0] += step * (1.0 + 0.3 * u(rng));
    p[1] += step * u(rng);
    p[2] += 0.3 * step * u(rng);
  }
  return pts;
}

std::vector<SplinePiece> build(SplineType type, const std::vector<SplineVertex>& pts) {
  SplineBuilder b(type, 3, 0b111);
  std::vector<SplinePiece> out;
  for (const SplineVertex& v : pts)
    for (const SplinePiece& p : b.push(v))
      out.push_back(p);
  for (const SplinePiece& p : b.finish())
    out.push_back(p);
  return out;
}

double dist(const AxisVec& a, const AxisVec& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < 3; ++i)
    s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

double vec_norm(const AxisVec& a) {
  return dist(a, AxisVec{});
}

AxisVec diff(const AxisVec& a, const AxisVec& b) {
  AxisVec r{};
  for (std::size_t i = 0; i < 3; ++i)
    r[i] = a[i] - b[i];
  return r;
}

}  // namespace

TEST_CASE("an Akima spline passes through every point, with continuous tangents (C1)") {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const auto pts = random_points(rng, 3 + trial * 3);
    const auto pieces = build(SplineType::akima, pts);
    REQUIRE(pieces.size() == pts.size() - 1);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const Segment& c = pieces[k].curve;
      CHECK(c.kind() == SegmentKind::spline);
      CHECK(dist(c.start(), pts[k].point) <= 1e-12);
      CHECK(dist(c.end(), pts[k + 1].point) <= 1e-9);
      CHECK(pieces[k].line == pts[k + 1].line);
      CHECK(pieces[k].feed == pts[k + 1].feed);
      if (k + 1 < pieces.size()) {
        const PathPoint a = c.at(c.length());
        const PathPoint b = pieces[k + 1].curve.at(0.0);
        CHECK(vec_norm(diff(a.d1, b.d1)) <= 1e-7);
      }
    }
  }
}

TEST_CASE("Akima keeps a straight run straight and two points give a line") {
  std::vector<SplineVertex> pts(6);
  for (int k = 0; k < 6; ++k)
    pts[k].point[0] = k * 1.5;
  for (const SplinePiece& p : build(SplineType::akima, pts)) {
    CHECK(p.curve.length() == doctest::Approx(1.5));
    CHECK(std::abs(p.curve.at(0.7).x[1]) <= 1e-12);
    CHECK(vec_norm(p.curve.bounds().d2) <= 1e-9);
  }
  pts.resize(2);
  const auto two = build(SplineType::akima, pts);
  REQUIRE(two.size() == 1);
  CHECK(two[0].curve.length() == doctest::Approx(1.5));
}

TEST_CASE("a B-spline starts and ends at its end control points and is C2 at every joint") {
  std::mt19937 rng(34);
  for (int trial = 0; trial < 20; ++trial) {
    const auto pts = random_points(rng, 4 + trial * 3);
    const auto pieces = build(SplineType::bspline, pts);
    REQUIRE(pieces.size() == pts.size() - 3);
    CHECK(dist(pieces.front().curve.start(), pts.front().point) <= 1e-12);
    CHECK(dist(pieces.back().curve.end(), pts.back().point) <= 1e-9);
    CHECK(pieces.back().line == pts.back().line);
    // Start tangent along the first leg (clamped end).
    const AxisVec leg = diff(pts[1].point, pts[0].point);
    const PathPoint p0 = pieces.front().curve.at(0.0);
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(p0.d1[i] == doctest::Approx(leg[i] / vec_norm(leg)).epsilon(1e-9));
    AxisVec lo = pts[0].point;
    AxisVec hi = pts[0].point;
    for (const auto& v : pts)
      for (std::size_t i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], v.point[i]);
        hi[i] = std::max(hi[i], v.point[i]);
      }
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const Segment& c = pieces[k].curve;
      for (int m = 0; m <= 20; ++m) {  // inside the control polygon's box (convex hull)
        const AxisVec x = c.point(c.length() * m / 20.0);
        for (std::size_t i = 0; i < 3; ++i) {
          CHECK(x[i] >= lo[i] - 1e-9);
          CHECK(x[i] <= hi[i] + 1e-9);
        }
      }
      if (k + 1 < pieces.size()) {
        const PathPoint a = c.at(c.length());
        const PathPoint b = pieces[k + 1].curve.at(0.0);
        CHECK(dist(a.x, b.x) <= 1e-12);
        CHECK(vec_norm(diff(a.d1, b.d1)) <= 1e-7);
        const double kappa = std::max(vec_norm(a.d2), 1e-3);
        CHECK(vec_norm(diff(a.d2, b.d2)) <= 1e-5 * kappa);
      }
    }
  }
}

TEST_CASE("spline arc length equals a fine numerical integration, and s is arc length") {
  std::mt19937 rng(56);
  for (const SplineType type : {SplineType::akima, SplineType::bspline}) {
    const auto pts = random_points(rng, 40);
    for (const SplinePiece& p : build(type, pts)) {
      const Segment& c = p.curve;
      constexpr int kSteps = 4000;
      double poly = 0.0;
      AxisVec prev = c.point(0.0);
      double worst_speed = 0.0;
      for (int m = 1; m <= kSteps; ++m) {
        const AxisVec x = c.point(c.length() * m / kSteps);
        const double d = dist(x, prev);
        poly += d;
        worst_speed = std::max(worst_speed, std::abs(d / (c.length() / kSteps) - 1.0));
        prev = x;
      }
      CHECK(c.length() == doctest::Approx(poly).epsilon(1e-6));
      CHECK(worst_speed <= 1e-4);  // |dx/ds| == 1: the parameter is arc length
    }
  }
}

TEST_CASE("a long section streams through a fixed window") {
  // 100,000 points pass through a builder whose size is fixed at compile time.
  for (const SplineType type : {SplineType::akima, SplineType::bspline}) {
    SplineBuilder b(type, 3, 0b111);
    std::size_t pieces = 0;
    double length = 0.0;
    SplineVertex v;
    constexpr int kPoints = 100000;
    bool lagging = false;  // a piece held back longer than the window needs
    for (int k = 0; k < kPoints; ++k) {
      v.point[0] = 0.1 * k;
      v.point[1] = std::sin(0.01 * k);
      for (const SplinePiece& p : b.push(v)) {
        ++pieces;
        length += p.curve.length();
      }
      if (pieces + (type == SplineType::akima ? 4 : 6) < static_cast<std::size_t>(k) + 1)
        lagging = true;
    }
    for (const SplinePiece& p : b.finish()) {
      ++pieces;
      length += p.curve.length();
    }
    CHECK_FALSE(lagging);
    CHECK(pieces == (type == SplineType::akima ? kPoints - 1 : kPoints - 3));
    CHECK(length > 0.1 * (kPoints - 4));
  }
}

TEST_CASE("repeated points are dropped; too few B-spline points is API misuse (NC4401)") {
  std::vector<SplineVertex> pts(5);
  pts[1].point[0] = 1.0;
  pts[2].point[0] = 1.0;  // duplicate
  pts[3].point = pts[1].point;
  pts[3].point[1] = 1.0;
  pts[4].point[1] = 2.0;
  CHECK(build(SplineType::akima, pts).size() == 3);
  SplineBuilder b(SplineType::bspline, 3, 0b111);
  (void)b.push(pts[0]);
  (void)b.push(pts[1]);
  (void)b.push(pts[3]);
  CHECK_THROWS_AS((void)b.finish(), std::invalid_argument);
}

TEST_CASE("property: motion inside the path limits of spline pieces keeps every axis inside") {
  std::mt19937 rng(78);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto range = [&](double lo, double hi) { return lo * std::pow(hi / lo, u(rng)); };
  for (int trial = 0; trial < 20; ++trial) {
    std::array<AxisLimits, 3> ax{};
    for (auto& a : ax) {
      a.v_max = a.v_reference = a.v_rapid = range(10, 1000);
      a.a_max = range(100, 1e4);
      a.d_max = range(100, 1e4);
      a.j_max = range(1e3, 1e6);
    }
    const auto pts = random_points(rng, 12);
    for (const SplineType type : {SplineType::akima, SplineType::bspline}) {
      for (const SplinePiece& piece : build(type, pts)) {
        Move m;
        m.feed = range(1, 2000);
        m.slope = SlopeType::trapez;
        const PathLimits pl = path_limits(piece.curve, m, ax);
        REQUIRE(pl.v_max > 0.0);
        REQUIRE(pl.a_max > 0.0);
        REQUIRE(pl.j_max > 0.0);
        const Segment& c = piece.curve;
        double worst = 0.0;  // largest |axis v, a, j| over its limit
        for (int k = 0; k <= 400; ++k) {
          const PathPoint p = c.at(c.length() * k / 400.0);
          for (const double a : {pl.a_max, -pl.d_max})
            for (const double j : {pl.j_max, -pl.j_max})
              for (std::size_t i = 0; i < 3; ++i) {
                const double v = pl.v_max;
                const double vi = p.d1[i] * v;
                const double ai = p.d2[i] * v * v + p.d1[i] * a;
                const double ji = p.d3[i] * v * v * v + 3 * p.d2[i] * v * a + p.d1[i] * j;
                worst = std::max({worst, std::abs(vi) / ax[i].v_max,
                                  std::abs(ai) / std::max(ax[i].a_max, ax[i].d_max),
                                  std::abs(ji) / ax[i].j_max});
              }
        }
        CHECK(worst <= 1.0 + 1e-9);
      }
    }
  }
}

TEST_CASE("spline pieces go through the preparation: B-spline joints chain (C2), Akima are C1") {
  std::vector<SplineVertex> pts(12);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    pts[k].point[0] = 2.0 * static_cast<double>(k);
    pts[k].point[1] = std::sin(0.8 * static_cast<double>(k));
    pts[k].line = static_cast<std::uint32_t>(100 + k);
    pts[k].feed = 30.0;
  }
  AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = 500.0;
  ax.a_max = ax.d_max = 5000.0;
  ax.j_max = 1e6;
  const std::array<AxisLimits, 3> axes = {ax, ax, ax};
  Move modal;
  modal.slope = SlopeType::trapez;
  for (const SplineType type : {SplineType::bspline, SplineType::akima}) {
    Preparer prep(axes, ChannelLimits{});
    std::vector<PreparedSegment> out;
    const auto pieces = build(type, pts);
    for (const SplinePiece& p : pieces)
      prep.push(p, modal, out);
    prep.finish(out);
    std::size_t parts = 0;
    double length = 0.0;
    double expected = 0.0;
    for (const SplinePiece& p : pieces)
      expected += p.curve.length();
    for (const PreparedSegment& ps : out) {
      parts += ps.path.parts();
      length += ps.path.length();
      if (ps.stop == StopReason::none)
        CHECK(ps.joint ==
              (type == SplineType::bspline ? TransitionClass::c2 : TransitionClass::c1));
    }
    CHECK(parts == pieces.size());
    CHECK(length == doctest::Approx(expected).epsilon(1e-12));
    CHECK(out.back().stop == StopReason::end_of_stream);
    if (type == SplineType::bspline) CHECK(out.size() < pieces.size());  // chained through C2
  }
}

TEST_CASE("spline pieces' derivative bounds hold against 2049 samples in arc length") {
  std::mt19937 rng(91);
  double worst = 0.0;  // largest sampled |derivative| over its bound
  for (int trial = 0; trial < 10; ++trial) {
    const auto pts = random_points(rng, 8);
    for (const SplineType type : {SplineType::akima, SplineType::bspline}) {
      for (const SplinePiece& piece : build(type, pts)) {
        const DerivativeBounds b = piece.curve.bounds();
        for (int k = 0; k <= 2048; ++k) {
          const PathPoint p = piece.curve.at(piece.curve.length() * k / 2048.0);
          for (std::size_t i = 0; i < 3; ++i) {
            if (b.d1[i] > 0.0) worst = std::max(worst, std::abs(p.d1[i]) / b.d1[i]);
            if (b.d2[i] > 0.0) worst = std::max(worst, std::abs(p.d2[i]) / b.d2[i]);
            if (b.d3[i] > 0.0) worst = std::max(worst, std::abs(p.d3[i]) / b.d3[i]);
          }
        }
      }
    }
  }
  CHECK(worst <= 1.0);
  CHECK(worst > 0.9);  // and they are not loose
}

TEST_CASE("a B-spline folding back on itself is split around its near-cusp into exact parts") {
  // issue 34 item 12: the control points of the issue (portal_3x, F1000)
  const std::vector<AxisVec> cps = {{10, 10, 0},     {20, 20, 0},       {790, 590, 0},
                                    {20, 20.001, 0}, {790, 590.001, 0}, {20, 20, 0}};
  std::vector<SplineVertex> pts;
  for (std::size_t k = 0; k < cps.size(); ++k) {
    SplineVertex v;
    v.point = cps[k];
    v.line = static_cast<std::uint32_t>(10 + k);
    v.feed = 1000.0 / 60.0;
    pts.push_back(v);
  }
  int split_pieces = 0;
  for (const SplinePiece& piece : build(SplineType::bspline, pts)) {
    const std::vector<SplinePiece> parts = split_near_cusp(piece, 0b111);
    if (parts.empty()) continue;
    ++split_pieces;
    double length = 0.0;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      length += parts[k].curve.length();
      CHECK(parts[k].line == piece.line);
      CHECK(parts[k].feed == piece.feed);
      if (k > 0) CHECK(parts[k].control[0] == parts[k - 1].control[3]);
    }
    CHECK(parts.front().control[0] == piece.control[0]);
    CHECK(parts.back().control[3] == piece.control[3]);
    CHECK(length == doctest::Approx(piece.curve.length()).epsilon(1e-3));
    // Running each part at the velocity its curvature bound allows (portal_3x: 3000 mm/s^2)
    // takes seconds, not the hours of the whole piece at the near-cusp's velocity.
    double seconds = 0.0, d2_max = 0.0;
    for (const SplinePiece& part : parts) {
      const double d2 = vec_norm(part.curve.bounds().d2);
      d2_max = std::max(d2_max, d2);
      seconds += part.curve.length() / std::min(1000.0 / 60.0, std::sqrt(3000.0 / d2));
    }
    CHECK(d2_max > 1e6);  // the near-cusp's curvature is there, in its innermost parts
    CHECK(seconds < 2.0 * piece.curve.length() / (1000.0 / 60.0) + 5.0);
  }
  CHECK(split_pieces >= 2);
  // pieces of CAM-like points (mostly forward) come back whole
  std::mt19937 rng(34);
  for (const SplineType type : {SplineType::akima, SplineType::bspline})
    for (const SplinePiece& piece : build(type, random_points(rng, 40)))
      CHECK(split_near_cusp(piece, 0b111).empty());
}
