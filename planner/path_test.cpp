// Path geometry: lengths, points, tangents and curvature of lines, arcs (three planes),
// helices and blends, checked against closed forms and against finite differences.

#include "planner/path.hpp"

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "planner/test_support.hpp"

namespace {

using ncsim::planner::Arc;
using ncsim::planner::AxisVec;
using ncsim::planner::Move;
using ncsim::planner::PathPoint;
using ncsim::planner::Segment;
using ncsim::planner::SegmentKind;
using ncsim::planner::test::vec;

constexpr double kPi = std::numbers::pi;

Move arc_move(AxisVec start, AxisVec end, double c1, double c2, bool cw, std::uint8_t a1 = 0,
              std::uint8_t a2 = 1) {
  Move m;
  m.start = start;
  m.end = end;
  m.feed = 10.0;
  m.arc = Arc{a1, a2, c1, c2, cw, false};
  return m;
}

double norm3(const AxisVec& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/// Finite-difference check of d1, d2, d3 at s (central differences of the next lower order).
void check_derivatives(const Segment& seg, double s, double tol) {
  const double h = 1e-4 * seg.length();
  const PathPoint p = seg.at(s);
  const PathPoint lo = seg.at(s - h);
  const PathPoint hi = seg.at(s + h);
  for (std::size_t i = 0; i < seg.axis_count(); ++i) {
    CHECK(p.d1[i] == doctest::Approx((hi.x[i] - lo.x[i]) / (2 * h)).epsilon(tol).scale(1.0));
    CHECK(p.d2[i] == doctest::Approx((hi.d1[i] - lo.d1[i]) / (2 * h)).epsilon(tol).scale(1.0));
    CHECK(p.d3[i] == doctest::Approx((hi.d2[i] - lo.d2[i]) / (2 * h)).epsilon(tol).scale(1.0));
  }
}

}  // namespace

TEST_CASE("a line is parametrised by its length over the path axes") {
  const Segment seg = Segment::line(3, 0b111, vec(0, 0, 0), vec(3, 4, 0));
  CHECK(seg.kind() == SegmentKind::line);
  CHECK(seg.length() == doctest::Approx(5.0));
  const PathPoint p = seg.at(2.5);
  CHECK(p.x[0] == doctest::Approx(1.5));
  CHECK(p.x[1] == doctest::Approx(2.0));
  CHECK(p.d1[0] == doctest::Approx(0.6));
  CHECK(p.d1[1] == doctest::Approx(0.8));
  CHECK(p.d2[0] == 0.0);
  CHECK(seg.end()[1] == doctest::Approx(4.0));
}

TEST_CASE("an auxiliary axis follows the path axes without adding to the length") {
  AxisVec a = vec(0, 0, 0);
  AxisVec b = vec(10, 0, 0);
  b[3] = 90.0;  // a rotary axis outside the path axes
  const Segment seg = Segment::line(4, 0b111, a, b);
  CHECK(seg.length() == doctest::Approx(10.0));
  CHECK(seg.at(5.0).x[3] == doctest::Approx(45.0));
  CHECK(seg.at(5.0).d1[3] == doctest::Approx(9.0));  // deg per mm of path
}

TEST_CASE("a move of non-path axes alone is measured over every axis") {
  AxisVec a{};
  AxisVec b{};
  b[3] = 30.0;
  const Segment seg = Segment::line(4, 0b111, a, b);
  CHECK(seg.length() == doctest::Approx(30.0));
  CHECK(seg.at(0.0).d1[3] == doctest::Approx(1.0));
}

TEST_CASE("a quarter circle G03 in G17 has length pi R / 2 and curvature 1/R to the centre") {
  const double r = 10.0;
  const Segment seg = Segment::arc(arc_move(vec(r, 0), vec(0, r), 0, 0, false));
  CHECK(seg.kind() == SegmentKind::arc);
  CHECK(seg.length() == doctest::Approx(kPi * r / 2));
  const PathPoint p = seg.at(seg.length() / 2);
  CHECK(p.x[0] == doctest::Approx(r / std::sqrt(2.0)));
  CHECK(p.x[1] == doctest::Approx(r / std::sqrt(2.0)));
  CHECK(norm3(p.d1) == doctest::Approx(1.0));
  CHECK(norm3(p.d2) == doctest::Approx(1.0 / r));
  CHECK(p.d2[0] < 0.0);  // towards the centre
  CHECK(p.d2[1] < 0.0);
  CHECK(seg.end()[0] == doctest::Approx(0.0).epsilon(1e-12).scale(1.0));
  CHECK(seg.end()[1] == doctest::Approx(r));
}

TEST_CASE("G02 from (R,0) to (0,R) takes the long way, three quarters of the circle") {
  const double r = 10.0;
  const Segment seg = Segment::arc(arc_move(vec(r, 0), vec(0, r), 0, 0, true));
  CHECK(seg.length() == doctest::Approx(1.5 * kPi * r));
  CHECK(seg.at(seg.length() / 3).x[1] == doctest::Approx(-r));  // passes (0,-R)
}

TEST_CASE("a closed arc is a full circle in the programmed direction") {
  Move m = arc_move(vec(5, 0), vec(5, 0), 0, 0, true);
  const Segment seg = Segment::arc(m);
  CHECK(seg.length() == doctest::Approx(2 * kPi * 5));
  CHECK(seg.at(seg.length() / 4).x[1] == doctest::Approx(-5.0));
}

TEST_CASE("G18 arcs use Z and X as plane axes") {
  // G18: first plane axis Z (index 2), second X (index 0).
  const Segment seg = Segment::arc(arc_move(vec(0, 0, 4), vec(4, 0, 0), 0, 0, false, 2, 0));
  CHECK(seg.length() == doctest::Approx(kPi * 2));
  const PathPoint p = seg.at(seg.length() / 2);
  CHECK(p.x[1] == 0.0);
  CHECK(p.x[0] == doctest::Approx(4 / std::sqrt(2.0)));
  CHECK(p.x[2] == doctest::Approx(4 / std::sqrt(2.0)));
}

TEST_CASE("a helix has length sqrt((R phi)^2 + h^2) and curvature R / (R^2 + c^2)") {
  const double r = 5.0;
  const double h = 8.0;
  Move m = arc_move(vec(r, 0, 0), vec(-r, 0, h), 0, 0, false);
  const Segment seg = Segment::arc(m);
  const double phi = kPi;
  CHECK(seg.length() == doctest::Approx(std::hypot(r * phi, h)));
  const double c = h / phi;
  const PathPoint p = seg.at(1.3);
  CHECK(norm3(p.d1) == doctest::Approx(1.0));
  CHECK(norm3(p.d2) == doctest::Approx(r / (r * r + c * c)));
  CHECK(seg.at(seg.length() / 2).x[2] == doctest::Approx(h / 2));
}

TEST_CASE("arc derivative bounds are exact over the swept angles") {
  const double r = 10.0;
  const Segment seg = Segment::arc(arc_move(vec(r, 0), vec(0, r), 0, 0, false));
  const auto b = seg.bounds();
  CHECK(b.d1[0] == doctest::Approx(1.0));  // at (0, R) the tangent is -X
  CHECK(b.d2[0] == doctest::Approx(1.0 / r));
  CHECK(b.d3[0] == doctest::Approx(1.0 / (r * r)));
  // Only the first 30 degrees: |x'_X| <= sin(30), |x''_Y| <= sin(30) / R.
  const Segment part = seg.trimmed(0.0, r * kPi / 6);
  const auto pb = part.bounds();
  CHECK(pb.d1[0] == doctest::Approx(0.5));
  CHECK(pb.d2[1] == doctest::Approx(0.5 / r));
  CHECK(pb.d2[0] == doctest::Approx(1.0 / r));
}

TEST_CASE("a trimmed segment is the same curve re-parametrised from its new start") {
  const Segment seg = Segment::arc(arc_move(vec(10, 0), vec(-10, 0), 0, 0, false));
  const Segment part = seg.trimmed(2.0, 7.0);
  CHECK(part.length() == doctest::Approx(5.0));
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(part.start()[i] == doctest::Approx(seg.point(2.0)[i]));
    CHECK(part.end()[i] == doctest::Approx(seg.point(7.0)[i]));
  }
}

TEST_CASE("a straight Bezier with evenly spaced points is a line of the same length") {
  std::array<AxisVec, 6> p{};
  for (int k = 0; k < 6; ++k)
    p[k] = vec(2.0 * k, 1.0 * k, 0);
  const Segment seg = Segment::bezier(3, 0b111, p);
  CHECK(seg.kind() == SegmentKind::blend);
  CHECK(seg.length() == doctest::Approx(std::hypot(10.0, 5.0)));
  const PathPoint q = seg.at(seg.length() * 0.3);
  CHECK(q.x[0] == doctest::Approx(3.0));
  CHECK(norm3(q.d2) == doctest::Approx(0.0).scale(1.0));
}

TEST_CASE("derivatives agree with finite differences on random arcs, helices and Beziers") {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (int n = 0; n < 40; ++n) {
    const double r = 1.0 + std::abs(u(rng));
    const double a0 = u(rng);
    const double a1 = a0 + 0.2 + std::abs(u(rng)) * 0.5;
    Move m = arc_move(vec(r * std::cos(a0), r * std::sin(a0), 0),
                      vec(r * std::cos(a1), r * std::sin(a1), u(rng)), 0, 0, n % 2 == 0);
    const Segment arc = Segment::arc(m);
    check_derivatives(arc, arc.length() * 0.37, 1e-5);
    std::array<AxisVec, 6> p{};
    for (auto& q : p)
      q = vec(u(rng), u(rng), u(rng));
    const Segment bez = Segment::bezier(3, 0b111, p);
    // Points where the speed does not vanish: compare at mid-curve.
    check_derivatives(bez, bez.length() * 0.5, 1e-4);
    CHECK(norm3(bez.at(bez.length() * 0.21).d1) == doctest::Approx(1.0));
  }
}

TEST_CASE("a Bezier's end points and derivatives are the limits of its inner points") {
  // The ends take a shortcut (the hodographs' first and last control points, path_bezier.cpp
  // eval_end); it must be the same curve: x(0) = P0, x'(0) along P1 - P0, and the point and
  // derivatives continuous into the curve at both ends.
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (int n = 0; n < 40; ++n) {
    std::array<AxisVec, 6> p{};
    for (auto& q : p)
      q = vec(u(rng), u(rng), u(rng));
    const Segment bez = Segment::bezier(3, 0b111, p);
    const double len = bez.length();
    const PathPoint a = bez.at(0.0);
    const PathPoint b = bez.at(len);
    const double l01 = norm3(vec(p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]));
    const double l45 = norm3(vec(p[5][0] - p[4][0], p[5][1] - p[4][1], p[5][2] - p[4][2]));
    const PathPoint a_in = bez.at(1e-7 * len);
    const PathPoint b_in = bez.at(len * (1 - 1e-7));
    for (std::size_t i = 0; i < 3; ++i) {
      CHECK(a.x[i] == p[0][i]);
      CHECK(b.x[i] == p[5][i]);
      CHECK(a.d1[i] == doctest::Approx((p[1][i] - p[0][i]) / l01).epsilon(1e-12));
      CHECK(b.d1[i] == doctest::Approx((p[5][i] - p[4][i]) / l45).epsilon(1e-12));
      CHECK(a_in.d1[i] == doctest::Approx(a.d1[i]).epsilon(1e-4).scale(1.0));
      CHECK(b_in.d1[i] == doctest::Approx(b.d1[i]).epsilon(1e-4).scale(1.0));
      CHECK(a_in.d2[i] == doctest::Approx(a.d2[i]).epsilon(1e-3).scale(1.0));
      CHECK(b_in.d2[i] == doctest::Approx(b.d2[i]).epsilon(1e-3).scale(1.0));
      CHECK(a_in.d3[i] == doctest::Approx(a.d3[i]).epsilon(1e-2).scale(1.0));
      CHECK(b_in.d3[i] == doctest::Approx(b.d3[i]).epsilon(1e-2).scale(1.0));
    }
  }
}

TEST_CASE("an arc of a huge radius and a tiny sweep stays a tiny sweep, exact to the nanometre") {
  // issue 34 items 4, 28: R 1e10 on a 10 mm chord ran as a full circle; points computed from
  // a centre 1e8 mm away carried its rounding (1e-8 mm steps)
  for (const double r : {10.0, 1e6, 1e8, 1e9, 1e10}) {
    CAPTURE(r);
    const double c2 = 10.0 - std::sqrt(r * r - 25.0);
    const Segment seg = Segment::arc(arc_move(vec(10, 10), vec(20, 10), 15, c2, true));
    const double y0 = 10.0 - c2;  // the start relative to the centre, as rounded
    const double radius = std::hypot(5.0, y0);
    const double sweep = 2.0 * std::asin(5.0 / radius);
    CHECK(seg.length() == doctest::Approx(radius * sweep).epsilon(1e-12));
    const AxisVec end = seg.point(seg.length());
    CHECK(std::abs(end[0] - 20.0) < 1e-9);
    CHECK(std::abs(end[1] - 10.0) < 1e-9);
    const AxisVec mid = seg.point(seg.length() / 2.0);
    CHECK(std::abs(mid[0] - 15.0) < 1e-9);
    CHECK(std::abs(mid[1] - (10.0 + 25.0 / (radius + y0))) < 1e-9);  // the sagitta
    double x = 10.0;
    for (int k = 1; k <= 1000; ++k) {  // X rises steadily, Y stays on the arc
      const AxisVec p = seg.point(seg.length() * k / 1000.0);
      CHECK(p[0] > x);
      x = p[0];
    }
  }
}

TEST_CASE("an arc whose end lies a tiny angle short of its start is a tiny sweep, not a circle") {
  // G03 from (R, 0) to just below it: the long way round, 2 pi minus the tiny angle; G02 the
  // tiny way. Closed only when the interpreter says so or the end is the start.
  const double r = 1e9;
  const double phi = 1e-14;
  Move m = arc_move(vec(r, 0), vec(r * std::cos(phi), -r * std::sin(phi)), 0, 0, true);
  CHECK(Segment::arc(m).length() == doctest::Approx(r * phi).epsilon(1e-6));
  m.arc->clockwise = false;
  CHECK(Segment::arc(m).length() == doctest::Approx(r * (2.0 * kPi - phi)).epsilon(1e-12));
}

TEST_CASE("a Bezier curve from the AVX2 build is the baseline build's to the bit") {
  // Session dense3: the arc-length tables and the bounds of a whole blend run in an AVX2 build of
  // their loops where the CPU has it (planner::allow_wide_loops). Random blends and spline
  // pieces of 1 to 5 axes (the planar two-axis loop, the general loop, constant and non-metric
  // axes, tiny and huge scales, folded control polygons near a cusp) give the same length,
  // points and bounds either way.
  if (!ncsim::planner::wide_loops_available())
    MESSAGE("no AVX2 on this CPU: both runs take the baseline build");
  std::mt19937 rng(36);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> axes(1, 5);
  const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
  const auto same = [&](const AxisVec& a, const AxisVec& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (bits(a[i]) != bits(b[i])) return false;
    return true;
  };
  for (int n = 0; n < 3000; ++n) {
    const auto count = static_cast<std::uint8_t>(axes(rng));
    const double scale = std::pow(10.0, 4.0 * u(rng));
    const auto metric = static_cast<ncsim::planner::AxisMask>(rng() % (1U << count));
    std::array<AxisVec, 6> p{};
    for (std::size_t i = 0; i < count; ++i) {
      const bool constant = rng() % 5 == 0;
      const double c = scale * u(rng);
      for (std::size_t k = 0; k < 6; ++k)
        p[k][i] = constant ? c : scale * u(rng);
    }
    if (n % 7 == 0) p[3] = p[2];    // a folded polygon
    const bool piece = n % 3 == 0;  // a spline piece: the 32-interval table
    const auto build = [&](bool wide) {
      ncsim::planner::allow_wide_loops(wide);
      return piece ? Segment::bezier_uneven(count, metric, p) : Segment::bezier(count, metric, p);
    };
    const Segment base_seg = build(false);
    const ncsim::planner::DerivativeBounds base = base_seg.bounds();
    const Segment wide_seg = build(true);
    const ncsim::planner::DerivativeBounds wide = wide_seg.bounds();
    REQUIRE(bits(wide_seg.length()) == bits(base_seg.length()));
    const double s = wide_seg.length() * 0.37;
    REQUIRE(same(wide_seg.at(s).x, base_seg.at(s).x));
    REQUIRE(same(wide_seg.at(s).d2, base_seg.at(s).d2));
    REQUIRE(same(wide.d1, base.d1));
    REQUIRE(same(wide.d2, base.d2));
    REQUIRE(same(wide.d3, base.d3));
    REQUIRE(bits(wide.curvature) == bits(base.curvature));
    REQUIRE(wide.metric == base.metric);
  }
}
