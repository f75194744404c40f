// Corners: classification and the link velocity (VELOJUMP 000 l.108, C1 budget, #TRANSVELMIN).
// Hand-checked cases (issue 12, seed-reading A2): C0 = 1, A = 10000 mm/s^2, T = 1 ms gives
// 10 mm/s at 90 degrees, 14.14 at 45, 5.86 at 135, and half the step (5) at a reversal.

#include "planner/corner.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace {

using namespace ncsim::planner;

constexpr double kDeg = std::numbers::pi / 180.0;

std::array<AxisLimits, 3> limits(double a, double c0 = 1.0, double j = 1e6) {
  AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = 1000.0;
  ax.a_max = ax.d_max = a;
  ax.j_max = j;
  ax.c0 = c0;
  return {ax, ax, ax};
}

PathPoint tangent(double angle_deg) {
  PathPoint p;
  p.d1[0] = std::cos(angle_deg * kDeg);
  p.d1[1] = std::sin(angle_deg * kDeg);
  return p;
}

double corner(double turn_deg, double c0 = 1.0, double v = 100.0,
              std::optional<double> vmin = std::nullopt) {
  const auto ax = limits(10000.0, c0);
  return link_velocity(tangent(0), tangent(turn_deg), 3, 0b111, ax, ChannelLimits{}, v, v, vmin,
                       true)
      .v_link;
}

}  // namespace

TEST_CASE("VELOJUMP: 90 degrees, C0 = 1, A = 10000 mm/s^2, T = 1 ms links at 10 mm/s") {
  CHECK(corner(90) == doctest::Approx(10.0));
  CHECK(corner(90, 4.0) == doctest::Approx(40.0));
}

TEST_CASE("VELOJUMP: 45 degrees gives 14.14 and 135 degrees 5.86 mm/s") {
  CHECK(corner(45) == doctest::Approx(14.1421356));
  CHECK(corner(45, 4.0) == doctest::Approx(56.5685425));
  CHECK(corner(135) == doctest::Approx(5.8578644));
  CHECK(corner(135, 4.0) == doctest::Approx(23.4314575));
}

TEST_CASE("VELOJUMP: a reversal without a stop gets half the step (axis step = v_jump)") {
  CHECK(corner(180) == doctest::Approx(5.0));
}

TEST_CASE("VELOJUMP: the link never exceeds min(v_in, v_out)") {
  const auto ax = limits(10000.0, 100.0);
  const Link link = link_velocity(tangent(0), tangent(90), 3, 0b111, ax, ChannelLimits{}, 30.0,
                                  50.0, std::nullopt, true);
  CHECK(link.v_link == doctest::Approx(30.0));
  CHECK(link.rule == LinkRule::segment_caps);
}

TEST_CASE("VELOJUMP uses min(A+, A-) of each axis and the slowest axis sets the link") {
  auto ax = limits(10000.0);
  ax[1].d_max = 2000.0;  // Y: v_jump = 2 mm/s
  const Link link = link_velocity(tangent(0), tangent(90), 3, 0b111, ax, ChannelLimits{}, 100, 100,
                                  std::nullopt, true);
  CHECK(link.v_link == doctest::Approx(2.0));
  CHECK(link.limiting_axis == 1);
  CHECK(link.rule == LinkRule::velojump);
  CHECK(link.cls == TransitionClass::c0);
  CHECK(link.zero_acceleration);
}

TEST_CASE("VELOJUMP scales with the interpolation cycle T") {
  const auto ax = limits(10000.0);
  ChannelLimits ch;
  ch.t_cycle = 0.004;
  CHECK(link_velocity(tangent(0), tangent(90), 3, 0b111, ax, ch, 100, 100, std::nullopt, true)
            .v_link == doctest::Approx(40.0));
}

TEST_CASE("#TRANSVELMIN has priority over VELOJUMP but stays within min(v_in, v_out)") {
  CHECK(corner(90, 1.0, 100.0, 20.0) == doctest::Approx(20.0));
  CHECK(corner(90, 1.0, 100.0, 5.0) == doctest::Approx(10.0));
  CHECK(corner(90, 1.0, 50.0, 1000.0) == doctest::Approx(50.0));
}

TEST_CASE("classification: knee C0, tangent with curvature jump C1, curvature continuous C2") {
  PathPoint line_end = tangent(0);
  PathPoint same = tangent(0);
  CHECK(classify(line_end, same, 3, 0b111) == TransitionClass::c2);
  PathPoint arc_start = tangent(0);
  arc_start.d2[1] = 0.1;  // tangent arc of radius 10
  CHECK(classify(line_end, arc_start, 3, 0b111) == TransitionClass::c1);
  PathPoint arc_end = arc_start;
  CHECK(classify(arc_end, arc_start, 3, 0b111) == TransitionClass::c2);
  CHECK(classify(line_end, tangent(1e-3 / kDeg), 3, 0b111) == TransitionClass::c0);
  CHECK(classify(line_end, tangent(1e-8 / kDeg), 3, 0b111) == TransitionClass::c2);
}

TEST_CASE("C1: the acceleration step of every axis stays within j_max * T") {
  // Line into a tangent arc of radius 10: the Y acceleration jumps by v^2 / 10.
  const auto ax = limits(10000.0, 1.0, 1e5);
  PathPoint arc_start = tangent(0);
  arc_start.d2[1] = 0.1;
  const Link link = link_velocity(tangent(0), arc_start, 3, 0b111, ax, ChannelLimits{}, 100, 100,
                                  std::nullopt, true);
  CHECK(link.cls == TransitionClass::c1);
  CHECK(link.rule == LinkRule::c1_jerk);
  CHECK(link.v_link == doctest::Approx(std::sqrt(1e5 * 1e-3 / 0.1)));  // 31.62 mm/s
  const double step = link.v_link * link.v_link * 0.1;
  CHECK(step == doctest::Approx(1e5 * 1e-3));
}

TEST_CASE("C1 is not limited for STEP slopes or when the channel switches it off") {
  const auto ax = limits(10000.0, 1.0, 1e5);
  PathPoint arc_start = tangent(0);
  arc_start.d2[1] = 0.1;
  CHECK(link_velocity(tangent(0), arc_start, 3, 0b111, ax, ChannelLimits{}, 100, 100, std::nullopt,
                      false)
            .v_link == doctest::Approx(100.0));
  ChannelLimits off;
  off.limit_c1_by_jerk = false;
  CHECK(link_velocity(tangent(0), arc_start, 3, 0b111, ax, off, 100, 100, std::nullopt, true)
            .v_link == doctest::Approx(100.0));
}

TEST_CASE("C2 transitions keep the segments' velocity and carry the acceleration") {
  const auto ax = limits(10000.0);
  const Link link = link_velocity(tangent(30), tangent(30), 3, 0b111, ax, ChannelLimits{}, 70, 80,
                                  std::nullopt, true);
  CHECK(link.cls == TransitionClass::c2);
  CHECK(link.v_link == doctest::Approx(70.0));
  CHECK_FALSE(link.zero_acceleration);
}

TEST_CASE("#TRANSVELMIN does not act at tangent transitions") {
  const auto ax = limits(10000.0, 1.0, 1e5);
  PathPoint arc_start = tangent(0);
  arc_start.d2[1] = 0.1;
  CHECK(link_velocity(tangent(0), arc_start, 3, 0b111, ax, ChannelLimits{}, 100, 100, 90.0, true)
            .v_link == doctest::Approx(std::sqrt(1e5 * 1e-3 / 0.1)));
}

TEST_CASE("a knee that limits nothing and fits the acceleration budget carries the acceleration") {
  // A = 10000 mm/s^2, J = 1e6 mm/s^3, T = 1 ms: budget 0.5 J T = 500 mm/s^2; the largest
  // path acceleration on the X-dominated tangent is 10000 / 1, so |dx'_i| <= 0.05 carries.
  const auto ax = limits(10000.0);
  const Link small = link_velocity(tangent(0), tangent(2.0), 3, 0b111, ax, ChannelLimits{}, 100,
                                   100, std::nullopt, true);
  CHECK(small.cls == TransitionClass::c0);
  CHECK(small.rule == LinkRule::segment_caps);
  CHECK(small.v_link == doctest::Approx(100.0));
  CHECK_FALSE(small.zero_acceleration);
  // 4 degrees: |dy'| = 0.0698 > 0.05, the velocity is not limited but the acceleration step
  // would exceed the budget: a = 0 there.
  const Link wider = link_velocity(tangent(0), tangent(4.0), 3, 0b111, ax, ChannelLimits{}, 100,
                                   100, std::nullopt, true);
  CHECK(wider.rule == LinkRule::segment_caps);
  CHECK(wider.zero_acceleration);
  // The same 2 degree knee at a feed VELOJUMP limits (10 / 0.0349 = 286 mm/s): a = 0.
  const Link fast = link_velocity(tangent(0), tangent(2.0), 3, 0b111, ax, ChannelLimits{}, 500, 500,
                                  std::nullopt, true);
  CHECK(fast.rule == LinkRule::velojump);
  CHECK(fast.zero_acceleration);
  CHECK(knee_carries_acceleration(tangent(0).d1, tangent(2.0).d1, ax, 0.001));
  CHECK_FALSE(knee_carries_acceleration(tangent(0).d1, tangent(2.0).d1, ax, 0.0001));
}

TEST_CASE("a knee into a curve: the curvature jump keeps the C1 budget as at a tangent joint") {
  // A line into an arc of radius 10 with a knee of 0.006 degrees (a CAM end point rounded):
  // VELOJUMP alone allows 100 mm/s (|dy'| = 1e-4: v <= 10 / 1e-4), but the Y acceleration
  // would jump by v^2 / 10 = 1000 mm/s^2 in one cycle, 10x the jerk budget j T = 100 mm/s^2.
  // The C1 rule (P-CHAN-00009 semantics) holds at C0 joints too: 31.62 mm/s, as tangent.
  const auto ax = limits(10000.0, 1.0, 1e5);
  PathPoint arc_start = tangent(1e-4 / kDeg);
  arc_start.d2[1] = 0.1;
  const Link knee = link_velocity(tangent(0), arc_start, 3, 0b111, ax, ChannelLimits{}, 100, 100,
                                  std::nullopt, true);
  CHECK(knee.cls == TransitionClass::c0);
  CHECK(knee.rule == LinkRule::c1_jerk);
  CHECK(knee.v_link == doctest::Approx(std::sqrt(1e5 * 1e-3 / 0.1)));
  CHECK(knee.zero_acceleration);
  // STEP slopes have no jerk budget: VELOJUMP alone (capped by the segments).
  CHECK(link_velocity(tangent(0), arc_start, 3, 0b111, ax, ChannelLimits{}, 100, 100, std::nullopt,
                      false)
            .v_link == doctest::Approx(100.0));
  // #TRANSVELMIN has priority over VELOJUMP at C0 (isg-language.md 5.6), not over this rule:
  // "jerk limitation is prioritised" (TF5200 PROG-207486091; issue 36 item 5). On a STEP
  // slope (no jerk limitation) it raises the link.
  const Link raised =
      link_velocity(tangent(0), arc_start, 3, 0b111, ax, ChannelLimits{}, 100, 100, 90.0, true);
  CHECK(raised.v_link == doctest::Approx(std::sqrt(1e5 * 1e-3 / 0.1)));
  CHECK(raised.rule == LinkRule::c1_jerk);
  const Link corner = link_velocity(tangent(0), tangent(90.0), 3, 0b111, ax, ChannelLimits{}, 100,
                                    100, 90.0, false);
  CHECK(corner.v_link == doctest::Approx(90.0));
  CHECK(corner.rule == LinkRule::transvelmin);
  // A knee between two lines has no curvature jump: unchanged (it carries, as above).
  const Link lines = link_velocity(tangent(0), tangent(2.0), 3, 0b111, limits(10000.0),
                                   ChannelLimits{}, 100, 100, std::nullopt, true);
  CHECK(lines.rule == LinkRule::segment_caps);
  CHECK_FALSE(lines.zero_acceleration);
}

TEST_CASE("a knee that carries the acceleration leaves half the budget to the curvature jump") {
  // A 2 degree knee into an arc: the knee's own step takes up to kKneeBudget j T, so the
  // curvature step v^2 |dk_i| must fit the other half for a != 0 at the joint.
  const auto ax = limits(10000.0);  // J = 1e6, T = 1 ms: budget 1000 mm/s^2
  PathPoint arc_start = tangent(2.0);
  arc_start.d2[0] = -std::sin(2.0 * kDeg) * 0.01;
  arc_start.d2[1] = std::cos(2.0 * kDeg) * 0.01;  // radius 100: the curvature step v^2 / 100
  // 100 mm/s: a step of 100 mm/s^2, within half the budget: carries.
  const Link slow = link_velocity(tangent(0), arc_start, 3, 0b111, ax, ChannelLimits{}, 100, 100,
                                  std::nullopt, true);
  CHECK(slow.rule == LinkRule::segment_caps);
  CHECK_FALSE(slow.zero_acceleration);
  // 250 mm/s: 625 mm/s^2, within the budget but not half of it: a = 0 at the joint.
  const Link fast = link_velocity(tangent(0), arc_start, 3, 0b111, limits(10000.0, 100.0),
                                  ChannelLimits{}, 250, 250, std::nullopt, true);
  CHECK(fast.rule == LinkRule::segment_caps);
  CHECK(fast.zero_acceleration);
}
