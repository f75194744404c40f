// The static unit's belt feed on arcs (--- static-saw; docs/conveyor.md "Static processing
// unit", decision "arcs"): the X component of the path velocity is the belt's velocity, so on
// an arc, whose X share varies, the path velocity varies along it; the arc is halved by angle
// until the X share varies by at most 1 % over each part, each part with its own feed; where
// the tangent turns perpendicular to the belt the velocity needed grows without bound and the
// axes' limits make it the dynamic error NC9100; an arc that turns X back is NC9102.

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "planner/move.hpp"
#include "tracking/x_virtual.hpp"

namespace {

using ncsim::planner::AxisLimits;
using ncsim::planner::Move;
using ncsim::tracking::belt_feed;
using ncsim::tracking::XVirtualParams;

constexpr double kDeg = 3.141592653589793 / 180.0;

// An XY arc (G17) about the origin of radius r from angle a0 to a1 [deg], counter-clockwise
// (G03) when a1 > a0; C (slot 3) from c0 to c1.
Move arc(double r, double a0, double a1, double c0 = 0.0, double c1 = 0.0) {
  Move m;
  m.axis_count = 4;
  m.path_axes = 0b111;
  m.start[0] = r * std::cos(a0 * kDeg);
  m.start[1] = r * std::sin(a0 * kDeg);
  m.end[0] = r * std::cos(a1 * kDeg);
  m.end[1] = r * std::sin(a1 * kDeg);
  m.start[3] = c0;
  m.end[3] = c1;
  m.arc = ncsim::planner::Arc{0, 1, 0.0, 0.0, a1 < a0, false};
  m.feed = 100.0 / 60.0;  // F100: ignored (004 l.1011)
  m.event_tag = 7;
  return m;
}

std::vector<AxisLimits> limits() {
  AxisLimits l{1000.0, 1000.0, 1000.0, 20000.0, 20000.0, 2000000.0, 1.0, 0.0, 0.0};
  std::vector<AxisLimits> v(4, l);
  v[0].v_max = v[0].v_reference = v[0].v_rapid = 2000.0;
  return v;
}

const std::vector<std::string> kNames{"X", "Y", "Z", "C"};

// The X component of the path velocity at angle phi [rad] of a part run at `feed`.
double vx(double feed, double phi) {
  return feed * std::fabs(std::sin(phi));
}

}  // namespace

TEST_CASE("an arc is cut into parts whose X component stays within 1 % of the belt") {
  const XVirtualParams p{0, 1.0, 300.0, 0b111};
  const Move m = arc(100.0, 30.0, 150.0, 0.0, 120.0);  // X 86.6 -> -86.6: against the belt
  const auto o = belt_feed(m, p, limits(), kNames);
  if (o.error) MESSAGE(o.error->message);
  REQUIRE_FALSE(o.error);
  REQUIRE(o.moves.size() > 4);
  CHECK(o.moves.front().start[0] == m.start[0]);
  CHECK(o.moves.back().end[0] == doctest::Approx(m.end[0]));
  CHECK(o.moves.back().end[1] == doctest::Approx(m.end[1]));
  CHECK(o.moves.front().event_tag == 7);
  double turned = 0.0;
  for (std::size_t k = 0; k < o.moves.size(); ++k) {
    const Move& part = o.moves[k];
    REQUIRE(part.arc);
    CHECK(part.arc->centre_1 == 0.0);
    CHECK_FALSE(part.arc->clockwise);
    if (k > 0) {
      CHECK(part.event_tag == 0);  // the block's events fire once
      CHECK(part.start[0] == doctest::Approx(o.moves[k - 1].end[0]));
      CHECK(part.start[1] == doctest::Approx(o.moves[k - 1].end[1]));
    }
    const double a0 = std::atan2(part.start[1], part.start[0]);
    const double a1 = std::atan2(part.end[1], part.end[0]);
    CHECK(std::hypot(part.end[0], part.end[1]) == doctest::Approx(100.0));
    for (const double phi : {a0, 0.5 * (a0 + a1), a1}) {  // every point of the part
      CHECK(vx(part.feed, phi) >= 300.0 * 0.99);
      CHECK(vx(part.feed, phi) <= 300.0 * 1.01);
    }
    // C stays linear in the angle (the #CAXTRACK tangent of an arc, tracking/caxtrack.hpp).
    CHECK(part.start[3] == doctest::Approx((a0 / kDeg - 30.0)).epsilon(1e-9));
    turned += (a1 - a0) / kDeg;
  }
  CHECK(turned == doctest::Approx(120.0));
  // The path is fastest where the arc is steepest against the belt: at 30 and 150 deg,
  // 300 / sin 30 = 600 mm/s; at 90 deg it is the belt's 300 mm/s.
  CHECK(o.moves.front().feed == doctest::Approx(600.0).epsilon(0.02));
  double slowest = 1e9;
  for (const Move& part : o.moves)
    slowest = std::min(slowest, part.feed);
  CHECK(slowest == doctest::Approx(300.0).epsilon(0.01));
}

TEST_CASE("a quarter circle ending tangent to Y needs an unbounded path velocity: NC9100") {
  const XVirtualParams p{0, 1.0, 300.0, 0b111};
  const auto o = belt_feed(arc(100.0, 90.0, 180.0), p, limits(), kNames);
  REQUIRE(o.error);
  CHECK(std::string(o.error->id) == "NC9100");
  CHECK(o.error->message.find("x_virtual") != std::string::npos);
  // Stopping short of the tangent point, where the belt needs <= 1000 mm/s (sin >= 0.3), runs.
  const double a1 = 180.0 - std::asin(0.31) / kDeg;
  {
    const auto e = belt_feed(arc(100.0, 90.0, a1), p, limits(), kNames);
    if (e.error) MESSAGE(e.error->message);
    CHECK_FALSE(e.error);
  }
  // A slower belt gets further: the cap is the axes' limit, not a fixed angle.
  const XVirtualParams slow{0, 1.0, 30.0, 0b111};
  const double a2 = 180.0 - std::asin(0.035) / kDeg;
  {
    const auto e = belt_feed(arc(100.0, 90.0, a2), slow, limits(), kNames);
    if (e.error) MESSAGE(e.error->message);
    CHECK_FALSE(e.error);
  }
  CHECK(belt_feed(arc(100.0, 90.0, a2), p, limits(), kNames).error);
}

TEST_CASE("an arc that turns X back along the belt is NC9102; the belt in -X takes G02 mirrored") {
  const XVirtualParams p{0, 1.0, 300.0, 0b111};
  const auto back = belt_feed(arc(100.0, 30.0, 210.0), p, limits(), kNames);
  REQUIRE(back.error);
  CHECK(std::string(back.error->id) == "NC9102");
  const auto with = belt_feed(arc(100.0, 150.0, 30.0), p, limits(), kNames);  // G02, +X
  REQUIRE(with.error);
  CHECK(std::string(with.error->id) == "NC9102");
  const XVirtualParams minus{0, -1.0, 300.0, 0b111};  // P-CHAN-00363: the belt moves in -X
  {
    const auto e = belt_feed(arc(100.0, 150.0, 30.0), minus, limits(), kNames);
    if (e.error) MESSAGE(e.error->message);
    CHECK_FALSE(e.error);
  }
}

TEST_CASE("split_arc halves by angle: the middle on the circle, the other axes linear") {
  Move m = arc(50.0, 0.0, 90.0, 10.0, 30.0);
  m.end[2] = 8.0;  // a helix's Z
  const auto [a, b] = ncsim::tracking::split_arc(m);
  CHECK(a.end[0] == doctest::Approx(50.0 * std::cos(45.0 * kDeg)));
  CHECK(a.end[1] == doctest::Approx(50.0 * std::sin(45.0 * kDeg)));
  CHECK(b.start[0] == a.end[0]);
  CHECK(a.end[2] == doctest::Approx(4.0));
  CHECK(a.end[3] == doctest::Approx(20.0));
  CHECK(b.end[3] == 30.0);
  CHECK(b.event_tag == 0);
}
