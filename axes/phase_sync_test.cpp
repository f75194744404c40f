// Phase-synchronised multi-axis motion (axes/phase_sync, docs/axes-phase-sync.md): the axes
// stay on the straight line between start and end, each within its own limits, all ending
// on their targets at the limiting axis's duration; otherwise time synchronisation.

#include "axes/phase_sync.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "jerk/test_random.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;
using ncsim::axes::Result;
using ncsim::axes::SyncKind;
using ncsim::test::log_uniform;

// Largest deviation from the straight line over a grid: |(p_i - p_i0) - D_i u| with u the
// progress of the axis with the longest distance, relative to that distance (or to the
// largest position, whose rounding is the floor).
double max_line_deviation(std::span<const Profile> out, std::span<const MotionState> starts,
                          std::span<const PositionTarget> targets) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (std::abs(targets[i].p - starts[i].p) > std::abs(targets[k].p - starts[k].p)) k = i;
  const double dk = targets[k].p - starts[k].p;
  // Relative to the way, or to the positions' own resolution where they are larger.
  double scale = std::abs(dk);
  for (std::size_t i = 0; i < out.size(); ++i)
    scale = std::max({scale, std::abs(starts[i].p), std::abs(targets[i].p)});
  double worst = 0.0;
  const double t_end = out[k].duration();
  for (int g = 0; g <= 1000; ++g) {
    const double t = t_end * g / 1000.0;
    const double u = (out[k].at(t).p - starts[k].p) / dk;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const double di = targets[i].p - starts[i].p;
      const double dev = std::abs(out[i].at(t).p - starts[i].p - di * u);
      worst = std::max(worst, dev / scale);
    }
  }
  return worst;
}

void check_axis_limits(const Profile& p, const Dynamics& d) {
  for (int g = 0; g <= 1000; ++g) {
    const auto sp = p.at(p.duration() * g / 1000.0);
    REQUIRE(std::abs(sp.v) <= d.v_max * (1.0 + 1e-9));
    const double cap = sp.v * sp.a > 0.0 ? d.a_max : d.d_max;
    REQUIRE(std::abs(sp.a) <= std::max(cap, std::min(d.a_max, d.d_max)) * (1.0 + 1e-9) + 1e-9);
  }
  for (const auto& ph : p.phases())
    REQUIRE((ph.j == 0.0 || std::abs(ph.j) <= d.j_max * (1.0 + 1e-12)));
}

}  // namespace

TEST_CASE("phase-synchronised axes with equal dynamics move on the straight line") {
  // Dynamik 1.1 on X (1000 mm, 1.0 s); Y and Z shorter: every axis takes 1.0 s on the line.
  const Dynamics d{2000.0, 5000.0, 5000.0, 50000.0};
  const std::array<MotionState, 3> starts{MotionState{}, MotionState{5.0, 0.0, 0.0},
                                          MotionState{-3.0, 0.0, 0.0}};
  const std::array<PositionTarget, 3> targets{
      PositionTarget{1000.0, 0.0}, PositionTarget{-395.0, 0.0}, PositionTarget{-3.0, 0.0}};
  const std::array<Dynamics, 3> dyn{d, d, d};
  std::array<Profile, 3> out;
  SyncKind used = SyncKind::time;
  REQUIRE(ncsim::axes::plan_phase_synchronized(starts, targets, dyn, ProfileRule::manual, 0.0, out,
                                               &used) == Result::ok);
  CHECK(used == SyncKind::phase);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(out[i].duration() == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(out[i].at(out[i].duration()).p == targets[i].p);
    CHECK(out[i].phases().size() == out[0].phases().size());
    check_axis_limits(out[i], d);
  }
  // Y at 0.4 of X's distance reaches 0.4 of X's velocity: 800 mm/s, never V.
  CHECK(std::abs(out[1].at(0.5).v) == doctest::Approx(800.0).epsilon(1e-12));
  CHECK(max_line_deviation(out, starts, targets) < 1e-14);
  // TIME= longer than the motion: the common profile is stretched, the line kept.
  REQUIRE(ncsim::axes::plan_phase_synchronized(starts, targets, dyn, ProfileRule::manual, 2.5, out,
                                               &used) == Result::ok);
  CHECK(used == SyncKind::phase);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(out[i].duration() == doctest::Approx(2.5).epsilon(1e-12));
    CHECK(out[i].at(out[i].duration()).p == targets[i].p);
  }
  CHECK(max_line_deviation(out, starts, targets) < 1e-14);
}

TEST_CASE(
    "phase synchronisation falls back to time synchronisation where phases cannot be shared") {
  const std::array<Dynamics, 2> dyn{Dynamics{2000.0, 5000.0, 5000.0, 50000.0},
                                    Dynamics{300.0, 100000.0, 100000.0, 1e7}};
  std::array<Profile, 2> out;
  SyncKind used = SyncKind::phase;
  // X limited by its acceleration, Y (same distance) by its velocity: the common profile under
  // both would be slower than either axis alone.
  const std::array<MotionState, 2> rest{MotionState{}, MotionState{}};
  const std::array<PositionTarget, 2> far{PositionTarget{100.0, 0.0}, PositionTarget{100.0, 0.0}};
  REQUIRE(ncsim::axes::plan_phase_synchronized(rest, far, dyn, ProfileRule::manual, 0.0, out,
                                               &used) == Result::ok);
  const std::array<Dynamics, 1> dx{dyn[0]};
  const std::array<MotionState, 1> sx{MotionState{}};
  const std::array<PositionTarget, 1> tx{far[0]};
  const std::array<Dynamics, 1> dy{dyn[1]};
  std::array<Profile, 1> alone;
  REQUIRE(ncsim::axes::plan_phase_synchronized(sx, tx, dx, ProfileRule::manual, 0.0, alone) ==
          Result::ok);
  const double tx_alone = alone[0].duration();
  REQUIRE(ncsim::axes::plan_phase_synchronized(sx, tx, dy, ProfileRule::manual, 0.0, alone) ==
          Result::ok);
  const double ty_alone = alone[0].duration();
  CHECK(used == SyncKind::time);
  CHECK(out[0].duration() == doctest::Approx(std::max(tx_alone, ty_alone)).epsilon(1e-12));
  CHECK(out[1].duration() == doctest::Approx(out[0].duration()).epsilon(1e-12));
  // A moving start: time synchronisation.
  const std::array<MotionState, 2> moving{MotionState{0.0, 100.0, 0.0}, MotionState{}};
  REQUIRE(ncsim::axes::plan_phase_synchronized(moving, far, dyn, ProfileRule::manual, 0.0, out,
                                               &used) == Result::ok);
  CHECK(used == SyncKind::time);
  CHECK(out[0].at(out[0].duration()).p == 100.0);
  CHECK(out[1].at(out[1].duration()).p == 100.0);
  // Nothing moves: every axis rests for TIME=.
  const std::array<PositionTarget, 2> here{PositionTarget{0.0, 0.0}, PositionTarget{0.0, 0.0}};
  REQUIRE(ncsim::axes::plan_phase_synchronized(rest, here, dyn, ProfileRule::manual, 0.7, out,
                                               &used) == Result::ok);
  CHECK(used == SyncKind::phase);
  CHECK(out[0].duration() == 0.7);
  CHECK(out[1].at(0.35).p == 0.0);
  CHECK(out[1].at(0.35).v == 0.0);
  // Mismatched spans: invalid input.
  std::array<Profile, 1> one;
  CHECK(ncsim::axes::plan_phase_synchronized(rest, far, dyn, ProfileRule::manual, 0.0, one) ==
        Result::error_invalid_input);
}

TEST_CASE("random phase-synchronised motions: on the line, within each axis's limits, exact") {
  // 2..6 axes; half share one axis's dynamics scaled per axis (so the phases can be shared),
  // half draw their own; distances 1e-4..1e4 mm of either sign, some 0.
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int phase = 0;
  int time = 0;
  for (int n = 0; n < 2000; ++n) {
    const std::size_t axes = 2 + static_cast<std::size_t>(unit(rng) * 5.0);
    std::vector<MotionState> starts(axes);
    std::vector<PositionTarget> targets(axes);
    std::vector<Dynamics> dyn(axes);
    std::vector<Profile> out(axes);
    const Dynamics base{log_uniform(rng, 1.0, 1e4), log_uniform(rng, 10.0, 1e5),
                        log_uniform(rng, 10.0, 1e5), log_uniform(rng, 1e2, 1e7)};
    const bool shared = unit(rng) < 0.5;
    for (std::size_t i = 0; i < axes; ++i) {
      starts[i].p = 100.0 * (2.0 * unit(rng) - 1.0);
      const double dist =
          unit(rng) < 0.1 ? 0.0 : (unit(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 1e-4, 1e4);
      targets[i].p = starts[i].p + dist;
      const double f = shared ? 1.0 + 2.0 * unit(rng) : 1.0;  // more than the limiting axis
      dyn[i] = shared ? Dynamics{base.v_max * f, base.a_max * f, base.d_max * f, base.j_max * f}
                      : Dynamics{log_uniform(rng, 1.0, 1e4), log_uniform(rng, 10.0, 1e5),
                                 log_uniform(rng, 10.0, 1e5), log_uniform(rng, 1e2, 1e7)};
    }
    const ProfileRule rule = unit(rng) < 0.5 ? ProfileRule::manual : ProfileRule::time_optimal;
    const double min_duration = unit(rng) < 0.2 ? log_uniform(rng, 1e-3, 1e2) : 0.0;
    SyncKind used = SyncKind::time;
    REQUIRE(ncsim::axes::plan_phase_synchronized(starts, targets, dyn, rule, min_duration, out,
                                                 &used) == Result::ok);
    // The slowest axis alone.
    double t_slowest = min_duration;
    for (std::size_t i = 0; i < axes; ++i) {
      Profile alone;
      REQUIRE(ncsim::axes::plan_position(starts[i], targets[i], dyn[i], alone, rule) == Result::ok);
      t_slowest = std::max(t_slowest, alone.duration());
    }
    INFO("n=", n, " axes=", axes, " shared=", shared, " T=", out[0].duration(),
         " t_slowest=", t_slowest);
    for (std::size_t i = 0; i < axes; ++i) {
      REQUIRE(out[i].at(out[i].duration()).p == targets[i].p);
      REQUIRE(out[i].at(out[i].duration()).v == 0.0);
      check_axis_limits(out[i], dyn[i]);
    }
    if (used == SyncKind::phase) {
      ++phase;
      bool any = false;
      for (std::size_t i = 0; i < axes; ++i)
        any = any || targets[i].p != starts[i].p;
      if (!any) continue;
      for (std::size_t i = 0; i < axes; ++i) {
        REQUIRE(out[i].duration() == doctest::Approx(t_slowest).epsilon(1e-9));
      }
      REQUIRE(max_line_deviation(out, starts, targets) < 1e-12);
    } else {
      ++time;
    }
  }
  MESSAGE("phase-synchronised ", phase, ", time-synchronised ", time);
  CHECK(phase > 900);
}
