// The bundled machines' axes map onto the axis core's configurations with the numbers their
// ISG lists give (docs/machines.md "From a machine to its axes").
#include "axes/axis_config.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "axes/control.hpp"
#include "axes/monitor.hpp"
#include "axes/profile_generator.hpp"
#include "machines/loader.hpp"

namespace ncsim::axes {
namespace {

machines::Machine load(const std::string& name) {
  const char* root = std::getenv("NCSIM_SOURCE_DIR");
  REQUIRE_MESSAGE(root != nullptr, "NCSIM_SOURCE_DIR must point to the repository");
  const machines::LoadResult r = machines::load_machine(machines::bundled_machine_dir(root, name));
  REQUIRE(r.machine.has_value());
  return *r.machine;
}

const machines::AxisParams& axis(const machines::Machine& m, std::string_view name) {
  const machines::AxisParams* a = m.find_axis(name);
  REQUIRE(a != nullptr);
  return *a;
}

TEST_CASE("laser_portal X: vb_eilgang, a_beschl/a_brems and the ramp jerk reach the generator") {
  const machines::Machine m = load("laser_portal");
  const AxisConfig c = make_axis_config(axis(m, "X"));
  CHECK(c.generator.dynamics.v_max == doctest::Approx(1000.0));    // 1000000 um/s P-AXIS-00209
  CHECK(c.generator.dynamics.a_max == doctest::Approx(10000.0));   // P-AXIS-00001
  CHECK(c.generator.dynamics.d_max == doctest::Approx(10000.0));   // P-AXIS-00002
  CHECK(c.generator.dynamics.j_max == doctest::Approx(200000.0));  // 10000 / 0.05 s
  CHECK(c.generator.v_axis_max == doctest::Approx(1000.0));        // P-AXIS-00212
  CHECK(c.generator.increment == doctest::Approx(1e-4));
  CHECK(c.control.kv == doctest::Approx(20.0));  // 2000 x 0.01/s P-AXIS-00099
  CHECK(c.control.drive_pt1_time == doctest::Approx(0.002));
  CHECK(c.control.noise_seed == 1U);
  CHECK(c.monitor.soft_limits.min_enabled);
  CHECK(c.monitor.soft_limits.max_enabled);
  CHECK(c.monitor.soft_limits.min_position == doctest::Approx(-200.0));
  CHECK(c.monitor.soft_limits.max_position == doctest::Approx(4000.0));
  CHECK(c.monitor.lag.enabled);
  CHECK(c.monitor.lag.max_lag == doctest::Approx(2.0));
  CHECK(c.monitor.exact_stop.window == doctest::Approx(0.05));        // 500 x 0.1 um
  CHECK(c.monitor.exact_stop.settling_time == doctest::Approx(0.1));  // 100000 us
  CHECK(effective_settling_time(c.monitor.exact_stop) == doctest::Approx(0.1));
  // The configs are usable as they are: the constructors accept them.
  CHECK_NOTHROW(SetpointGenerator(c.generator));
  CHECK_NOTHROW(PositionControlModel(c.control, 0.002, 0.0));
  CHECK_NOTHROW(AxisMonitor(c.monitor, 0.002, 0));
}

TEST_CASE("laser_portal S: the conveyor spindle has no soft limits and its jerk from 2667 us") {
  const machines::Machine m = load("laser_portal");
  const AxisConfig c = make_axis_config(axis(m, "S"));
  CHECK(c.generator.dynamics.v_max == doctest::Approx(1000.0));
  CHECK(c.generator.dynamics.a_max == doctest::Approx(2000.0));
  CHECK(c.generator.dynamics.j_max == doctest::Approx(2000.0 / 2667e-6));  // 749906 mm/s^3
  CHECK_FALSE(c.monitor.soft_limits.min_enabled);
  CHECK_FALSE(c.monitor.soft_limits.max_enabled);
  CHECK(c.control.drive_pt1_time == 0.0);
  CHECK(c.control.noise_seed == 4U);
}

TEST_CASE("delta_picker and static_saw: rotary axes map in deg, deg/s, deg/s^2, deg/s^3") {
  const machines::Machine delta = load("delta_picker");
  const AxisConfig x = make_axis_config(axis(delta, "X"));
  CHECK(x.generator.dynamics.v_max == doctest::Approx(720.0));  // 720000 x 0.001 deg/s
  CHECK(x.generator.dynamics.a_max == doctest::Approx(20000.0));
  CHECK(x.generator.dynamics.j_max == doctest::Approx(500000.0));  // 20000 / 0.04 s
  CHECK(x.monitor.soft_limits.min_position == doctest::Approx(-180.0));
  CHECK(x.monitor.soft_limits.max_position == doctest::Approx(180.0));
  CHECK(x.monitor.soft_limits.max_enabled);

  const machines::Machine saw = load("static_saw");
  const AxisConfig c = make_axis_config(axis(saw, "C"));
  CHECK(c.generator.dynamics.v_max == doctest::Approx(1080.0));
  CHECK(c.generator.dynamics.j_max == doctest::Approx(500000.0));
  CHECK(c.monitor.soft_limits.max_position == doctest::Approx(3600.0));
}

TEST_CASE("portal_3x: one config per axis, in machine order") {
  const machines::Machine m = load("portal_3x");
  const std::vector<AxisConfig> configs = make_axis_configs(m);
  REQUIRE(configs.size() == 3);
  CHECK(configs[0].generator.dynamics.v_max == doctest::Approx(500.0));
  CHECK(configs[0].generator.dynamics.j_max == doctest::Approx(50000.0));  // 3000 / 0.06 s
  CHECK(configs[2].generator.dynamics.v_max == doctest::Approx(250.0));
  CHECK(configs[2].generator.dynamics.a_max == doctest::Approx(2000.0));
  CHECK(configs[2].generator.dynamics.j_max == doctest::Approx(40000.0));  // 2000 / 0.05 s
  CHECK(configs[2].monitor.soft_limits.min_position == doctest::Approx(-300.0));
  CHECK(configs[2].monitor.soft_limits.max_position == doctest::Approx(200.0));
}

TEST_CASE("only ACHSMODE_MODULO axes get a modulo range, P-AXIS-00126 - P-AXIS-00127") {
  const machines::Machine m = load("laser_portal");
  CHECK_FALSE(make_axis_config(axis(m, "X")).modulo.has_value());
  CHECK_FALSE(make_axis_config(axis(m, "S")).modulo.has_value());  // belt positions in mm
  machines::AxisParams table = axis(m, "X");
  table.kind = machines::AxisKind::rotary;
  table.modulo = true;
  table.modulo_upper = 360.0;
  const std::optional<ModuloParams> p = make_modulo_params(table);
  REQUIRE(p.has_value());
  CHECK(p->factor == doctest::Approx(360.0));
  CHECK_FALSE(make_monitor_params(table).soft_limits.max_enabled);
  table.modulo_lower = -180.0;
  table.modulo_upper = 180.0;
  CHECK_THROWS_WITH_AS(make_modulo_params(table), doctest::Contains("P-AXIS-00127"),
                       std::invalid_argument);
}

TEST_CASE("an axis without dynamics in its list gets the TF5200 defaults") {
  machines::AxisParams a;        // values as the loader fills them from the table defaults
  a.dynamics.v_max = 200.0;      // P-AXIS-00212 default 200000 um/s
  a.dynamics.v_rapid = 166.666;  // P-AXIS-00209 default 166666 um/s
  a.dynamics.acc_feed = 1000.0;  // P-AXIS-00001 default
  a.dynamics.dec_feed = 1000.0;  // P-AXIS-00002 default
  a.dynamics.ramp_acc_up = a.dynamics.ramp_acc_down = 0.05;  // P-AXIS-00195/00196 50000 us
  a.dynamics.ramp_dec_up = a.dynamics.ramp_dec_down = 0.05;  // P-AXIS-00197/00198
  const GeneratorConfig g = make_generator_config(a);
  CHECK(g.dynamics.v_max == doctest::Approx(166.666));
  CHECK(g.dynamics.j_max == doctest::Approx(20000.0));
  CHECK(make_position_control(a).kv == doctest::Approx(10.0));  // P-AXIS-00099 1000 x 0.01/s
}

TEST_CASE("ncsim.profile_rule (NCSIM-AXIS-030) selects the generator's profile rule") {
  machines::AxisParams a;
  a.dynamics.v_max = a.dynamics.v_rapid = 100.0;
  a.dynamics.acc_feed = a.dynamics.dec_feed = 1000.0;
  a.dynamics.ramp_acc_up = a.dynamics.ramp_acc_down = 0.05;
  a.dynamics.ramp_dec_up = a.dynamics.ramp_dec_down = 0.05;
  CHECK(make_generator_config(a).profile_rule == ProfileRule::manual);  // default: 002 rules
  a.dynamics.time_optimal_profiles = true;
  CHECK(make_generator_config(a).profile_rule == ProfileRule::time_optimal);
}

// A machine whose X list sets `ncsim.profile_rule time_optimal` (the other lists: the bad-list
// corpus' base machine, table defaults): the loaded axis plans time-optimal profiles.
machines::LoadResult load_base_with_x_line(const std::string& dir_name, const std::string& line) {
  const char* root = std::getenv("NCSIM_SOURCE_DIR");
  REQUIRE_MESSAGE(root != nullptr, "NCSIM_SOURCE_DIR must point to the repository");
  const std::filesystem::path base = std::filesystem::path(root) / "machines" / "testdata" / "base";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / dir_name;
  std::filesystem::create_directories(dir);
  {
    std::ifstream x_in(base / "x.lis");
    std::ofstream x_out(dir / "x.lis");
    x_out << x_in.rdbuf() << "\n" << line << "\n";
    std::ofstream index(dir / machines::kMachineIndexFile);
    index << "channel " << (base / "channel.lis").string() << "\n"
          << "axis X " << (dir / "x.lis").string() << "\n"
          << "axis Y " << (base / "y.lis").string() << "\n"
          << "axis Z " << (base / "z.lis").string() << "\n"
          << "axis S " << (base / "s.lis").string() << "\n";
  }
  return machines::load_machine(dir);
}

void step_ok(SetpointGenerator& g, double cycle) {
  const Result r = g.step(cycle);
  REQUIRE((r == Result::working || r == Result::finished));
}

// Time until the generator is idle after a new end position behind the axis at 60 % of the way.
double time_with_new_end_position(const GeneratorConfig& config) {
  SetpointGenerator g(config);
  REQUIRE(g.start_position(100.0) == Result::ok);
  double t = 0.0;
  const double cycle = 0.001;
  while (g.setpoint().p < 60.0) {
    step_ok(g, cycle);
    t += cycle;
  }
  REQUIRE(g.new_end_position(-50.0) == Result::ok);
  while (g.moving()) {
    step_ok(g, cycle);
    t += cycle;
    REQUIRE(t < 100.0);
  }
  CHECK(g.setpoint().p == -50.0);
  return t;
}

TEST_CASE("a machine list with ncsim.profile_rule time_optimal gives the time-optimal profile") {
  const machines::LoadResult plain = load_base_with_x_line("ncsim_axes_profile_rule_plain", "");
  REQUIRE(plain.machine.has_value());
  const machines::LoadResult fast =
      load_base_with_x_line("ncsim_axes_profile_rule_fast", "ncsim.profile_rule time_optimal");
  REQUIRE(fast.machine.has_value());
  const GeneratorConfig manual = make_axis_config(axis(*plain.machine, "X")).generator;
  const GeneratorConfig optimal = make_axis_config(axis(*fast.machine, "X")).generator;
  CHECK(manual.profile_rule == ProfileRule::manual);  // NCSIM-AXIS-030 default
  CHECK(optimal.profile_rule == ProfileRule::time_optimal);
  // 002 2.3 (manual): stop, then return; time-optimal: reverse without a stop, earlier.
  const double t_manual = time_with_new_end_position(manual);
  const double t_optimal = time_with_new_end_position(optimal);
  CHECK(t_optimal < t_manual);
  // The plan itself equals plan_position under the loaded rule.
  Profile from_config;
  Profile direct;
  const MotionState start{0.0, 100.0, 0.0};
  REQUIRE(plan_position(start, PositionTarget{-10.0, 0.0}, optimal.dynamics, from_config,
                        optimal.profile_rule) == Result::ok);
  REQUIRE(plan_position(start, PositionTarget{-10.0, 0.0}, optimal.dynamics, direct,
                        ProfileRule::time_optimal) == Result::ok);
  CHECK(from_config.duration() == direct.duration());
}

TEST_CASE("machines and axes default Kv to the same P-AXIS-00099 value") {
  CHECK(PositionControlParams{}.kv == machines::kDefaultKv);
  CHECK(machines::ControlLoop{}.kv == machines::kDefaultKv);
}

}  // namespace
}  // namespace ncsim::axes
