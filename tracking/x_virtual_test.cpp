// The static processing unit, P-CHAN-00364 x_virtual (seed 004 §2.1.6 l.432-443, §4.1.2
// l.617-621; seed-reading question 13, A22): the belt feed whose X component is the belt's, the
// direction rule, the "dynamic error" NC9100 (docs/conveyor.md "Static processing unit").

#include "tracking/x_virtual.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "planner/move.hpp"

namespace {

using ncsim::planner::AxisLimits;
using ncsim::planner::Move;
using ncsim::tracking::belt_feed;
using ncsim::tracking::XVirtualParams;

Move line(double x0, double y0, double x1, double y1) {
  Move m;
  m.axis_count = 4;
  m.path_axes = 0b111;
  m.start[0] = x0;
  m.start[1] = y0;
  m.end[0] = x1;
  m.end[1] = y1;
  m.feed = 100.0 / 60.0;  // F100: ignored (004 l.1011)
  return m;
}

std::vector<AxisLimits> limits(double y_a_max = 10000.0, double x_v_max = 2000.0) {
  AxisLimits l{1000.0, 1000.0, 1000.0, 20000.0, 20000.0, 200000.0, 1.0, 0.0, 0.0};
  std::vector<AxisLimits> v(4, l);
  v[0].v_max = v[0].v_reference = v[0].v_rapid = x_v_max;
  v[1].a_max = v[1].d_max = y_a_max;
  return v;
}

const std::vector<std::string> kNames{"X", "Y", "Z", "C"};

}  // namespace

TEST_CASE("A22: the diagonal X-550 Y-550 gets the feed whose X component is the belt's") {
  const XVirtualParams p{0, 1.0, 200.0, 0b111};
  const auto o = belt_feed(line(0, 0, -550, -550), p, limits(), kNames);
  REQUIRE_FALSE(o.error);
  REQUIRE(o.moves.size() == 1);
  // Y moves like the virtual X, at 200 mm/s: the path at sqrt(2) * 200 mm/s, 2.75 s.
  CHECK(o.moves[0].feed == doctest::Approx(200.0 * std::sqrt(2.0)));
  CHECK(ncsim::tracking::line_belt_feed(line(0, 0, -550, -550), p) ==
        doctest::Approx(200.0 * std::sqrt(2.0)));
  CHECK_FALSE(o.moves[0].rapid);
}

TEST_CASE("a block along the belt or with it is NC9102; the sign follows P-CHAN-00363") {
  const XVirtualParams p{0, 1.0, 200.0, 0b111};
  const auto o = belt_feed(line(0, 0, 0, -50), p, limits(), kNames);
  REQUIRE(o.error);
  CHECK(std::string(o.error->id) == "NC9102");
  CHECK(belt_feed(line(0, 0, 50, 0), p, limits(), kNames).error);
  const XVirtualParams q{0, -1.0, 200.0, 0b111};  // the belt moves in -X: the contour runs +X
  CHECK_FALSE(belt_feed(line(0, 0, 50, 0), q, limits(), kNames).error);
}

TEST_CASE("a spline is cut into parts whose X component stays within 1 % of the belt") {
  const XVirtualParams p{0, 1.0, 300.0, 0b111};
  Move m = line(0, 0, -200, -30);
  auto c = std::make_shared<ncsim::planner::SplineControl>();
  c->c1[0] = -50;
  c->c2[0] = -150;
  c->c1[1] = 0;
  c->c2[1] = -40;
  m.spline = std::move(c);
  const auto o = belt_feed(m, p, limits(), kNames);
  REQUIRE_FALSE(o.error);
  CHECK(o.moves.size() > 1);
  for (const Move& part : o.moves) {
    for (double u = 0.0; u <= 1.0; u += 0.125) {
      const double w = 1.0 - u;
      auto d = [&](std::size_t i) {
        return 3 * (w * w * (part.spline->c1[i] - part.start[i]) +
                    2 * w * u * (part.spline->c2[i] - part.spline->c1[i]) +
                    u * u * (part.end[i] - part.spline->c2[i]));
      };
      const double vx = part.feed * std::fabs(d(0)) / std::hypot(d(0), d(1));
      CHECK(vx == doctest::Approx(300.0).epsilon(0.011));
    }
  }
}

TEST_CASE("NC9100: a belt too fast for Y's acceleration on the curve is a dynamic error") {
  Move m = line(0, 0, -200, -30);
  auto c = std::make_shared<ncsim::planner::SplineControl>();
  c->c1[0] = -50;
  c->c2[0] = -150;
  c->c1[1] = 0;
  c->c2[1] = -40;
  m.spline = std::move(c);
  const XVirtualParams slow{0, 1.0, 300.0, 0b111};
  CHECK_FALSE(belt_feed(m, slow, limits(), kNames).error);
  const XVirtualParams fast{0, 1.0, 3000.0, 0b111};
  const auto o = belt_feed(m, fast, limits(), kNames);
  REQUIRE(o.error);
  CHECK(std::string(o.error->id) == "NC9100");
  CHECK(o.error->message.find("axis Y") != std::string::npos);
  // The virtual X is planned in PCS1 at the belt's velocity: its list must allow it (004
  // l.617-618: "a simulation axis with sufficient dynamics to cater for the conveyor").
  const auto x = belt_feed(m, fast, limits(1e7), kNames);
  REQUIRE(x.error);
  CHECK(x.error->message.find("axis X") != std::string::npos);
  // The same contour passes at the fast belt when X and Y can follow.
  std::vector<AxisLimits> big = limits(1e7, 1e5);
  big[0].a_max = big[0].d_max = 1e7;
  const auto ok = belt_feed(m, fast, big, kNames);
  CHECK_MESSAGE(!ok.error, (ok.error ? ok.error->message : std::string()));
}

TEST_CASE("a tolerance ball raises both neighbours' feeds to the belt feed of its steepest point") {
  using ncsim::tracking::blend_belt_feed;
  using ncsim::tracking::line_belt_feed;
  const XVirtualParams p{0, 1.0, 66.0, 0b111};
  SUBCASE("+-45 deg: the ball's X share is 0.707 at its ends, its lines' own; feeds kept") {
    Move in = line(0, 0, -100, -100);
    in.contour = ncsim::planner::Contour::tolerance;
    in.path_dev = 20.0;
    Move out = line(-100, -100, -200, 0);
    in.feed = line_belt_feed(in, p);
    out.feed = line_belt_feed(out, p);
    const auto e = blend_belt_feed(in, out, p, limits(), kNames);
    CHECK_FALSE(e);
    CHECK(in.feed == doctest::Approx(66.0 * std::sqrt(2.0)).epsilon(1e-6));
    CHECK(out.feed == doctest::Approx(66.0 * std::sqrt(2.0)).epsilon(1e-6));
  }
  SUBCASE("steep (X share 0.447) into flat (0.832): the flat line is raised to the steep one's") {
    Move in = line(0, 0, -50, -100);
    in.contour = ncsim::planner::Contour::tolerance;
    in.path_dev = 20.0;
    Move out = line(-50, -100, -200, 0);
    in.feed = line_belt_feed(in, p);
    out.feed = line_belt_feed(out, p);
    const double steep = in.feed;
    CHECK(out.feed < 0.6 * steep);
    const auto e = blend_belt_feed(in, out, p, limits(), kNames);
    CHECK_FALSE(e);
    CHECK(in.feed == doctest::Approx(steep).epsilon(1e-3));  // the ball's steepest: its start
    CHECK(out.feed == doctest::Approx(in.feed));
  }
  SUBCASE("a 2 mm ball for a belt at 330 mm/s: Y cannot turn the path that fast, NC9100") {
    const XVirtualParams fast{0, 1.0, 330.0, 0b111};
    Move in = line(0, 0, -100, -100);
    in.contour = ncsim::planner::Contour::tolerance;
    in.path_dev = 2.0;
    Move out = line(-100, -100, -200, 0);
    const auto e = blend_belt_feed(in, out, fast, limits(), kNames);
    REQUIRE(e);
    CHECK(std::string(e->id) == "NC9100");
    CHECK(e->message.find("tolerance ball") != std::string::npos);
    CHECK(e->message.find("axis Y") != std::string::npos);
  }
  SUBCASE("DIST: the curve is the planner's, from PRE_DIST to POST_DIST (not PATH_DEV's ball)") {
    const XVirtualParams fast{0, 1.0, 330.0, 0b111};
    Move in = line(0, 0, -100, -100);
    in.contour = ncsim::planner::Contour::distance;
    in.path_dev = 20.0;  // DEV's, not read under DIST
    in.pre_dist = 2.0;
    in.post_dist = 0.5;
    Move out = line(-100, -100, -200, 0);
    const auto e = blend_belt_feed(in, out, fast, limits(), kNames);
    REQUIRE(e);
    CHECK(std::string(e->id) == "NC9100");
    CHECK(e->message.find("radius 2 mm") != std::string::npos);  // max(PRE_DIST, POST_DIST)
  }
  SUBCASE("collinear blocks get no ball: nothing changes") {
    Move in = line(0, 0, -100, -100);
    in.contour = ncsim::planner::Contour::tolerance;
    Move out = line(-100, -100, -200, -200);
    in.feed = out.feed = 5.0;
    CHECK_FALSE(blend_belt_feed(in, out, p, limits(), kNames));
    CHECK(in.feed == 5.0);
    CHECK(out.feed == 5.0);
  }
}

TEST_CASE("a joint without a ball that the planner passes below the belt's need is NC9100") {
  // A line along -X into a tangent G02 arc of R 300 turning towards +Y: the
  // curvature jumps by 1/300 mm^-1, all of it in Y (a C1 joint). The planner's C1 rule allows
  // sqrt(j_Y T / |dx''_Y|) = sqrt(200000 x 0.001 x 300) = 244.9 mm/s there (T = 1 ms); the X
  // share at the joint is 1, so the path must pass it at the belt's velocity.
  using ncsim::planner::SlopeType;
  using ncsim::tracking::joint_belt_check;
  Move in = line(0, 0, -100, 0);
  Move out = line(-100, 0, -100 - 300 * std::sin(0.5), 300 - 300 * std::cos(0.5));
  out.arc = ncsim::planner::Arc{0, 1, -100.0, 300.0, true, false};
  in.slope = out.slope = SlopeType::trapez;
  const ncsim::planner::ChannelLimits channel;  // T = 1 ms, the C1 rule on
  SUBCASE("a belt at 300 mm/s: the C1 rule's 244.9 mm/s is too slow, NC9100 naming Y's jerk") {
    const auto e =
        joint_belt_check(in, out, XVirtualParams{0, 1.0, 300.0, 0b111}, limits(), channel, kNames);
    REQUIRE(e);
    CHECK(std::string(e->id) == "NC9100");
    CHECK(e->message.find("a C1 joint") != std::string::npos);
    CHECK(e->message.find("axis Y's jerk (the C1 rule") != std::string::npos);
    CHECK(e->message.find("244.9") != std::string::npos);
  }
  SUBCASE("a G261 on a tangent joint gets no ball (nothing to blend): still NC9100") {
    in.contour = ncsim::planner::Contour::tolerance;
    in.path_dev = 5.0;
    CHECK(
        joint_belt_check(in, out, XVirtualParams{0, 1.0, 300.0, 0b111}, limits(), channel, kNames));
  }
  SUBCASE("a belt at 200 mm/s passes") {
    CHECK_FALSE(
        joint_belt_check(in, out, XVirtualParams{0, 1.0, 200.0, 0b111}, limits(), channel, kNames));
  }
  SUBCASE("STEP slopes allow acceleration steps (no C1 rule): passes") {
    in.slope = out.slope = SlopeType::step;
    CHECK_FALSE(
        joint_belt_check(in, out, XVirtualParams{0, 1.0, 300.0, 0b111}, limits(), channel, kNames));
  }
  SUBCASE("two collinear lines (C2) pass at any belt") {
    const Move on = line(-100, 0, -200, 0);
    CHECK_FALSE(
        joint_belt_check(in, on, XVirtualParams{0, 1.0, 1000.0, 0b111}, limits(), channel, kNames));
  }
}
