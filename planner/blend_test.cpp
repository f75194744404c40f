// Tolerance balls: the blend lies inside the ball, its ends are on it, it joins both
// neighbours with continuous tangent and curvature, radii shrink to half a block; a seeded
// property test over random line/arc corners in 3-D.

#include "planner/blend.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "planner/corner.hpp"
#include "planner/test_support.hpp"

namespace {

using namespace ncsim::planner;
using test::vec;

double dist(const AxisVec& a, const AxisVec& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

/// Largest and smallest distance of the blend from the corner, over dense samples.
std::pair<double, double> distance_range(const Segment& curve, const AxisVec& corner) {
  double hi = 0.0;
  double lo = 1e300;
  for (int k = 0; k <= 400; ++k) {
    const double d = dist(curve.point(curve.length() * k / 400.0), corner);
    hi = std::max(hi, d);
    lo = std::min(lo, d);
  }
  return {hi, lo};
}

/// Length of the curve from 0 to s_end, from chord sums at N and 2N pieces (Richardson).
double chord_length(const Segment& curve, double s_end) {
  auto chords = [&](int n) {
    double sum = 0.0;
    AxisVec prev = curve.point(0.0);
    for (int k = 1; k <= n; ++k) {
      const AxisVec p = curve.point(s_end * k / n);
      sum += dist(prev, p);
      prev = p;
    }
    return sum;
  };
  return (4.0 * chords(2000) - chords(1000)) / 3.0;
}

void check_joint(const PathPoint& a, const PathPoint& b, double curv_tol) {
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(a.x[i] == doctest::Approx(b.x[i]).epsilon(1e-9).scale(1.0));
    CHECK(a.d1[i] == doctest::Approx(b.d1[i]).epsilon(1e-6).scale(1.0));
    CHECK(a.d2[i] == doctest::Approx(b.d2[i]).epsilon(curv_tol).scale(curv_tol));
  }
}

}  // namespace

TEST_CASE("a 90 degree corner blend: deviation from the corner equals its radius") {
  const Segment in = Segment::line(3, 0b111, vec(0, 0), vec(10, 0));
  const Segment out = Segment::line(3, 0b111, vec(10, 0), vec(10, 10));
  const auto blend = make_blend(in, out, 1.0, 5.0, 5.0);
  REQUIRE(blend);
  CHECK(blend->radius == doctest::Approx(1.0));
  CHECK(blend->cut_in == doctest::Approx(1.0));
  CHECK(blend->cut_out == doctest::Approx(1.0));
  const auto [hi, lo] = distance_range(blend->curve, vec(10, 0));
  CHECK(hi == doctest::Approx(1.0));  // the ends are on the ball, nothing leaves it
  CHECK(lo > 0.2);                    // the apex stays clear of the corner
  CHECK(lo < 0.5);
  // Ends: position, tangent and curvature (0 on a line) continuous: C2 joints.
  const Segment in_t = in.trimmed(0, in.length() - blend->cut_in);
  const Segment out_t = out.trimmed(blend->cut_out, out.length());
  check_joint(in_t.at(in_t.length()), blend->curve.at(0), 1e-6);
  check_joint(blend->curve.at(blend->curve.length()), out_t.at(0), 1e-6);
  CHECK(classify(in_t.at(in_t.length()), blend->curve.at(0), 3, 0b111) == TransitionClass::c2);
}

TEST_CASE("the ball shrinks so that it takes at most half of a neighbouring block") {
  const Segment in = Segment::line(3, 0b111, vec(0, 0), vec(10, 0));
  const Segment out = Segment::line(3, 0b111, vec(10, 0), vec(10, 1));
  const auto blend = make_blend(in, out, 2.0, in.length() / 2, out.length() / 2);
  REQUIRE(blend);
  CHECK(blend->radius == doctest::Approx(0.5));
  CHECK(blend->cut_out == doctest::Approx(0.5));
  CHECK(blend->cut_in == doctest::Approx(0.5));
}

TEST_CASE(
    "DIST: a 90 degree corner blend starts PRE_DIST before the corner, ends POST_DIST "
    "after it") {
  // isg-language.md §5.3 (PROG-475180811): PRE_DIST on the incoming block, POST_DIST on the
  // outgoing one.
  const Segment in = Segment::line(3, 0b111, vec(0, 0), vec(10, 0));
  const Segment out = Segment::line(3, 0b111, vec(10, 0), vec(10, 10));
  const auto blend = make_blend(in, out, joint_ends(in, out), CornerDistances{2.0, 0.5, false},
                                in.length() / 2, out.length() / 2);
  REQUIRE(blend);
  CHECK(blend->cut_in == doctest::Approx(2.0));
  CHECK(blend->cut_out == doctest::Approx(0.5));
  const AxisVec start = blend->curve.point(0.0);
  const AxisVec end = blend->curve.point(blend->curve.length());
  CHECK(start[0] == doctest::Approx(8.0));
  CHECK(start[1] == doctest::Approx(0.0).epsilon(1e-12));
  CHECK(end[0] == doctest::Approx(10.0));
  CHECK(end[1] == doctest::Approx(0.5));
  // Inside the ball of radius max(PRE_DIST, POST_DIST), its farthest point the start.
  CHECK(blend->radius == doctest::Approx(2.0));
  const auto [hi, lo] = distance_range(blend->curve, vec(10, 0));
  CHECK(hi == doctest::Approx(2.0));
  CHECK(lo > 0.0);
  // G2 contact with both trimmed neighbours.
  const Segment in_t = in.trimmed(0, in.length() - blend->cut_in);
  const Segment out_t = out.trimmed(blend->cut_out, out.length());
  check_joint(in_t.at(in_t.length()), blend->curve.at(0), 1e-6);
  check_joint(blend->curve.at(blend->curve.length()), out_t.at(0), 1e-6);
  CHECK(classify(in_t.at(in_t.length()), blend->curve.at(0), 3, 0b111) == TransitionClass::c2);
  CHECK(classify(blend->curve.at(blend->curve.length()), out_t.at(0), 3, 0b111) ==
        TransitionClass::c2);
}

TEST_CASE("DIST: each corner distance is capped at half of its own block, DEV's ball at both") {
  const Segment in = Segment::line(3, 0b111, vec(0, 0), vec(10, 0));
  const Segment out = Segment::line(3, 0b111, vec(10, 0), vec(10, 1));
  const JointEnds ends = joint_ends(in, out);
  const auto dist = make_blend(in, out, ends, CornerDistances{2.0, 2.0, false}, in.length() / 2,
                               out.length() / 2);
  REQUIRE(dist);
  CHECK(dist->cut_in == doctest::Approx(2.0));   // the 10 mm block gives its 2 mm
  CHECK(dist->cut_out == doctest::Approx(0.5));  // the 1 mm block half of itself
  CHECK(dist->radius == doctest::Approx(2.0));
  const auto dev =
      make_blend(in, out, ends, CornerDistances{2.0, 2.0, true}, in.length() / 2, out.length() / 2);
  REQUIRE(dev);
  CHECK(dev->cut_in == doctest::Approx(0.5));
  CHECK(dev->cut_out == doctest::Approx(0.5));
}

TEST_CASE("DIST: the derivative bounds of a blend with uneven ends cover the curve") {
  // With the 65 samples of a symmetric blend, the 170 degree corner at POST_DIST = PRE_DIST / 4
  // under-estimated |x'''| by 54 % and random DIST programs exceeded the jerk limit
  // (docs/planner.md "Geometry"): uneven blends are sampled as spline pieces.
  for (const double turn_deg : {90.0, 135.0, 170.0}) {
    const double turn = turn_deg * std::numbers::pi / 180.0;
    const Segment in = Segment::line(3, 0b111, vec(0, 0), vec(10, 0));
    const Segment out =
        Segment::line(3, 0b111, vec(10, 0), vec(10 + 10 * std::cos(turn), 10 * std::sin(turn)));
    const auto blend =
        make_blend(in, out, joint_ends(in, out), CornerDistances{2.0, 0.5, false}, 5.0, 5.0);
    REQUIRE(blend);
    const DerivativeBounds b = blend->curve.bounds();
    double d2 = 0.0;  // largest sampled |x''_i| / bound
    double d3 = 0.0;  // largest sampled |x'''_i| / bound
    const double len = blend->curve.length();
    for (int k = 0; k <= 20000; ++k) {
      const PathPoint p = blend->curve.at(len * k / 20000.0);
      for (std::size_t i = 0; i < 2; ++i) {
        d2 = std::max(d2, std::abs(p.d2[i]) / std::max(b.d2[i], 1e-300));
        d3 = std::max(d3, std::abs(p.d3[i]) / std::max(b.d3[i], 1e-300));
      }
    }
    CAPTURE(turn_deg);
    CHECK(d2 <= 1.0);
    CHECK(d3 <= 1.0);
  }
}

TEST_CASE("a DEV ball is the symmetric corner distance: the same curve bit for bit") {
  const Segment in = Segment::line(3, 0b111, vec(0, 0), vec(10, 0));
  const Segment out = Segment::line(3, 0b111, vec(10, 0), vec(13, 4));
  Move m;
  m.contour = Contour::tolerance;
  m.path_dev = 0.7;
  const auto ball = make_blend(in, out, 0.7, 5.0, 2.5);
  const auto via_move = corner_blend(m, in, out, 5.0, 2.5);
  REQUIRE(ball);
  REQUIRE(via_move);
  CHECK(via_move->cut_in == ball->cut_in);
  CHECK(via_move->cut_out == ball->cut_out);
  CHECK(via_move->radius == ball->radius);
  for (const double f : {0.0, 0.3, 1.0})
    CHECK(via_move->curve.point(f * ball->curve.length()) ==
          ball->curve.point(f * ball->curve.length()));
  m.contour = Contour::distance;  // DIST reads PRE_DIST / POST_DIST, not PATH_DEV
  m.pre_dist = 1.5;
  m.post_dist = 0.25;
  const auto dist = corner_blend(m, in, out, 5.0, 2.5);
  REQUIRE(dist);
  CHECK(dist->cut_in == doctest::Approx(1.5));
  CHECK(dist->cut_out == doctest::Approx(0.25));
  m.contour = Contour::none;
  CHECK_FALSE(corner_blend(m, in, out, 5.0, 2.5));
}

TEST_CASE("collinear joints and reversals are not blended") {
  const Segment in = Segment::line(3, 0b111, vec(0, 0), vec(10, 0));
  CHECK_FALSE(make_blend(in, Segment::line(3, 0b111, vec(10, 0), vec(20, 0)), 1, 5, 5));
  CHECK_FALSE(make_blend(in, Segment::line(3, 0b111, vec(10, 0), vec(0, 0.01)), 1, 5, 5));
}

TEST_CASE("a line into an arc: the blend matches the arc's curvature at its end") {
  const Segment in = Segment::line(3, 0b111, vec(0, 0), vec(10, 0));
  Move m;
  m.start = vec(10, 0);
  m.end = vec(10, 20);
  m.feed = 10;
  m.arc = Arc{0, 1, 10.0 + 10.0, 10.0, true, false};  // G02, R = 10 centred at (20, 10)
  const Segment out = Segment::arc(m);
  const auto blend = make_blend(in, out, 0.5, 5.0, out.length() / 2);
  REQUIRE(blend);
  const Segment out_t = out.trimmed(blend->cut_out, out.length());
  check_joint(blend->curve.at(blend->curve.length()), out_t.at(0), 1e-5);
  const auto [hi, lo] = distance_range(blend->curve, vec(10, 0));
  CHECK(hi <= blend->radius * (1 + 1e-9));
  (void)lo;
}

TEST_CASE("property: random corners keep the blend inside its ball and join with G2") {
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int blended = 0;
  for (int n = 0; n < 400; ++n) {
    const AxisVec corner = vec(5 * u(rng), 5 * u(rng), 5 * u(rng));
    auto random_dir = [&] {
      AxisVec d = vec(u(rng), u(rng), u(rng));
      const double l = dist(d, AxisVec{});
      for (std::size_t i = 0; i < 3; ++i)
        d[i] /= l;
      return d;
    };
    const AxisVec d_in = random_dir();
    const AxisVec d_out = random_dir();
    const double l_in = 0.1 + 20 * std::abs(u(rng));
    const double l_out = 0.1 + 20 * std::abs(u(rng));
    AxisVec a{}, b{};
    for (std::size_t i = 0; i < 3; ++i) {
      a[i] = corner[i] - l_in * d_in[i];
      b[i] = corner[i] + l_out * d_out[i];
    }
    Segment in = Segment::line(3, 0b111, a, corner);
    Segment out = Segment::line(3, 0b111, corner, b);
    if (n % 2 == 1) {
      // Replace the outgoing line by an arc in XY starting at the corner.
      Move m;
      m.start = corner;
      const double r = 0.5 + 10 * std::abs(u(rng));
      const double phi = std::atan2(d_in[1], d_in[0]) + 3 * u(rng);
      m.arc = Arc{0,          1,    corner[0] - r * std::cos(phi), corner[1] - r * std::sin(phi),
                  n % 4 == 1, false};
      const double phi1 = phi + 2 * u(rng);
      m.end = vec(m.arc->centre_1 + r * std::cos(phi1), m.arc->centre_2 + r * std::sin(phi1),
                  corner[2] + u(rng));
      m.feed = 1;
      out = Segment::arc(m);
    }
    const double radius = 0.001 + 3 * std::abs(u(rng));
    const auto blend = make_blend(in, out, radius, in.length() / 2, out.length() / 2);
    const double angle = tangent_angle(in.at(in.length()).d1, out.at(0).d1, 3, 0b111);
    if (angle > kMaxBlendAngle) {
      CHECK_FALSE(blend);
      continue;
    }
    REQUIRE(blend);
    ++blended;
    CHECK(blend->radius <= radius);
    CHECK(blend->cut_in <= in.length() / 2 * (1 + 1e-12));
    CHECK(blend->cut_out <= out.length() / 2 * (1 + 1e-12));
    const auto [hi, lo] = distance_range(blend->curve, corner);
    CHECK(hi <= blend->radius * (1 + 1e-9));
    CHECK(hi >= blend->radius * (1 - 1e-9));
    const Segment in_t = in.trimmed(0, in.length() - blend->cut_in);
    const Segment out_t = out.trimmed(blend->cut_out, out.length());
    check_joint(in_t.at(in_t.length()), blend->curve.at(0), 1e-5);
    check_joint(blend->curve.at(blend->curve.length()), out_t.at(0), 1e-5);
    // The 16-interval arc-length table (docs/planner.md "Blends"): the curve's length from 0 to
    // s, measured as chord sums over 1000 and 2000 pieces with Richardson's step (error
    // O(h^4)), equals s to 1e-9 of the length, at the end and inside the table (the worst of
    // these 800 blends is 3.3e-11, a 2.5 mm ball into an arc of small radius: 8e-11 mm).
    const double len = blend->curve.length();
    for (const double s_end : {0.37 * len, len}) {
      CHECK(std::abs(chord_length(blend->curve, s_end) - s_end) <= 1e-9 * len);
    }
  }
  CHECK(blended > 350);
}

TEST_CASE("property: DIST blends of random corners stay within max(PRE_DIST, POST_DIST)") {
  std::mt19937 rng(261);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int blended = 0;
  int at_distances = 0;
  for (int n = 0; n < 400; ++n) {
    const AxisVec corner = vec(5 * u(rng), 5 * u(rng), 5 * u(rng));
    auto point = [&](double l) {
      AxisVec d = vec(u(rng), u(rng), u(rng));
      const double norm = dist(d, AxisVec{});
      for (std::size_t i = 0; i < 3; ++i)
        d[i] = corner[i] + l * d[i] / norm;
      return d;
    };
    const Segment in = Segment::line(3, 0b111, point(0.1 + 20 * std::abs(u(rng))), corner);
    Segment out = Segment::line(3, 0b111, corner, point(0.1 + 20 * std::abs(u(rng))));
    if (n % 2 == 1) {  // an arc in XY out of the corner
      Move m;
      m.start = corner;
      const double r = 0.5 + 10 * std::abs(u(rng));
      const double phi = 3.2 * u(rng);
      m.arc = Arc{0,          1,    corner[0] - r * std::cos(phi), corner[1] - r * std::sin(phi),
                  n % 4 == 1, false};
      m.end = vec(m.arc->centre_1 + r * std::cos(phi + 2 * u(rng)),
                  m.arc->centre_2 + r * std::sin(phi + 2 * u(rng)), corner[2] + u(rng));
      m.feed = 1;
      out = Segment::arc(m);
    }
    const CornerDistances d{0.001 + 3 * std::abs(u(rng)), 0.001 + 3 * std::abs(u(rng)), false};
    const auto blend =
        make_blend(in, out, joint_ends(in, out), d, in.length() / 2, out.length() / 2);
    const double angle = tangent_angle(in.at(in.length()).d1, out.at(0).d1, 3, 0b111);
    if (angle > kMaxBlendAngle) {
      CHECK_FALSE(blend);
      continue;
    }
    REQUIRE(blend);
    ++blended;
    CHECK(blend->radius <= std::max(d.in, d.out));
    CHECK(blend->cut_in <= in.length() / 2 * (1 + 1e-12));
    CHECK(blend->cut_out <= out.length() / 2 * (1 + 1e-12));
    const double e_in = dist(blend->curve.point(0.0), corner);
    const double e_out = dist(blend->curve.point(blend->curve.length()), corner);
    CHECK(e_in <= d.in * (1 + 1e-9));
    CHECK(e_out <= d.out * (1 + 1e-9));
    CHECK(std::max(e_in, e_out) == doctest::Approx(blend->radius).epsilon(1e-9));
    // Neither end capped nor shrunk: the ends are exactly at PRE_DIST and POST_DIST.
    if (std::abs(e_in - d.in) <= 1e-9 * d.in && std::abs(e_out - d.out) <= 1e-9 * d.out)
      ++at_distances;
    const auto [hi, lo] = distance_range(blend->curve, corner);
    CHECK(hi <= blend->radius * (1 + 1e-9));
    (void)lo;
    const Segment in_t = in.trimmed(0, in.length() - blend->cut_in);
    const Segment out_t = out.trimmed(blend->cut_out, out.length());
    check_joint(in_t.at(in_t.length()), blend->curve.at(0), 1e-5);
    check_joint(blend->curve.at(blend->curve.length()), out_t.at(0), 1e-5);
  }
  CHECK(blended > 350);
  CHECK(at_distances > 200);
}
