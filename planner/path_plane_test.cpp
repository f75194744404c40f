// Arcs in a general plane (an arc programmed under a rotated #CS, planner::ArcPlane) and the
// G00 slope (P-AXIS-00004 / 00200): the rotated arc is the rotation of the principal arc
// point for point, its derivatives and bounds hold, and G00 plans with its own a and j.

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "planner/limits.hpp"
#include "planner/path.hpp"
#include "planner/test_support.hpp"

namespace {

using namespace ncsim::planner;
using ncsim::planner::test::vec;

using Mat = std::array<std::array<double, 3>, 3>;

/// Rotation Rz(a) Ry(b) Rx(c).
Mat rotation(double a, double b, double c) {
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  const double cc = std::cos(c), sc = std::sin(c);
  return {{{ca * cb, ca * sb * sc - sa * cc, ca * sb * cc + sa * sc},
           {sa * cb, sa * sb * sc + ca * cc, sa * sb * cc - ca * sc},
           {-sb, cb * sc, cb * cc}}};
}

AxisVec apply(const Mat& r, const AxisVec& p, const AxisVec& t) {
  AxisVec q{};
  for (std::size_t i = 0; i < 3; ++i)
    q[i] = r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i];
  return q;
}

/// A G17 arc (helix when z1 != 0) about the origin from angle a0 to a1 at radius rad.
Move principal(double rad, double a0, double a1, double z1, bool cw) {
  Move m;
  m.start = vec(rad * std::cos(a0), rad * std::sin(a0), 0.0);
  m.end = vec(rad * std::cos(a1), rad * std::sin(a1), z1);
  m.feed = 10.0;
  m.arc = Arc{0, 1, 0.0, 0.0, cw, false};
  return m;
}

/// The same arc after p -> R p + t, as a general-plane arc.
Move rotated(const Move& m, const Mat& r, const AxisVec& t) {
  Move g = m;
  g.start = apply(r, m.start, t);
  g.end = apply(r, m.end, t);
  ArcPlane plane;
  for (std::size_t k = 0; k < 3; ++k) {
    plane.u[k] = r[k][0];
    plane.v[k] = r[k][1];
    plane.centre[k] = t[k];  // the centre (0, 0, 0) moved
  }
  g.arc_plane = plane;
  return g;
}

}  // namespace

TEST_CASE("an arc in a rotated plane is the rotated arc, point for point, with the same length") {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int n = 0; n < 50; ++n) {
    const Mat r = rotation(u(rng), u(rng), u(rng));
    const AxisVec t = vec(10 * u(rng), 10 * u(rng), 10 * u(rng));
    const double a0 = u(rng);
    const Move m = principal(1.0 + std::abs(u(rng)), a0, a0 + 0.1 + std::abs(u(rng)),
                             n % 3 == 0 ? u(rng) : 0.0, n % 2 == 0);
    const Move g = rotated(m, r, t);
    validate(g);
    const Segment a = Segment::arc(m);
    const Segment b = Segment::arc(g);
    REQUIRE(b.length() == doctest::Approx(a.length()).epsilon(1e-12));
    for (int k = 0; k <= 16; ++k) {
      const double s = a.length() * k / 16.0;
      const PathPoint pa = a.at(s);
      const PathPoint pb = b.at(s);
      const AxisVec x = apply(r, pa.x, t);
      const AxisVec d1 = apply(r, pa.d1, {});
      const AxisVec d2 = apply(r, pa.d2, {});
      const AxisVec d3 = apply(r, pa.d3, {});
      for (std::size_t i = 0; i < 3; ++i) {
        CHECK(pb.x[i] == doctest::Approx(x[i]).epsilon(1e-12).scale(10.0));
        CHECK(pb.d1[i] == doctest::Approx(d1[i]).epsilon(1e-12).scale(1.0));
        CHECK(pb.d2[i] == doctest::Approx(d2[i]).epsilon(1e-12).scale(1.0));
        CHECK(pb.d3[i] == doctest::Approx(d3[i]).epsilon(1e-12).scale(1.0));
      }
    }
    // The end is the programmed end; the bounds cover dense samples and are reached.
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(b.end()[i] == doctest::Approx(g.end[i]).epsilon(1e-12).scale(10.0));
    const DerivativeBounds bound = b.bounds();
    DerivativeBounds seen;
    for (int k = 0; k <= 4000; ++k) {
      const PathPoint p = b.at(b.length() * k / 4000.0);
      for (std::size_t i = 0; i < 3; ++i) {
        seen.d1[i] = std::max(seen.d1[i], std::abs(p.d1[i]));
        seen.d2[i] = std::max(seen.d2[i], std::abs(p.d2[i]));
        seen.d3[i] = std::max(seen.d3[i], std::abs(p.d3[i]));
      }
    }
    for (std::size_t i = 0; i < 3; ++i) {
      CHECK(seen.d1[i] <= bound.d1[i] * (1 + 1e-12) + 1e-15);
      CHECK(seen.d2[i] <= bound.d2[i] * (1 + 1e-12) + 1e-15);
      CHECK(seen.d3[i] <= bound.d3[i] * (1 + 1e-12) + 1e-15);
      // The curvature bound is the exact maximum over the swept angles.
      CHECK(bound.d2[i] <= seen.d2[i] * (1 + 1e-4) + 1e-9);
    }
  }
}

TEST_CASE("a general plane spanned by X and Y is the G17 arc") {
  const Move m = principal(5.0, 0.3, 2.0, 1.5, false);
  const Mat identity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  const Segment a = Segment::arc(m);
  const Segment b = Segment::arc(rotated(m, identity, vec(0, 0, 0)));
  CHECK(b.length() == doctest::Approx(a.length()).epsilon(1e-14));
  for (int k = 0; k <= 8; ++k)
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(b.point(a.length() * k / 8.0)[i] ==
            doctest::Approx(a.point(a.length() * k / 8.0)[i]).epsilon(1e-14));
}

TEST_CASE("a general plane whose u, v are not orthonormal is refused by validate") {
  Move g = rotated(principal(5.0, 0.0, 1.0, 0.0, false), {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                   vec(0, 0, 0));
  g.arc_plane->v = {0.5, 1.0, 0.0};
  CHECK_THROWS_AS(validate(g), std::invalid_argument);
}

TEST_CASE("G00 plans with the G00 slope P-AXIS-00004 / P-AXIS-00200; feed moves with their own") {
  std::array<AxisLimits, 3> axes{};
  for (auto& a : axes) {
    a = test::axis(500.0, 1000.0, 1e5);
    a.a_rapid = 4000.0;  // P-AXIS-00004
    a.j_rapid = 4e5;     // P-AXIS-00004 / P-AXIS-00200 (10 ms)
  }
  Move m;
  m.start = vec(0, 0, 0);
  m.end = vec(100, 0, 0);
  m.rapid = true;
  m.slope = SlopeType::trapez;
  const Segment seg = Segment::from_move(m);
  const PathLimits rapid = path_limits(seg, m, axes);
  CHECK(rapid.a_max == doctest::Approx(4000.0));
  CHECK(rapid.d_max == doctest::Approx(4000.0));
  CHECK(rapid.j_max == doctest::Approx(4e5));
  m.rapid = false;
  m.feed = 100.0;
  const PathLimits feed = path_limits(seg, m, axes);
  CHECK(feed.a_max == doctest::Approx(1000.0));
  CHECK(feed.j_max == doctest::Approx(1e5));
  // Without a G00 slope (0) G00 keeps the feed slope.
  for (auto& a : axes)
    a.a_rapid = a.j_rapid = 0.0;
  m.rapid = true;
  const PathLimits same = path_limits(seg, m, axes);
  CHECK(same.a_max == doctest::Approx(1000.0));
  CHECK(same.j_max == doctest::Approx(1e5));
  axes[1].a_rapid = -1.0;
  CHECK_THROWS_AS(validate(axes), std::invalid_argument);
}
