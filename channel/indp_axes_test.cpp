// Independent (INDP) axes: PTP profiles sampled per cycle, FEED / G00 / TIME, soft limits,
// replanning, per-axis override (002_* 2.2) and the INTERRUPTIBLE hook.

#include "channel/indp_axes.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "axes/profile.hpp"
#include "machines/machine.hpp"

namespace {

using ncsim::axes::Result;
using ncsim::channel::IndpAxes;
using ncsim::channel::IndpAxisConfig;
using ncsim::channel::IndpMove;

constexpr double kT = 0.001;

IndpAxisConfig axis_config(const char* name = "C") {
  IndpAxisConfig c;
  c.name = name;
  c.feed = {500.0, 2000.0, 1500.0, 40000.0};   // v_max, A+, A-, J
  c.rapid = {300.0, 1000.0, 1000.0, 20000.0};  // G00
  c.limits.min_enabled = true;
  c.limits.min_position = -1000.0;
  c.limits.max_enabled = true;
  c.limits.max_position = 1000.0;
  return c;
}

IndpAxes one_axis(double start = 0.0) {
  ncsim::planner::AxisVec p{};
  p[0] = start;
  return IndpAxes({axis_config()}, kT, p);
}

IndpMove feed_move(double target, double feed) {
  IndpMove m;
  m.target = target;
  m.feed = feed;
  return m;
}

// Runs axis 0 until in position (at most `max_cycles`); returns the cycles run.
int run_to_position(IndpAxes& ax, int max_cycles = 100000) {
  int n = 0;
  while (!ax.in_position(0) && n < max_cycles) {
    ax.step();
    ++n;
  }
  return n;
}

}  // namespace

TEST_CASE("an INDP FEED move runs its PTP profile and ends on the target bit for bit") {
  IndpAxes ax = one_axis();
  REQUIRE_FALSE(ax.command(0, feed_move(100.0, 200.0)));
  CHECK(ax.owned(0));
  CHECK_FALSE(ax.in_position(0));
  double v_peak = 0.0;
  double a_peak = 0.0;
  int n = 0;
  while (!ax.in_position(0)) {
    ax.step();
    ++n;
    v_peak = std::max(v_peak, std::abs(ax.setpoint(0).v));
    a_peak = std::max(a_peak, std::abs(ax.setpoint(0).a));
  }
  ncsim::axes::Profile ref;
  REQUIRE(ncsim::axes::plan_position({0.0, 0.0, 0.0}, {100.0, 0.0},
                                     {200.0, 2000.0, 1500.0, 40000.0}, ref) == Result::ok);
  CHECK(n == static_cast<int>(std::ceil(ref.duration() / kT - 1e-9)));
  CHECK(ax.setpoint(0).p == 100.0);
  CHECK(ax.setpoint(0).v == 0.0);
  CHECK(v_peak == doctest::Approx(200.0).epsilon(1e-6));
  CHECK(a_peak <= 2000.0 * (1.0 + 1e-9));
}

TEST_CASE(
    "G00 runs at the rapid velocity on the smaller slope; FEED above P-AXIS-00212 is capped") {
  IndpAxes ax = one_axis();
  IndpMove m;
  m.target = 400.0;
  m.rapid = true;
  REQUIRE_FALSE(ax.command(0, m));
  double v_peak = 0.0;
  double a_peak = 0.0;
  while (!ax.in_position(0)) {
    ax.step();
    v_peak = std::max(v_peak, std::abs(ax.setpoint(0).v));
    a_peak = std::max(a_peak, std::abs(ax.setpoint(0).a));
  }
  CHECK(v_peak == doctest::Approx(300.0).epsilon(1e-6));
  CHECK(a_peak <= 1000.0 * (1.0 + 1e-9));
  CHECK(ax.capped() == 0);
  REQUIRE_FALSE(ax.command(0, feed_move(-400.0, 5000.0)));
  CHECK(ax.capped() == 1);
  v_peak = 0.0;
  while (!ax.in_position(0)) {
    ax.step();
    v_peak = std::max(v_peak, std::abs(ax.setpoint(0).v));
  }
  CHECK(v_peak == doctest::Approx(500.0).epsilon(1e-6));
  CHECK(ax.setpoint(0).p == -400.0);
}

TEST_CASE("TIME= sets the motion's duration; a TIME shorter than possible runs the fastest") {
  IndpAxes ax = one_axis();
  IndpMove m;
  m.target = 50.0;
  m.time = 2.0;
  REQUIRE_FALSE(ax.command(0, m));
  CHECK(run_to_position(ax) == 2000);
  CHECK(ax.setpoint(0).p == 50.0);
  m.target = 0.0;
  m.time = 0.01;
  REQUIRE_FALSE(ax.command(0, m));
  CHECK(ax.capped() == 1);
  ncsim::axes::Profile ref;
  REQUIRE(ncsim::axes::plan_position({50.0, 0.0, 0.0}, {0.0, 0.0}, axis_config().feed, ref) ==
          Result::ok);
  CHECK(run_to_position(ax) == static_cast<int>(std::ceil(ref.duration() / kT - 1e-9)));
}

TEST_CASE("a target beyond a soft limit is rejected before the axis moves [NC5501/NC5502]") {
  IndpAxes ax = one_axis();
  const auto e = ax.command(0, feed_move(1000.5, 100.0));
  REQUIRE(e);
  CHECK(e->id == "NC5502");
  CHECK(e->message.find("P-AXIS-00178") != std::string::npos);
  CHECK_FALSE(ax.owned(0));
  CHECK(ax.in_position(0));
  const auto low = ax.command(0, feed_move(-1001.0, 100.0));
  REQUIRE(low);
  CHECK(low->id == "NC5501");
  CHECK_FALSE(ax.command(0, feed_move(1000.0, 100.0)));  // on the limit is allowed
}

TEST_CASE("a new command to a moving axis replans from its moving state, p v a continuous") {
  IndpAxes ax = one_axis();
  REQUIRE_FALSE(ax.command(0, feed_move(300.0, 400.0)));
  for (int k = 0; k < 600; ++k)
    ax.step();
  const ncsim::axes::Setpoint before = ax.setpoint(0);
  REQUIRE(before.v > 100.0);
  REQUIRE_FALSE(ax.command(0, feed_move(50.0, 400.0)));  // behind it: stop and return (002 2.3)
  double p_prev = before.p;
  double v_prev = before.v;
  double a_prev = before.a;
  int n = 0;
  while (!ax.in_position(0)) {
    ax.step();
    ++n;
    const ncsim::axes::Setpoint s = ax.setpoint(0);
    CHECK(std::abs(s.p - p_prev) <= 400.0 * kT * (1.0 + 1e-9));
    CHECK(std::abs(s.v - v_prev) <= 2000.0 * kT * (1.0 + 1e-9));
    CHECK(std::abs(s.a - a_prev) <= 40000.0 * kT * (1.0 + 1e-9));
    p_prev = s.p;
    v_prev = s.v;
    a_prev = s.a;
  }
  CHECK(n > 0);
  CHECK(ax.setpoint(0).p == 50.0);
}

TEST_CASE("axis override before the braking phase slows the motion; in it, it is kept [002 2.2]") {
  IndpAxes fast = one_axis();
  REQUIRE_FALSE(fast.command(0, feed_move(200.0, 400.0)));
  const int n_full = run_to_position(fast);

  IndpAxes slow = one_axis();
  REQUIRE_FALSE(slow.command(0, feed_move(200.0, 400.0)));
  for (int k = 0; k < 100; ++k)
    slow.step();
  CHECK(slow.set_override(0, 0.5) == Result::ok);
  double v_peak_after = 0.0;
  int n = 100;
  while (!slow.in_position(0)) {
    slow.step();
    ++n;
    if (n > 400) v_peak_after = std::max(v_peak_after, std::abs(slow.setpoint(0).v));
  }
  CHECK(n > n_full);
  CHECK(v_peak_after == doctest::Approx(200.0).epsilon(1e-6));  // 50 % of the level at start

  IndpAxes late = one_axis();
  REQUIRE_FALSE(late.command(0, feed_move(200.0, 400.0)));
  for (int k = 0; k < n_full - 20; ++k)
    late.step();
  CHECK(late.set_override(0, 0.5) == Result::ignored_braking_phase);
  CHECK(late.override_fraction(0) == 0.5);  // kept for the next command
  CHECK(run_to_position(late) == 20);
  CHECK(late.set_override(0, 1.5) == Result::error_invalid_input);
}

TEST_CASE("axis override 0 stops and holds with the target kept; a start at 0 % holds at once") {
  IndpAxes ax = one_axis();
  REQUIRE_FALSE(ax.command(0, feed_move(200.0, 400.0)));
  for (int k = 0; k < 200; ++k)
    ax.step();
  CHECK(ax.set_override(0, 0.0) == Result::ok);
  for (int k = 0; k < 2000; ++k)
    ax.step();
  CHECK_FALSE(ax.in_position(0));
  CHECK(ax.setpoint(0).v == 0.0);
  const double held = ax.setpoint(0).p;
  CHECK(held < 200.0);
  ax.step();
  CHECK(ax.setpoint(0).p == held);
  CHECK(ax.set_override(0, 1.0) == Result::ok);
  run_to_position(ax);
  CHECK(ax.setpoint(0).p == 200.0);

  IndpAxes zero = one_axis();
  CHECK(zero.set_override(0, 0.0) == Result::ok);
  REQUIRE_FALSE(zero.command(0, feed_move(10.0, 100.0)));
  for (int k = 0; k < 100; ++k)
    zero.step();
  CHECK(zero.setpoint(0).p == 0.0);
  CHECK_FALSE(zero.in_position(0));
}

TEST_CASE("interrupt() stops only an INTERRUPTIBLE motion; it is done where it stops") {
  IndpAxes ax = one_axis();
  REQUIRE_FALSE(ax.command(0, feed_move(300.0, 400.0)));
  for (int k = 0; k < 300; ++k)
    ax.step();
  CHECK_FALSE(ax.interruptible(0));
  CHECK_FALSE(ax.interrupt(0));
  IndpMove m = feed_move(300.0, 400.0);
  m.interruptible = true;
  REQUIRE_FALSE(ax.command(0, m));
  CHECK(ax.interruptible(0));
  CHECK(ax.interrupt(0));
  CHECK_FALSE(ax.interrupt(0));
  run_to_position(ax);
  CHECK(ax.in_position(0));
  CHECK(ax.setpoint(0).v == 0.0);
  CHECK(ax.target(0) == ax.setpoint(0).p);
  CHECK(ax.setpoint(0).p < 300.0);
}

TEST_CASE("a move shorter than one increment does not start; the axis is owned [002 2.1]") {
  IndpAxes ax = one_axis(5.0);
  REQUIRE_FALSE(ax.command(0, feed_move(5.00001, 100.0)));
  CHECK(ax.owned(0));
  CHECK(ax.in_position(0));
  CHECK(ax.setpoint(0).p == 5.0);
  ax.release(0);
  CHECK_FALSE(ax.owned(0));
}

TEST_CASE("seeded random INDP commands and overrides keep v, a, j within the axis limits") {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> pos(-900.0, 900.0);
  std::uniform_real_distribution<double> feed(10.0, 800.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int run = 0; run < 20; ++run) {
    ncsim::planner::AxisVec p{};
    IndpAxes ax({axis_config("C"), axis_config("U")}, kT, p);
    for (int k = 0; k < 6000; ++k) {
      if (unit(rng) < 0.004) {
        const std::size_t i = unit(rng) < 0.5 ? 0 : 1;
        IndpMove m = feed_move(pos(rng), feed(rng));
        m.rapid = unit(rng) < 0.3;
        if (unit(rng) < 0.2) m.time = 0.2 + 3.0 * unit(rng);
        const auto e = ax.command(i, m);
        INFO((e ? e->message : std::string()));
        REQUIRE_FALSE(e);
      }
      if (unit(rng) < 0.002) ax.set_override(unit(rng) < 0.5 ? 0 : 1, unit(rng));
      ax.step();
      for (std::size_t i = 0; i < 2; ++i) {
        const ncsim::axes::Setpoint s = ax.setpoint(i);
        CHECK(std::abs(s.v) <= 500.0 * (1.0 + 1e-6));
        CHECK(std::abs(s.a) <= 2000.0 * (1.0 + 1e-6));
        CHECK(std::abs(s.j) <= 40000.0 * (1.0 + 1e-6));
        CHECK(s.p >= -1000.0);
        CHECK(s.p <= 1000.0);
      }
    }
  }
}

// NC6104 had no test (issue 14, the ids without a test)
TEST_CASE("NC6104: an INDP motion the PTP core cannot plan names the axis and the core's id") {
  IndpAxisConfig c = axis_config("C");
  c.feed = {0.0, 0.0, 0.0, 0.0};  // unusable dynamics: the core answers NC5001
  ncsim::planner::AxisVec p{};
  IndpAxes ax({c}, kT, p);
  const auto e = ax.command(0, feed_move(100.0, 200.0));
  REQUIRE(e);
  CHECK(e->id == "NC6104");
  CHECK(e->message.find("axis C") != std::string::npos);
  CHECK(e->message.find("NC5001") != std::string::npos);
  CHECK(ax.in_position(0));  // nothing started
}

TEST_CASE("NCSIM-AXIS-030: time-optimal INDP moves reverse without stopping; off, the manual's") {
  // The axis parameter ncsim.profile_rule (machines::Dynamics::time_optimal_profiles) selects
  // the rule INDP moves are planned with (indp_axis_config -> IndpAxisConfig::rule). A command
  // behind an axis moving at 400 mm/s: the manual stops and returns (002_* 2.3), the
  // time-optimal rule turns without a stop (A- before v = 0, A+ after it) and arrives sooner.
  // Each cycle's setpoint is the profile of its rule, planned from the moving state.
  ncsim::machines::AxisParams axis;
  axis.name = "C";
  auto& dyn = axis.dynamics;
  dyn.v_max = dyn.v_rapid = 500.0;
  dyn.acc_max = 5000.0;
  dyn.acc_feed = 2000.0;  // A+
  dyn.dec_feed = 1500.0;  // A-
  dyn.acc_rapid = 1000.0;
  dyn.ramp_acc_up = dyn.ramp_acc_down = 0.05;  // J = 2000 / 0.05 = 40000
  dyn.ramp_dec_up = dyn.ramp_dec_down = 0.0375;
  dyn.ramp_rapid = 0.05;
  int cycles[2] = {0, 0};
  for (const bool optimal : {false, true}) {
    CAPTURE(optimal);
    dyn.time_optimal_profiles = optimal;
    const IndpAxisConfig c = ncsim::channel::indp_axis_config(axis);
    REQUIRE(c.rule ==
            (optimal ? ncsim::axes::ProfileRule::time_optimal : ncsim::axes::ProfileRule::manual));
    REQUIRE(c.feed.a_max == 2000.0);
    REQUIRE(c.feed.d_max == 1500.0);
    IndpAxes ax({c}, kT, ncsim::planner::AxisVec{});
    REQUIRE_FALSE(ax.command(0, feed_move(300.0, 400.0)));
    for (int k = 0; k < 600; ++k)
      ax.step();
    const ncsim::axes::Setpoint s0 = ax.setpoint(0);
    REQUIRE(s0.v > 300.0);
    REQUIRE_FALSE(ax.command(0, feed_move(50.0, 400.0)));
    // The profile of the rule from the moving state, sampled as the INDP layer samples it.
    ncsim::axes::Dynamics d = c.feed;
    d.v_max = 400.0;
    ncsim::axes::Profile expected;
    REQUIRE(ncsim::axes::plan_position(ncsim::axes::MotionState{s0.p, s0.v, s0.a},
                                       ncsim::axes::PositionTarget{50.0, 0.0}, d, expected,
                                       c.rule) == Result::ok);
    int n = 0;
    while (!ax.in_position(0) && n < 100000) {
      ax.step();
      ++n;
      const double t = n * kT;
      if (t < expected.duration() * (1.0 - 1e-12)) {
        const ncsim::axes::Setpoint e = expected.at(t);
        REQUIRE(ax.setpoint(0).p == e.p);
        REQUIRE(ax.setpoint(0).v == e.v);
        REQUIRE(ax.setpoint(0).a == e.a);
      }
    }
    CHECK(ax.setpoint(0).p == 50.0);  // on the target bit for bit
    CHECK(ax.setpoint(0).v == 0.0);
    CHECK(n == static_cast<int>(std::ceil(expected.duration() / kT * (1.0 - 1e-12))));
    cycles[optimal ? 1 : 0] = n;
    // The manual stands still on the way (stop, then return: a phase starting at v = 0 with
    // a = 0 before the end); the time-optimal profile passes v = 0 accelerating.
    int stands = 0;
    const auto phases = expected.phases();
    for (std::size_t k = 1; k < phases.size(); ++k) {
      if (std::abs(phases[k].v) <= 1e-9 * 400.0 && std::abs(phases[k].a) <= 1e-9 * 2000.0) ++stands;
    }
    CHECK(stands == (optimal ? 0 : 1));
  }
  MESSAGE("manual ", cycles[0], " cycles, time-optimal ", cycles[1], " cycles");
  CHECK(cycles[1] < cycles[0]);
}
