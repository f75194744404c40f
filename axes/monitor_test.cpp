#include "axes/monitor.hpp"

#include <doctest/doctest.h>

#include <optional>
#include <stdexcept>

namespace ncsim::axes {
namespace {

constexpr double kT = 0.001;  // [s]

// Only the monitor under test is on.
AxisMonitorParams quiet() {
  AxisMonitorParams params;
  params.lag.enabled = false;
  params.position_range.enabled = false;
  params.target_position.enabled = false;
  params.motion.enabled = false;
  params.exact_stop.settling_time = 0.0;
  return params;
}

// Feeds `cycles` samples; returns the 1-based cycle of the first alarm, or 0.
template <typename SampleAt>
int first_alarm_cycle(AxisMonitor& monitor, int cycles, SampleAt sample_at,
                      std::optional<AxisAlarm>* alarm_out = nullptr) {
  for (int k = 1; k <= cycles; ++k) {
    AxisSample sample = sample_at(k);
    sample.t = k * kT;
    if (auto alarm = monitor.step(sample)) {
      if (alarm_out) *alarm_out = alarm;
      return k;
    }
  }
  return 0;
}

TEST_CASE("soft limits reject targets beyond them and accept targets on them") {
  SoftLimitParams limits{true, -20.0, true, 400.0};
  CHECK_FALSE(check_soft_limits(limits, 400.0, 0, 0.0));
  CHECK_FALSE(check_soft_limits(limits, -20.0, 0, 0.0));
  const auto above = check_soft_limits(limits, 400.001, 2, 1.5);
  REQUIRE(above);
  CHECK(above->kind == AlarmKind::soft_limit_max);
  CHECK(above->id == kIdSoftLimitMax);
  CHECK(above->reaction == AlarmReaction::reject_command);
  CHECK(above->axis == 2);
  CHECK(above->limit == 400.0);
  const auto below = check_soft_limits(limits, -20.5, 0, 0.0);
  REQUIRE(below);
  CHECK(below->kind == AlarmKind::soft_limit_min);
  limits.max_enabled = false;
  CHECK_FALSE(check_soft_limits(limits, 1e9, 0, 0.0));
}

TEST_CASE("the lag alarm 0x4550 trips exactly after the filter time, not before") {
  AxisMonitorParams params = quiet();
  params.lag = LagMonitorParams{true, 1.0, 0.005};
  AxisMonitor monitor(params, kT, 1);
  std::optional<AxisAlarm> alarm;
  // Lag exactly at the limit never trips; above it from cycle 11 on.
  const int cycle = first_alarm_cycle(
      monitor, 100,
      [](int k) {
        return AxisSample{0.0, 10.0, k <= 10 ? 9.0 : 8.999, true, std::nullopt};
      },
      &alarm);
  // Exceeded in cycles 11..15 = 5 ms (not longer than 5 ms); cycle 16 makes it 6 ms.
  CHECK(cycle == 16);
  REQUIRE(alarm);
  CHECK(alarm->id == kIdPositionLag);
  CHECK(alarm->reaction == AlarmReaction::shutdown);
  CHECK(alarm->axis == 1);
  CHECK(alarm->t == doctest::Approx(0.016));
  CHECK(alarm->value == doctest::Approx(1.001));
  CHECK(monitor.status().error);
}

TEST_CASE("without filter time the lag alarm trips in the first cycle above the limit") {
  AxisMonitorParams params = quiet();
  params.lag = LagMonitorParams{true, 1.0, 0.0};
  AxisMonitor monitor(params, kT, 0);
  const int cycle = first_alarm_cycle(monitor, 50, [](int k) {
    return AxisSample{0.0, 0.0, k < 7 ? -1.0 : -1.0001, true, std::nullopt};
  });
  CHECK(cycle == 7);
}

TEST_CASE("a lag excursion shorter than the filter time does not trip") {
  AxisMonitorParams params = quiet();
  params.lag = LagMonitorParams{true, 1.0, 0.003};
  AxisMonitor monitor(params, kT, 0);
  // Above for 3 cycles, back for one, above for 3 again: never longer than 3 ms.
  const int cycle = first_alarm_cycle(monitor, 40, [](int k) {
    const bool above = (k % 4) != 0;
    return AxisSample{0.0, 0.0, above ? 2.0 : 0.0, true, std::nullopt};
  });
  CHECK(cycle == 0);
}

TEST_CASE("after an alarm the monitor stays silent until reset") {
  AxisMonitorParams params = quiet();
  params.lag = LagMonitorParams{true, 1.0, 0.0};
  AxisMonitor monitor(params, kT, 0);
  CHECK(monitor.step(AxisSample{0.001, 0.0, 5.0, true, std::nullopt}));
  CHECK_FALSE(monitor.step(AxisSample{0.002, 0.0, 5.0, true, std::nullopt}));
  monitor.reset();
  CHECK_FALSE(monitor.status().error);
  CHECK(monitor.step(AxisSample{0.003, 0.0, 5.0, true, std::nullopt}));
}

TEST_CASE("In Position Area is set inside the position range window") {
  AxisMonitorParams params = quiet();
  params.position_range = PositionRangeParams{true, 0.5};
  AxisMonitor monitor(params, kT, 0);
  monitor.step(AxisSample{0.0, 99.0, 99.4, true, 100.0});
  CHECK_FALSE(monitor.status().in_position_area);
  monitor.step(AxisSample{0.001, 99.8, 99.5, true, 100.0});
  CHECK(monitor.status().in_position_area);
  monitor.step(AxisSample{0.002, 100.0, 100.5, false, 100.0});
  CHECK(monitor.status().in_position_area);
  monitor.step(AxisSample{0.003, 100.0, 100.5001, false, 100.0});
  CHECK_FALSE(monitor.status().in_position_area);
}

TEST_CASE("In Target Position needs the window for the whole monitoring time") {
  AxisMonitorParams params = quiet();
  params.target_position.enabled = true;
  params.target_position.window = 0.1;
  params.target_position.time = 0.004;
  AxisMonitor monitor(params, kT, 0);
  // Set position reaches 50 at cycle 1; actual enters the window at cycle 3, leaves it at 5,
  // re-enters at 6.
  const double actual[] = {0, 49.5, 49.8, 49.95, 49.97, 49.8, 49.92, 49.95, 49.99, 50.0, 50.0};
  bool flags[11] = {};
  for (int k = 1; k <= 10; ++k) {
    monitor.step(AxisSample{k * kT, 50.0, actual[k], false, 50.0});
    flags[k] = monitor.status().in_target_position;
  }
  // In the window at cycles 3, 4, then 6, 7, 8, 9 (4 cycles = 4 ms at cycle 9).
  for (int k = 1; k <= 8; ++k)
    CHECK_FALSE(flags[k]);
  CHECK(flags[9]);
  CHECK(flags[10]);
}

TEST_CASE("the In-Target alarm 0x435C trips exactly after the timeout") {
  AxisMonitorParams params = quiet();
  params.target_position.enabled = true;
  params.target_position.window = 0.1;
  params.target_position.in_target_alarm = true;
  params.target_position.in_target_timeout = 0.010;
  AxisMonitor monitor(params, kT, 3);
  std::optional<AxisAlarm> alarm;
  // Set position moves until cycle 5, is at the target from cycle 6 on; actual stays outside.
  const int cycle = first_alarm_cycle(
      monitor, 100,
      [](int k) {
        return AxisSample{0.0, k < 6 ? 10.0 * k : 50.0, 49.5, k < 6, 50.0};
      },
      &alarm);
  // Cycle 6 is time 0 of the timeout; cycle 16 is 10 ms (not exceeded), cycle 17 is 11 ms.
  CHECK(cycle == 17);
  REQUIRE(alarm);
  CHECK(alarm->id == kIdInTargetTimeout);
  CHECK(alarm->limit == 0.010);
}

TEST_CASE("reaching the target window in time suppresses the In-Target alarm") {
  AxisMonitorParams params = quiet();
  params.target_position.enabled = true;
  params.target_position.window = 0.1;
  params.target_position.in_target_alarm = true;
  params.target_position.in_target_timeout = 0.010;
  AxisMonitor monitor(params, kT, 0);
  // In the window exactly at the last permitted cycle (16), then outside again.
  const int cycle = first_alarm_cycle(monitor, 100, [](int k) {
    return AxisSample{0.0, 50.0, k == 16 ? 49.95 : 49.5, k < 6, 50.0};
  });
  CHECK(cycle == 0);
}

TEST_CASE("motion monitoring 0x435D trips when the axis does not move for longer than the time") {
  AxisMonitorParams params = quiet();
  params.motion = MotionMonitorParams{true, 0.01, 0.005};
  AxisMonitor monitor(params, kT, 0);
  std::optional<AxisAlarm> alarm;
  // Moves 0.02 mm per cycle up to cycle 10, then blocks (creeps 0.005 mm per cycle).
  const int cycle = first_alarm_cycle(
      monitor, 100,
      [](int k) {
        const double p = k <= 10 ? 0.02 * k : 0.2 + 0.005 * (k - 10);
        return AxisSample{0.0, 0.05 * k, p, true, std::nullopt};
      },
      &alarm);
  // Still in cycles 11..15 (5 ms), the 6th still cycle (16) is longer than 5 ms.
  CHECK(cycle == 16);
  REQUIRE(alarm);
  CHECK(alarm->id == kIdMotionNotDetected);
}

TEST_CASE("motion monitoring is off at logical standstill") {
  AxisMonitorParams params = quiet();
  params.motion = MotionMonitorParams{true, 0.01, 0.002};
  AxisMonitor monitor(params, kT, 0);
  const int cycle = first_alarm_cycle(monitor, 50, [](int) {
    return AxisSample{0.0, 1.0, 1.0, false, 1.0};
  });
  CHECK(cycle == 0);
}

TEST_CASE("the exact stop alarm P-ERR-70082 trips exactly after P-AXIS-00532") {
  AxisMonitorParams params = quiet();
  params.exact_stop = ExactStopParams{0.05, 0.020, 0.0};
  AxisMonitor monitor(params, kT, 0);
  std::optional<AxisAlarm> alarm;
  const int cycle = first_alarm_cycle(
      monitor, 100,
      [](int k) {
        return AxisSample{0.0, 10.0, 9.9, k < 3, 10.0};
      },
      &alarm);
  // t_1 at cycle 3; 20 ms later (cycle 23) not yet; cycle 24 is 21 ms.
  CHECK(cycle == 24);
  REQUIRE(alarm);
  CHECK(alarm->id == kIdExactStopTimeout);
  CHECK(alarm->reaction == AlarmReaction::stop);
  CHECK_FALSE(to_diagnostic(*alarm).message.empty());
  CHECK(to_diagnostic(*alarm).id == "P-ERR-70082");
}

TEST_CASE("the exact stop window is reached and ends the settling timeout") {
  AxisMonitorParams params = quiet();
  params.exact_stop = ExactStopParams{0.05, 0.020, 0.0};
  AxisMonitor monitor(params, kT, 0);
  bool reached_at_23 = false;
  const int cycle = first_alarm_cycle(monitor, 100, [&](int k) {
    return AxisSample{0.0, 10.0, k >= 23 ? 9.96 : 9.9, k < 3, 10.0};
  });
  reached_at_23 = monitor.status().in_exact_stop_window;
  CHECK(cycle == 0);
  CHECK(reached_at_23);
}

TEST_CASE("P-AXIS-00532 = 0 disables the time monitoring, negative falls back to P-AXIS-00151") {
  CHECK(effective_settling_time(ExactStopParams{0.05, 0.0, 0.3}) == 0.0);
  CHECK(effective_settling_time(ExactStopParams{0.05, -1e-6, 0.3}) == 0.3);
  CHECK(effective_settling_time(ExactStopParams{0.05, 0.1, 0.3}) == 0.1);

  AxisMonitorParams params = quiet();
  params.exact_stop = ExactStopParams{0.05, 0.0, 0.001};
  AxisMonitor disabled(params, kT, 0);
  CHECK(first_alarm_cycle(disabled, 500, [](int) {
          return AxisSample{0.0, 10.0, 9.0, false, 10.0};
        }) == 0);

  params.exact_stop = ExactStopParams{0.05, -1e-6, 0.004};
  AxisMonitor legacy(params, kT, 0);
  CHECK(first_alarm_cycle(legacy, 500, [](int) {
          return AxisSample{0.0, 10.0, 9.0, false, 10.0};
        }) == 6);
}

TEST_CASE("a new target restarts the target monitors") {
  AxisMonitorParams params = quiet();
  params.exact_stop = ExactStopParams{0.05, 0.005, 0.0};
  AxisMonitor monitor(params, kT, 0);
  // First positioning: at target from cycle 1, in the window at cycle 3.
  for (int k = 1; k <= 3; ++k) {
    CHECK_FALSE(monitor.step(AxisSample{k * kT, 10.0, k == 3 ? 10.0 : 9.0, false, 10.0}));
  }
  CHECK(monitor.status().in_exact_stop_window);
  // New motion to 20: the window status is gone while moving.
  CHECK_FALSE(monitor.step(AxisSample{4 * kT, 12.0, 11.0, true, 20.0}));
  CHECK_FALSE(monitor.status().in_exact_stop_window);
  // At 20 from cycle 5, never in the window: cycle 11 is 6 ms > 5 ms.
  std::optional<AxisAlarm> alarm;
  int cycle = 0;
  for (int k = 5; k <= 20 && !alarm; ++k) {
    alarm = monitor.step(AxisSample{k * kT, 20.0, 19.0, false, 20.0});
    cycle = k;
  }
  CHECK(cycle == 11);
}

TEST_CASE("invalid monitoring parameters throw naming the parameter") {
  AxisMonitorParams params;
  params.lag.max_lag = -1.0;
  CHECK_THROWS_WITH_AS(AxisMonitor(params, kT, 0), doctest::Contains("Maximum Position Lag Value"),
                       std::invalid_argument);
  params = AxisMonitorParams{};
  params.soft_limits = SoftLimitParams{true, 10.0, true, 5.0};
  CHECK_THROWS_WITH_AS(AxisMonitor(params, kT, 0), doctest::Contains("P-AXIS-00177"),
                       std::invalid_argument);
  params = AxisMonitorParams{};
  params.exact_stop.settling_time = -1.0;
  params.exact_stop.legacy_settling_time = -2.0;
  CHECK_THROWS_WITH_AS(AxisMonitor(params, kT, 0), doctest::Contains("P-AXIS-00151"),
                       std::invalid_argument);
  CHECK_THROWS_AS(AxisMonitor(AxisMonitorParams{}, 0.0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace ncsim::axes
