#include "conveyor/world.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "conveyor/test_world.hpp"

namespace ncsim::conveyor {
namespace {

constexpr double kT = 0.001;
using scenario::ConveyorMode;

void run(Port& w, int& k, double until) {
  while (k * kT < until - 1e-12)
    w.step(++k * kT);
}

machines::ProbeArm arm(int channel = 1, std::optional<machines::ProbeEdge> edge = std::nullopt) {
  machines::ProbeArm a;
  a.axis = 1;
  a.channel = channel;
  a.edge = edge;
  return a;
}

scenario::Workpiece at_travel(double travel, double length = 100.0) {
  scenario::Workpiece w;
  w.travel = travel;
  w.length = length;
  return w;
}

}  // namespace

TEST_CASE("dead time shifts the measured value by exactly the dead time") {
  const auto m = test::machine(true);
  for (const double dead : {0.017, 0.017455}) {
    CAPTURE(dead);
    auto s = test::belt(ConveyorMode::encoder, 100.0);
    s.conveyor->profile = {{0.05, 400.0, 0.1}};  // constant acceleration 3000 mm/s^2
    s.conveyor->dead_time = dead;
    World w(m, &s, kT);
    Belt truth = Belt::encoder(100.0, s.conveyor->profile, std::nullopt);
    for (int k = 1; k <= 300; ++k) {
      const double t = k * kT;
      w.step(t);
      const BeltState expected = truth.base(t - dead);
      CAPTURE(t);
      CHECK(w.measured().p == doctest::Approx(expected.p).epsilon(1e-12));
    }
  }
}

TEST_CASE("encoder noise is seeded: the same seed repeats, another differs, sigma holds") {
  const auto m = test::machine(true);
  auto trace = [&](std::uint64_t seed) {
    auto s = test::belt(ConveyorMode::encoder, 300.0);
    s.conveyor->noise = scenario::BeltNoise{0.01, seed};
    World w(m, &s, kT);
    std::vector<double> e;
    for (int k = 1; k <= 20000; ++k) {
      w.step(k * kT);
      e.push_back(w.measured().p - w.actual().p);
    }
    return e;
  };
  const auto a = trace(7), b = trace(7), c = trace(8);
  CHECK(a == b);
  CHECK(a != c);
  double sum = 0.0, sq = 0.0;
  for (const double x : a) {
    sum += x;
    sq += x * x;
  }
  const double mean = sum / static_cast<double>(a.size());
  const double sd = std::sqrt(sq / static_cast<double>(a.size()) - mean * mean);
  CHECK(std::abs(mean) < 0.0005);  // 5 standard errors of 10 um / sqrt(20000)
  CHECK(sd == doctest::Approx(0.01).epsilon(0.03));
}

TEST_CASE(
    "10 um encoder noise: the raw velocity passes 50653's 1.1 x CONV_VEL, the filtered master "
    "velocity (P-AXIS-00620 on, FIR 20) does not") {
  auto m = test::machine(true);
  m.axes[1].conveyor->enable_filter = true;  // P-AXIS-00623 at its default 20
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->noise = scenario::BeltNoise{0.01, 7};
  World w(m, &s, kT);
  // CONV_VEL 290 mm/s: 50653's limit 1.1 x 290 = 319 mm/s lies 19 mm/s above the belt, 1.34
  // standard deviations of the raw quotient (sqrt(2) x 10 um / 1 ms = 14.1 mm/s; about 9 % of
  // the cycles above it) and 47 of the filtered velocity's 0.40 mm/s (filter_test).
  const double limit = 1.1 * 290.0;
  int k = 0;
  run(w, k, 0.1);  // the filters' histories filled
  constexpr int kCycles = 20000;
  int raw_over = 0, master_over = 0;
  for (int i = 0; i < kCycles; ++i) {
    w.step(++k * kT);
    if (std::fabs(w.measured().v) > limit) ++raw_over;
    if (std::fabs(w.master().v) > limit) ++master_over;
  }
  CAPTURE(raw_over);
  CHECK(raw_over > kCycles / 20);
  CHECK(master_over == 0);
}

TEST_CASE(
    "delay-time compensation P-AXIS-00626 cancels a dead time at constant velocity "
    "(the static synchro_lag goes to 0)") {
  auto m = test::machine(true);
  machines::ConveyorAxisParams& c = *m.axes[1].conveyor;
  c.enable_filter = true;  // the laser listing's filters: position average 4, FIR 10
  c.type_pos_filter = 1;
  c.order_pos_filter = 4;
  c.order_v_filter = 10;
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->dead_time = 0.017455;
  const double filter_delay = 1.5 * kT;  // (4 - 1) T / 2
  for (const double delay : {0.0, 0.017455, 0.017455 + filter_delay}) {
    c.delay_time = delay;
    World w(m, &s, kT);
    int k = 0;
    run(w, k, 0.5);
    const double lag = w.master().p - w.actual().p;
    CAPTURE(delay);
    if (delay < 0.0175) {  // too short by the position filter's delay (and the dead time)
      CHECK(lag == doctest::Approx(-300.0 * (0.017455 + filter_delay - delay)).epsilon(1e-9));
    } else {
      CHECK(std::abs(lag) < 1e-9);
    }
    CHECK(w.master().v == doctest::Approx(300.0).epsilon(1e-12));
  }
}

TEST_CASE(
    "method 1 (DRIVE_TYPE_DEFAULT): MC_TouchProbe latches the real front edge; "
    "the workpiece's V.E. values come with it") {
  const auto m = test::machine(false);
  auto s = test::belt(ConveyorMode::spindle);
  scenario::Workpiece wp = at_travel(150.0);
  wp.ve = {{"PART", 2.0}};
  s.conveyor->workpieces = {wp};
  s.conveyor->dead_time = 0.01;
  World w(m, &s, kT);
  CHECK(w.method() == MeasuringMethod::drive);
  machines::MoveVelocity mv;
  mv.axis = 1;
  mv.velocity = 300.0;
  REQUIRE(w.command_velocity(mv));
  w.arm_probe(arm());
  int k = 0;
  run(w, k, 0.3);
  CHECK_FALSE(w.take_latch());
  run(w, k, 1.0);
  const auto latch = w.take_latch();
  REQUIRE(latch);
  CHECK(*latch == doctest::Approx(150.0).epsilon(1e-12));  // the drive: no bus delay
  CHECK(w.last_latch().workpiece == 1);
  REQUIRE(w.last_latch().ve.size() == 1);
  CHECK(w.last_latch().ve[0].first == "PART");
  CHECK_FALSE(w.take_latch());
  CHECK_FALSE(w.error());
}

TEST_CASE("method 2 (PLC_FIRST_EVENT): the PLC trigger takes the measured value of its cycle") {
  const auto m = test::machine(true, "PLC_FIRST_EVENT");
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->workpieces = {at_travel(150.1)};
  s.conveyor->dead_time = 0.002;
  World w(m, &s, kT);
  CHECK(w.method() == MeasuringMethod::plc_trigger);
  w.arm_probe(arm());
  int k = 0;
  run(w, k, 1.0);
  const auto latch = w.take_latch();
  REQUIRE(latch);
  // Edge at 0.5003 s; the cycle ends at 0.501 s; the measured value lags 2 ms: 149.7 mm.
  CHECK(*latch == doctest::Approx(300.0 * (0.501 - 0.002)).epsilon(1e-12));
  CHECK(w.last_latch().true_position == doctest::Approx(150.1));
}

TEST_CASE(
    "method 3 (PLC_EXT_LATCH_CONTROL): the PLC queues every workpiece and hands the "
    "oldest out at each MC_TouchProbe; a full queue is NC9001") {
  const auto m = test::machine(true, "PLC_EXT_LATCH_CONTROL");
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->series = scenario::WorkpieceSeries{at_travel(30.0, 20.0), 60.0, 5};
  s.conveyor->sensor.queue = 3;
  World w(m, &s, kT);
  int k = 0;
  run(w, k, 0.55);  // workpieces at 30, 90, 150 mm passed (0.1, 0.3, 0.5 s)
  CHECK(w.queued() == 3);
  w.arm_probe(arm());
  auto latch = w.take_latch();
  REQUIRE(latch);
  CHECK(*latch == doctest::Approx(30.0).epsilon(1e-3));
  CHECK(w.last_latch().workpiece == 1);
  CHECK(w.queued() == 2);
  run(w, k, 0.75);  // the 4th at 210 mm: 3 queued
  CHECK(w.queued() == 3);
  CHECK_FALSE(w.error());
  run(w, k, 0.95);  // the 5th: overflow
  REQUIRE(w.error());
  CHECK(w.error()->id == "NC9001");
}

TEST_CASE("methods 1 and 2 do not keep workpieces that pass while the probe is not armed") {
  const auto m = test::machine(true, "PLC");
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->series = scenario::WorkpieceSeries{at_travel(30.0, 20.0), 60.0, 3};
  World w(m, &s, kT);
  int k = 0;
  run(w, k, 0.2);  // the first passed unarmed
  CHECK(w.missed() == 1);
  w.arm_probe(arm());
  run(w, k, 0.4);
  const auto latch = w.take_latch();
  REQUIRE(latch);
  CHECK(w.last_latch().workpiece == 2);
}

TEST_CASE(
    "a light barrier's other edge is the rear edge: Mode=1 (falling) latches the front "
    "edge plus the length (P-AXIS-00518 / MC_TouchProbe Mode)") {
  const auto m = test::machine(true);
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->workpieces = {at_travel(30.0, 45.0)};
  World w(m, &s, kT);
  w.arm_probe(arm(1, machines::ProbeEdge::falling));
  int k = 0;
  run(w, k, 0.5);
  const auto latch = w.take_latch();
  REQUIRE(latch);
  CHECK(*latch == doctest::Approx(75.0).epsilon(1e-12));
}

TEST_CASE(
    "MC_TouchProbe without Mode takes the edge of P-AXIS-00518 kenngr.measure.edge: NEG "
    "latches the rear edge, POS the front edge") {
  auto m = test::machine(true);
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->workpieces = {at_travel(30.0, 45.0)};  // front edge at 30 mm, rear edge at 75 mm
  for (const char* edge : {"NEG", "POS"}) {
    CAPTURE(edge);
    m.axes[1].measure_edge = edge;
    World w(m, &s, kT);
    w.arm_probe(arm(1));  // no Mode
    int k = 0;
    run(w, k, 0.5);
    const auto latch = w.take_latch();
    REQUIRE(latch);
    CHECK(*latch == doctest::Approx(std::string(edge) == "NEG" ? 75.0 : 30.0).epsilon(1e-12));
  }
}

TEST_CASE("a camera gives both edges at the front edge") {
  const auto m = test::machine(true);
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->sensor.kind = scenario::SensorKind::camera;
  s.conveyor->workpieces = {at_travel(30.0, 45.0)};
  World w(m, &s, kT);
  w.arm_probe(arm(1, machines::ProbeEdge::falling));
  int k = 0;
  run(w, k, 0.5);
  const auto latch = w.take_latch();
  REQUIRE(latch);
  CHECK(*latch == doctest::Approx(30.0).epsilon(1e-12));
}

TEST_CASE("workpieces arriving at a time latch the belt position then") {
  const auto m = test::machine(true);
  auto s = test::belt(ConveyorMode::encoder, 200.0);
  scenario::Workpiece wp;
  wp.t = 0.2505;
  s.conveyor->workpieces = {wp};
  World w(m, &s, kT);
  w.arm_probe(arm());
  int k = 0;
  run(w, k, 0.5);
  const auto latch = w.take_latch();
  REQUIRE(latch);
  CHECK(*latch == doctest::Approx(50.1).epsilon(1e-12));
}

TEST_CASE("MC_TouchProbe while a measurement is active: P-ERR-44009, 44011, 44012, 44001") {
  const auto m = test::machine(true);
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->workpieces = {at_travel(300.0)};
  struct Case {
    machines::ProbeArm second;
    const char* id;
  };
  machines::ProbeArm other_axis = arm();
  other_axis.axis = 0;
  for (const Case& c : {Case{arm(), "P-ERR-44009"}, Case{arm(2), "P-ERR-44011"},
                        Case{arm(1, machines::ProbeEdge::falling), "P-ERR-44012"},
                        Case{other_axis, "P-ERR-44001"}}) {
    World w(m, &s, kT);
    w.arm_probe(arm());
    w.arm_probe(c.second);
    REQUIRE(w.error());
    CHECK(w.error()->id == c.id);
    CHECK(w.armed());  // the active command stays
  }
}

TEST_CASE(
    "MC_TouchProbe errors of the world: NC9002 wrong input, NC9003 no workpiece left, "
    "NC9004 not the conveyor axis") {
  const auto m = test::machine(true);
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->workpieces = {at_travel(30.0)};
  {
    World w(m, &s, kT);
    w.arm_probe(arm(2));
    REQUIRE(w.error());
    CHECK(w.error()->id == "NC9002");
  }
  {
    World w(m, &s, kT);
    int k = 0;
    run(w, k, 0.5);
    w.arm_probe(arm());
    REQUIRE(w.error());
    CHECK(w.error()->id == "NC9003");
  }
  {
    World w(m, &s, kT);
    machines::ProbeArm a = arm();
    a.axis = 0;
    w.arm_probe(a);
    REQUIRE(w.error());
    CHECK(w.error()->id == "NC9004");
  }
}

TEST_CASE("MC_MoveVelocity: NC9006 on an encoder belt, NC9005 above P-AXIS-00212") {
  machines::MoveVelocity mv;
  mv.axis = 1;
  mv.velocity = 300.0;
  {
    const auto m = test::machine(true);
    auto s = test::belt(ConveyorMode::encoder, 300.0);
    World w(m, &s, kT);
    CHECK_FALSE(w.command_velocity(mv));
    REQUIRE(w.error());
    CHECK(w.error()->id == "NC9006");
  }
  {
    const auto m = test::machine(false);
    World w(m, nullptr, kT);
    mv.velocity = 1000.5;
    CHECK_FALSE(w.command_velocity(mv));
    REQUIRE(w.error());
    CHECK(w.error()->id == "NC9005");
  }
}

TEST_CASE("make_port refuses settings it cannot run, naming the parameter") {
  auto encoder = test::belt(ConveyorMode::encoder, 300.0);
  auto spindle = test::belt(ConveyorMode::spindle);
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  CHECK(message([&] { make_port(test::machine(false), &encoder, kT); }).rfind("P-AXIS-00015", 0) ==
        0);
  CHECK(message([&] { make_port(test::machine(true), &spindle, kT); }).rfind("P-AXIS-00015", 0) ==
        0);
  CHECK(message([&] {
          make_port(test::machine(false, "FIXED_STOP"), nullptr, kT);
        }).rfind("P-AXIS-00516", 0) == 0);
  auto bad_edge = test::machine(false);
  bad_edge.axes[1].measure_edge = "UP";
  CHECK(message([&] { make_port(bad_edge, nullptr, kT); }).rfind("P-AXIS-00518", 0) == 0);
  auto none = test::machine(false);
  none.axes[1].conveyor.reset();
  CHECK(message([&] { make_port(none, nullptr, kT); }).rfind("P-AXIS-00708", 0) == 0);
  CHECK(make_port(test::machine(false), nullptr, kT) != nullptr);
}

TEST_CASE("#MACHINE DATA on conv_sync: new filter orders and delay time take effect at once") {
  auto m = test::machine(true);
  auto s = test::belt(ConveyorMode::encoder, 300.0);
  s.conveyor->dead_time = 0.01;
  World w(m, &s, kT);
  int k = 0;
  run(w, k, 0.2);
  CHECK(w.master().p - w.actual().p == doctest::Approx(-3.0).epsilon(1e-9));
  machines::ConveyorAxisParams p = *m.axes[1].conveyor;
  p.enable_filter = true;
  p.order_v_filter = 10;
  p.delay_time = 0.01;
  REQUIRE(w.set_axis_params(p));
  run(w, k, 0.3);
  CHECK(std::abs(w.master().p - w.actual().p) < 1e-9);
}

}  // namespace ncsim::conveyor

namespace ncsim::conveyor {
namespace {

// The front edges' travels of a series over a belt moving 1 mm per cycle to `until` mm.
std::vector<double> fronts(const scenario::Conveyor& c, double until) {
  Sensor sensor(&c, 1.0);
  std::vector<double> out;
  BeltState s0;
  for (int k = 1; k <= static_cast<int>(until); ++k) {
    BeltState s1{static_cast<double>(k), 1000.0, 0.0};
    for (const Edge& e : sensor.cycle((k - 1) * kT, s0, k * kT, s1))
      if (e.front && e.rising) out.push_back(e.position);
    s0 = s1;
  }
  return out;
}

}  // namespace

TEST_CASE("a seeded random stream: gaps of pitch + scatter x u, the same for the same seed") {
  scenario::Conveyor c = *test::belt(ConveyorMode::encoder, 300.0).conveyor;
  c.series = scenario::WorkpieceSeries{at_travel(100.0, 50.0), 60.0, 50};
  c.series->scatter = 40.0;
  c.series->seed = 37;
  const std::vector<double> a = fronts(c, 6000.0);
  REQUIRE(a.size() == 50);
  CHECK(a[0] == doctest::Approx(100.0).epsilon(1e-12));
  double lo = 1e9;
  double hi = 0.0;
  for (std::size_t i = 1; i < a.size(); ++i) {
    lo = std::min(lo, a[i] - a[i - 1]);
    hi = std::max(hi, a[i] - a[i - 1]);
  }
  CHECK(lo >= 60.0);
  CHECK(hi <= 100.0 + 1e-9);
  CHECK(hi - lo > 20.0);  // they do scatter
  CHECK(fronts(c, 6000.0) == a);
  c.series->seed = 38;
  CHECK(fronts(c, 6000.0) != a);
  c.series->scatter = 0.0;  // none: every gap is the pitch, as before
  const std::vector<double> even = fronts(c, 6000.0);
  REQUIRE(even.size() == 50);
  CHECK(even[49] == doctest::Approx(100.0 + 49 * 60.0).epsilon(1e-12));
}

}  // namespace ncsim::conveyor
