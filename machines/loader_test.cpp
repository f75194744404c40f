#include "machines/loader.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "machines/param_table.hpp"

namespace ncsim::machines {
namespace {

std::filesystem::path source_root() {
  const char* root = std::getenv("NCSIM_SOURCE_DIR");
  REQUIRE_MESSAGE(root != nullptr, "NCSIM_SOURCE_DIR must point to the repository");
  return root;
}

std::string all_diagnostics(const LoadResult& r) {
  std::string out;
  for (const auto& d : r.diagnostics.items())
    out += core::format(d);
  return out;
}

Machine load_bundled(std::string_view name) {
  const LoadResult r = load_machine(bundled_machine_dir(source_root(), name));
  INFO(all_diagnostics(r));
  CHECK(r.diagnostics.items().empty());
  REQUIRE(r.machine.has_value());
  return *r.machine;
}

// A machine of the bad-list corpus's base axis lists (machines/testdata/base) whose channel list
// is `channel` (written to a scratch folder named after `name`), and the channel list's path.
struct ChannelLoad {
  LoadResult result;
  std::string channel_file;
};
ChannelLoad load_base_with_channel(const std::string& name, const std::string& channel) {
  const auto base = source_root() / "machines" / "testdata" / "base";
  const auto dir = std::filesystem::temp_directory_path() / ("ncsim_machines_" + name);
  std::filesystem::create_directories(dir);
  {
    std::ofstream list(dir / "channel.lis");
    list << channel;
    std::ofstream index(dir / kMachineIndexFile);
    index << "channel channel.lis\n";
    for (const char* ax : {"X", "Y", "Z", "S"}) {
      std::string file(ax);
      file[0] = static_cast<char>(file[0] - 'A' + 'a');
      index << "axis " << ax << ' ' << (base / (file + ".lis")).string() << "\n";
    }
  }
  return {load_machine(dir), (dir / "channel.lis").string()};
}

// The only error of `r`; fails the test when there is not exactly one.
core::Diagnostic only_error(const LoadResult& r) {
  INFO(all_diagnostics(r));
  CHECK_FALSE(r.machine.has_value());
  std::vector<core::Diagnostic> errors;
  for (const core::Diagnostic& d : r.diagnostics.items())
    if (d.severity == core::Severity::error) errors.push_back(d);
  REQUIRE(errors.size() == 1);
  return errors[0];
}

TEST_CASE("every bundled machine loads without any diagnostic") {
  for (const char* name :
       {"laser_portal", "delta_picker", "static_saw", "portal_3x", "laser_portal_encoder"}) {
    CAPTURE(name);
    const Machine m = load_bundled(name);
    CHECK(m.name == name);
  }
}

TEST_CASE("laser_portal: soft limits arrive in mm and the conveyor is the spindle S") {
  const Machine m = load_bundled("laser_portal");
  REQUIRE(m.axes.size() == 4);
  const AxisParams* x = m.find_axis("X");
  REQUIRE(x != nullptr);
  CHECK(x->soft_limits.pos == doctest::Approx(4000.0));  // 40000000 x 0.1 um
  CHECK(x->soft_limits.neg == doctest::Approx(-200.0));
  CHECK(m.find_axis("Z")->soft_limits.pos == doctest::Approx(300.0));
  const AxisParams* s = m.find_axis("S1");  // "S" answers to S1 as well
  REQUIRE(s != nullptr);
  CHECK(s->name == "S");
  CHECK(s->kind == AxisKind::spindle);
  REQUIRE(s->conveyor.has_value());
  CHECK(s->conveyor->delay_time == doctest::Approx(0.017455));  // 17455 us
  CHECK(s->conveyor->order_v_filter == 10);
  CHECK(m.conveyor_axis() == s);
  CHECK(x->monitoring.exact_stop_window == doctest::Approx(0.05));  // 500 x 0.1 um
  REQUIRE(x->monitoring.settling_time.has_value());
  CHECK(*x->monitoring.settling_time == doctest::Approx(0.1));  // 100000 us
  REQUIRE(m.channel.conveyor.has_value());
  const ConveyorSyncChannel& c = *m.channel.conveyor;
  CHECK(m.channel.interpolator.conveyor_tracking);
  CHECK(c.master_axis_number == 4);
  CHECK(c.hold_limit_vel_factor == doctest::Approx(0.95));  // 950 x 0.1 %
  CHECK(c.hold_limit_tolerance == doctest::Approx(5.0));    // 5e4 x 0.1 um
  CHECK(c.sync_in_tolerance == doctest::Approx(0.01));
  CHECK(c.pos_limit == doctest::Approx(-190.0));
  CHECK_FALSE(c.workspace_configured);  // falls back to the soft limits of X, Y, Z
  CHECK(c.workspace.upper.x() == doctest::Approx(4000.0));
  CHECK(c.workspace.lower.z() == doctest::Approx(-100.0));
  CHECK(m.find_axis("X")->conveyor == std::nullopt);
  // ISG keys in their list units, converted once (docs/machines.md "Axis dynamics").
  CHECK(x->dynamics.v_max == doctest::Approx(1000.0));      // 1000000 um/s P-AXIS-00212
  CHECK(x->dynamics.v_rapid == doctest::Approx(1000.0));    // P-AXIS-00209
  CHECK(x->dynamics.acc_max == doctest::Approx(10000.0));   // P-AXIS-00008
  CHECK(x->dynamics.ramp_acc_up == doctest::Approx(0.05));  // 50000 us P-AXIS-00196
  CHECK(x->dynamics.jerk_feed() == doctest::Approx(200000.0));
  // Feed hold: P-AXIS-00053 a_feedh 0 stands for P-AXIS-00004 a_grenz, P-AXIS-00081 tr_feedh 0
  // for P-AXIS-00200 tr_grenz.
  CHECK(x->dynamics.dec_feedhold == doctest::Approx(10000.0));
  CHECK(x->dynamics.ramp_feedhold == doctest::Approx(0.05));
  CHECK(x->control.kv == doctest::Approx(20.0));  // 2000 x 0.01/s P-AXIS-00099
}

TEST_CASE("an axis list without dynamics gets the TF5200 defaults, converted") {
  const LoadResult r = load_machine(source_root() / "machines" / "testdata" / "base");
  REQUIRE(r.machine.has_value());
  const Dynamics& d = r.machine->find_axis("X")->dynamics;
  CHECK(d.v_max == doctest::Approx(200.0));      // 200000 um/s
  CHECK(d.v_rapid == doctest::Approx(166.666));  // 166666 um/s
  CHECK(d.acc_max == doctest::Approx(1000.0));
  CHECK(d.acc_feed == doctest::Approx(1000.0));
  CHECK(d.dec_feed == doctest::Approx(1000.0));
  CHECK(d.acc_rapid == doctest::Approx(1000.0));
  CHECK(d.ramp_acc_down == doctest::Approx(0.05));
  CHECK(d.ramp_rapid == doctest::Approx(0.01));
  CHECK(d.ramp_min == doctest::Approx(0.01));
  CHECK(d.ramp_geom == doctest::Approx(0.01));
  CHECK(d.jerk_feed() == doctest::Approx(20000.0));
  CHECK(d.jerk_rapid() == doctest::Approx(100000.0));
  CHECK(r.machine->find_axis("X")->modulo_lower == 0.0);                     // P-AXIS-00127
  CHECK(r.machine->find_axis("X")->modulo_upper == doctest::Approx(360.0));  // 3600000 x 1e-4
  CHECK(r.machine->find_axis("X")->control.kv == doctest::Approx(kDefaultKv));
  CHECK(kDefaultKv == 10.0);
}

TEST_CASE(
    "conveyor lists without filter keys or P-CHAN-00366 get the defaults 0 / 20 / 10 / 6 and "
    "1000") {
  // machines/testdata/base names none of P-AXIS-00620, 00623, 00625, 00624 (s.lis) nor
  // P-CHAN-00366 (channel.lis): 004 section 5.2 gives their defaults.
  const LoadResult r = load_machine(source_root() / "machines" / "testdata" / "base");
  INFO(all_diagnostics(r));
  REQUIRE(r.machine.has_value());
  const AxisParams* s = r.machine->find_axis("S");
  REQUIRE(s != nullptr);
  REQUIRE(s->conveyor.has_value());
  CHECK_FALSE(s->conveyor->enable_filter);       // P-AXIS-00620 = 0
  CHECK(s->conveyor->order_v_filter == 20);      // P-AXIS-00623
  CHECK(s->conveyor->order_v_filter_dyn == 10);  // P-AXIS-00625
  CHECK(s->conveyor->order_post_v_filter == 6);  // P-AXIS-00624
  REQUIRE(r.machine->channel.conveyor.has_value());
  CHECK(r.machine->channel.conveyor->hold_limit_vel_factor ==
        doctest::Approx(1.0));  // 1000 x 0.1 %
}

TEST_CASE("an unknown key close to a known one is answered with the known key and its id") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsim_machines_did_you_mean";
  std::filesystem::create_directories(dir);
  const auto base =
      std::filesystem::path(std::getenv("NCSIM_SOURCE_DIR")) / "machines" / "testdata" / "base";
  {
    std::ofstream index(dir / kMachineIndexFile);
    index << "channel " << (base / "channel.lis").string() << "\naxis X x.lis\naxis S "
          << (base / "s.lis").string() << "\n";
    std::ofstream x(dir / "x.lis");
    x << "kopf.log_achs_name X\nkopf.achs_nr 1\nkenngr.swe_poss 100\n"
      << "getriebe[0].dynamik.vb_eilgang 1000\ncompletely.different 1\n";
  }
  const LoadResult r = load_machine(dir);
  INFO(all_diagnostics(r));
  REQUIRE(r.diagnostics.items().size() == 3);
  CHECK(r.diagnostics.items()[0].message ==
        "unknown parameter 'kenngr.swe_poss' in the axis list; did you mean kenngr.swe_pos "
        "(P-AXIS-00178)?");
  CHECK(r.diagnostics.items()[1].message.find(
            "did you mean getriebe[].vb_eilgang (P-AXIS-00209)") != std::string::npos);
  CHECK(r.diagnostics.items()[2].message.find("did you mean") == std::string::npos);
}

TEST_CASE("every retired key (NC3015, NC3013) names its replacement, none is also a live key") {
  for (const RetiredKey& k : retired_keys()) {
    CAPTURE(k.key);
    CHECK(find_param(k.list, k.key) == nullptr);
    CHECK((k.diagnostic == "NC3015" || k.diagnostic == "NC3013"));
    CHECK(!k.use_instead.empty());
  }
}

TEST_CASE("delta_picker: trafo parameters arrive in mm and the workspace is configured") {
  const Machine m = load_bundled("delta_picker");
  REQUIRE(m.channel.trafos.size() == 1);
  const TrafoParams& t = m.channel.trafos[0];
  CHECK(t.id == 37);
  CHECK(t.param[4] == doctest::Approx(200.0));
  CHECK(t.param[6] == doctest::Approx(465.544));
  CHECK(t.param[10] == doctest::Approx(-180.0));
  REQUIRE(m.channel.conveyor.has_value());
  CHECK(m.channel.conveyor->workspace_configured);
  CHECK(m.channel.conveyor->workspace.lower.z() == doctest::Approx(-500.0));
  CHECK(m.find_axis("S1")->number == 5);
  CHECK(m.channel.main_spindle_number == 5);
  CHECK(m.find_axis("X")->kind == AxisKind::rotary);
}

TEST_CASE("static_saw: virtual X, T0 shift and tracking axis arrive converted") {
  const Machine m = load_bundled("static_saw");
  REQUIRE(m.channel.conveyor.has_value());
  CHECK(m.channel.conveyor->x_virtual);
  CHECK(m.channel.conveyor->t0_shift.x() == doctest::Approx(-100.0));
  CHECK(m.channel.conveyor->t0().apply(Eigen::Vector3d::Zero()).x() == doctest::Approx(-100.0));
  CHECK(m.channel.tracking_axis_number == 4);
  CHECK(m.find_axis("Z")->soft_limits.pos == doctest::Approx(55.0));
  CHECK(m.find_axis("X")->drive_type == 4);
}

TEST_CASE("portal_3x: no conveyor, standard look-ahead, unknown axis names give nothing") {
  const Machine m = load_bundled("portal_3x");
  CHECK_FALSE(m.channel.conveyor.has_value());
  CHECK(m.channel.interpolator.look_ahead_blocks == 120);
  CHECK(m.conveyor_axis() == nullptr);
  CHECK(m.find_axis("A") == nullptr);
  CHECK(m.find_axis("S1") == nullptr);
  REQUIRE(m.soft_limits("Z").has_value());
  CHECK(m.soft_limits("Z")->neg == doctest::Approx(-300.0));
  CHECK(m.axes[0].name == "X");
}

TEST_CASE("a missing machine folder is one diagnostic, not an exception") {
  const LoadResult r = load_machine(source_root() / "machines" / "no_such_machine");
  CHECK_FALSE(r.machine.has_value());
  REQUIRE(r.diagnostics.items().size() == 1);
  CHECK(r.diagnostics.items()[0].id == "NC3010");
}

TEST_CASE(
    "warnings: hold_limit_vel_factor above 1000 is limited (21483), a feed acceleration "
    "above P-AXIS-00008 and a ramp below P-AXIS-00201 are limited (NC3020), and the machine "
    "still loads") {
  const LoadResult r = load_machine(source_root() / "machines" / "testdata" / "warn");
  INFO(all_diagnostics(r));
  REQUIRE(r.machine.has_value());
  CHECK_FALSE(r.diagnostics.has_errors());
  REQUIRE(r.diagnostics.items().size() == 3);
  CHECK(r.diagnostics.items()[0].id == "NC3020");
  CHECK(r.diagnostics.items()[0].severity == core::Severity::warning);
  CHECK(r.diagnostics.items()[0].loc.line == 5);
  // y.lis: tr_grenz below tr_min is named; tr_feedh 0 (= tr_grenz) is not blamed.
  CHECK(r.diagnostics.items()[1].id == "NC3020");
  CHECK(r.diagnostics.items()[1].loc.line == 6);
  CHECK(r.diagnostics.items()[1].message.find("tr_grenz") != std::string::npos);
  CHECK(r.diagnostics.items()[2].id == "21483");
  CHECK(r.diagnostics.items()[2].loc.line == 4);
  const Dynamics& y = r.machine->find_axis("Y")->dynamics;
  CHECK(y.ramp_rapid == doctest::Approx(0.02));     // raised to P-AXIS-00201
  CHECK(y.ramp_feedhold == doctest::Approx(0.02));  // P-AXIS-00081 0: = P-AXIS-00200
  CHECK(r.machine->channel.conveyor->hold_limit_vel_factor == doctest::Approx(1.0));
  CHECK(r.machine->find_axis("X")->dynamics.acc_feed == doctest::Approx(500.0));
}

TEST_CASE("the parameter table has unique keys, sane ranges and docs for every key") {
  const auto table = param_table();
  std::ifstream docs(source_root() / "docs" / "machines.md");
  REQUIRE(docs.good());
  const std::string text((std::istreambuf_iterator<char>(docs)), std::istreambuf_iterator<char>());
  for (std::size_t i = 0; i < table.size(); ++i) {
    CAPTURE(table[i].key);
    CHECK(table[i].min <= table[i].max);
    CHECK(text.find("`" + std::string(table[i].key) + "`") != std::string::npos);
    for (std::size_t k = 0; k < i; ++k) {
      CHECK_FALSE((table[k].key == table[i].key && table[k].list == table[i].list));
    }
  }
}

/// The test base machine (X, Y, Z, conveyor S) with `line` as the channel list's third line.
LoadResult load_with(const std::string& line) {
  return load_base_with_channel("channel_line",
                                "configuration.interpolator.function FCT_DLM\n"
                                "conveyor_sync.log_number_master 4\n" +
                                    line + "\n")
      .result;
}

/// True when `r` refused its list with `id` at the channel list's third line (load_with's line),
/// the message naming `what`.
bool refused_at_line_3(const LoadResult& r, const std::string& id, const std::string& what) {
  if (r.machine.has_value() || r.diagnostics.items().empty()) return false;
  const core::Diagnostic& d = r.diagnostics.items()[0];
  return d.id == id && d.loc.line == 3 && d.message.find(what) != std::string::npos;
}

TEST_CASE("P-CHAN-00014 einrechnen_mit_t is read once at load (default 0)") {
  const LoadResult plain = load_with("");
  REQUIRE(plain.machine.has_value());
  CHECK_FALSE(plain.machine->channel.d_with_t);
  const LoadResult on = load_with("einrechnen_mit_t 1");
  INFO(all_diagnostics(on));
  REQUIRE(on.machine.has_value());
  CHECK(on.machine->channel.d_with_t);
  CHECK(refused_at_line_3(load_with("einrechnen_mit_t 2"), "NC3004", "P-CHAN-00014"));
}

TEST_CASE("P-CHAN-00097 = 1 (feed hold on the feed-hold ramps) is NC3013 at its line; 0 loads") {
  const LoadResult zero = load_with("use_drive_curr_limit 0");
  INFO(all_diagnostics(zero));
  CHECK(zero.machine.has_value());
  CHECK(refused_at_line_3(load_with("use_drive_curr_limit 1"), "NC3013", "P-CHAN-00097"));
}

TEST_CASE(
    "NCSIM-CHAN-630 path override type: REDUCED by default, ORIGINAL read, a typo refused; "
    "NCSIM-CHAN-640 read in 0.1 %") {
  const LoadResult plain = load_with("");
  INFO(all_diagnostics(plain));
  REQUIRE(plain.machine.has_value());
  CHECK(plain.machine->channel.path_override_type == PathOverrideType::reduced);
  const LoadResult original = load_with("ncsim.path_override_type ORIGINAL");
  REQUIRE(original.machine.has_value());
  CHECK(original.machine->channel.path_override_type == PathOverrideType::original);
  const LoadResult above = load_with("ncsim.path_override_type REDUCED_ABOVE_100");
  REQUIRE(above.machine.has_value());
  CHECK(above.machine->channel.path_override_type == PathOverrideType::reduced_above_100);
  CHECK(
      refused_at_line_3(load_with("ncsim.path_override_type REDUCE"), "NC3004", "NCSIM-CHAN-630"));
  // NCSIM-CHAN-640, the belt's dynamics reserve in 0.1 % (004 l.454)
  REQUIRE(plain.machine->channel.conveyor.has_value());
  CHECK(plain.machine->channel.conveyor->dynamics_reserve == 0.0);
  const LoadResult reserve = load_with("conveyor_sync.ncsim_dynamics_reserve 15");
  REQUIRE(reserve.machine.has_value());
  CHECK(reserve.machine->channel.conveyor->dynamics_reserve == doctest::Approx(0.015));
  const LoadResult too_much = load_with("conveyor_sync.ncsim_dynamics_reserve 501");
  CHECK_FALSE(too_much.machine.has_value());
  REQUIRE_FALSE(too_much.diagnostics.items().empty());
  CHECK(too_much.diagnostics.items()[0].message.find("NCSIM-CHAN-640") != std::string::npos);
}

TEST_CASE("a channel with more axes than ncsim supports is refused at the index line") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsim_machines_too_many_axes";
  std::filesystem::create_directories(dir);
  const auto base =
      std::filesystem::path(std::getenv("NCSIM_SOURCE_DIR")) / "machines" / "testdata" / "base";
  {
    std::ofstream index(dir / kMachineIndexFile);
    index << "channel " << (base / "channel.lis").string() << "\n";
    for (std::size_t i = 0; i <= kMaxChannelAxes; ++i) {
      index << "axis X" << i << ' ' << (base / "x.lis").string() << "\n";
    }
  }
  const LoadResult r = load_machine(dir);
  CHECK_FALSE(r.machine.has_value());
  bool found = false;
  for (const core::Diagnostic& d : r.diagnostics.items()) {
    found = found || (d.id == "NC3014" && d.loc.line == kMaxChannelAxes + 2);
  }
  CHECK(found);
}

TEST_CASE(
    "P-CHAN-00071 prog_start.slope.profile: STEP when absent, 0 / 1 / 2 read as STEP / TRAPEZ / "
    "SIN2") {
  const std::string head =
      "configuration.interpolator.function FCT_DLM\n"
      "conveyor_sync.log_number_master 4\n";
  const ChannelLoad absent = load_base_with_channel("slope_absent", head);
  INFO(all_diagnostics(absent.result));
  REQUIRE(absent.result.machine.has_value());
  CHECK(absent.result.machine->channel.start_slope == SlopeProfile::step);
  const std::pair<const char*, SlopeProfile> cases[] = {
      {"0", SlopeProfile::step}, {"1", SlopeProfile::trapez}, {"2", SlopeProfile::sin2}};
  for (const auto& [text, want] : cases) {
    CAPTURE(text);
    const ChannelLoad r =
        load_base_with_channel("slope_read", head + "prog_start.slope.profile " + text + "\n");
    INFO(all_diagnostics(r.result));
    CHECK(r.result.diagnostics.items().empty());
    REQUIRE(r.result.machine.has_value());
    CHECK(r.result.machine->channel.start_slope == want);
  }
  // Every bundled machine starts on STEP, today's behaviour (the goldens depend on it).
  for (const char* name : {"laser_portal", "delta_picker", "static_saw", "portal_3x"}) {
    CAPTURE(name);
    CHECK(load_bundled(name).channel.start_slope == SlopeProfile::step);
  }
}

TEST_CASE(
    "P-CHAN-00009 corr_v_trans_jerk: on when absent (ncsim's default), 0 and 1 read, 2 is "
    "outside the BOOLEAN at its line") {
  const std::string head =
      "configuration.interpolator.function FCT_DLM\n"
      "conveyor_sync.log_number_master 4\n";
  const ChannelLoad absent = load_base_with_channel("c1_absent", head);
  INFO(all_diagnostics(absent.result));
  REQUIRE(absent.result.machine.has_value());
  CHECK(absent.result.machine->channel.corr_v_trans_jerk);
  for (const bool on : {false, true}) {
    CAPTURE(on);
    const ChannelLoad r =
        load_base_with_channel("c1_read", head + "corr_v_trans_jerk " + (on ? "1" : "0") + "\n");
    INFO(all_diagnostics(r.result));
    CHECK(r.result.diagnostics.items().empty());
    REQUIRE(r.result.machine.has_value());
    CHECK(r.result.machine->channel.corr_v_trans_jerk == on);
  }
  const ChannelLoad two = load_base_with_channel("c1_two", head + "corr_v_trans_jerk 2\n");
  const core::Diagnostic e = only_error(two.result);
  CHECK(e.file == two.channel_file);
  CHECK(e.loc.line == 3);
  CHECK(e.message.find("corr_v_trans_jerk (P-CHAN-00009)") != std::string::npos);
}

TEST_CASE(
    "NCSIM-CHAN-620 ncsim.default_path_dev: 1 mm when absent, read in mm, 0 refused; the axis "
    "list's nci.tolerance_ball (NCSIM-AXIS-021) is retired and names it") {
  const std::string head =
      "configuration.interpolator.function FCT_DLM\n"
      "conveyor_sync.log_number_master 4\n";
  const ChannelLoad absent = load_base_with_channel("dev_absent", head);
  REQUIRE(absent.result.machine.has_value());
  CHECK(absent.result.machine->channel.default_path_dev == 1.0);
  const ChannelLoad set = load_base_with_channel("dev_set", head + "ncsim.default_path_dev 0.05\n");
  INFO(all_diagnostics(set.result));
  CHECK(set.result.diagnostics.items().empty());
  REQUIRE(set.result.machine.has_value());
  CHECK(set.result.machine->channel.default_path_dev == 0.05);
  const ChannelLoad zero = load_base_with_channel("dev_zero", head + "ncsim.default_path_dev 0\n");
  const core::Diagnostic e = only_error(zero.result);
  CHECK(e.id == "NC3004");
  CHECK(e.loc.line == 3);
  CHECK(e.message.find("ncsim.default_path_dev (NCSIM-CHAN-620)") != std::string::npos);
  const RetiredKey* ball = find_retired(ListKind::axis, "nci.tolerance_ball");
  REQUIRE(ball != nullptr);
  CHECK(std::string(ball->use_instead).find("ncsim.default_path_dev (NCSIM-CHAN-620)") !=
        std::string::npos);
  CHECK(find_param(ListKind::axis, "nci.tolerance_ball") == nullptr);
}

TEST_CASE(
    "NCSIM-CHAN-610 ncsim.cycle_time: 1 ms when absent, whole us read into s, 0 and above 1 s "
    "refused at their line") {
  const std::string head =
      "configuration.interpolator.function FCT_DLM\n"
      "conveyor_sync.log_number_master 4\n";
  const ChannelLoad absent = load_base_with_channel("cycle_absent", head);
  REQUIRE(absent.result.machine.has_value());
  CHECK(absent.result.machine->channel.cycle_time == 0.001);
  const ChannelLoad set = load_base_with_channel("cycle_set", head + "ncsim.cycle_time 250\n");
  INFO(all_diagnostics(set.result));
  CHECK(set.result.diagnostics.items().empty());
  REQUIRE(set.result.machine.has_value());
  CHECK(set.result.machine->channel.cycle_time == 250 * 1e-6);  // as --cycle-us 250
  for (const char* bad : {"0", "1000001", "2.5"}) {
    CAPTURE(bad);
    const ChannelLoad r =
        load_base_with_channel("cycle_bad", head + "ncsim.cycle_time " + bad + "\n");
    const core::Diagnostic e = only_error(r.result);
    CHECK(e.loc.line == 3);
    CHECK(e.message.find("ncsim.cycle_time (NCSIM-CHAN-610)") != std::string::npos);
  }
}

TEST_CASE(
    "P-CHAN-00071: 3 (HSC) is NC3013 and a value outside 0..3 or not an integer is refused, each "
    "at its file:line with the id") {
  const std::string head =
      "configuration.interpolator.function FCT_DLM\n"
      "conveyor_sync.log_number_master 4\n";
  {
    const ChannelLoad r =
        load_base_with_channel("slope_hsc", head + "prog_start.slope.profile 3\n");
    const core::Diagnostic e = only_error(r.result);
    CHECK(e.id == "NC3013");
    CHECK(e.file == r.channel_file);
    CHECK(e.loc.line == 3);
    CHECK(e.message.find("prog_start.slope.profile (P-CHAN-00071)") != std::string::npos);
    CHECK(e.message.find("HSC") != std::string::npos);
    CHECK(e.message.find("write 0 (STEP), 1 (TRAPEZ) or 2 (SIN2)") != std::string::npos);
  }
  const std::pair<const char*, const char*> bad[] = {{"4", "NC3004"},
                                                     {"-1", "NC3004"},
                                                     {"65536", "NC3004"},
                                                     {"1.5", "NC3003"},
                                                     {"TRAPEZ", "NC3003"}};
  for (const auto& [text, id] : bad) {
    CAPTURE(text);
    const ChannelLoad r = load_base_with_channel(
        "slope_bad", "# a comment line\n" + head + "prog_start.slope.profile " + text + "\n");
    const core::Diagnostic e = only_error(r.result);
    CHECK(e.id == id);
    CHECK(e.file == r.channel_file);
    CHECK(e.loc.line == 4);
    CHECK(e.message.find("prog_start.slope.profile (P-CHAN-00071)") != std::string::npos);
    if (std::string(id) == "NC3004")
      CHECK(e.message.find("outside its range 0..3") != std::string::npos);
  }
}

TEST_CASE(
    "P-CHAN-00650 look-ahead window: FCT_DLM alone is STANDARD (120), LOW 30, HIGH 190, the same "
    "size twice is no conflict, CUSTOM takes P-CHAN-00653 (below 10: 50611, corrected)") {
  const std::string master = "conveyor_sync.log_number_master 4\n";
  const std::pair<const char*, int> sizes[] = {
      {"FCT_DLM", 120},
      {"FCT_IPO_DEFAULT|FCT_DLM", 120},
      {"FCT_LOOK_AHEAD_STANDARD|FCT_DLM", 120},
      {"FCT_IPO_DEFAULT|FCT_LOOK_AHEAD_STANDARD|FCT_DLM", 120},
      {"FCT_LOOK_AHEAD_LOW|FCT_DLM", 30},
      {"FCT_DLM|FCT_LOOK_AHEAD_HIGH", 190}};
  for (const auto& [flags, blocks] : sizes) {
    CAPTURE(flags);
    const ChannelLoad r = load_base_with_channel(
        "look_ahead", std::string("configuration.interpolator.function ") + flags + "\n" + master);
    INFO(all_diagnostics(r.result));
    CHECK(r.result.diagnostics.items().empty());
    REQUIRE(r.result.machine.has_value());
    CHECK(r.result.machine->channel.interpolator.look_ahead_blocks == blocks);
  }
  // FCT_LOOK_AHEAD_CUSTOM takes P-CHAN-00653 configuration.interpolator.number_blocks_lah
  // (TF5200: 10..10000, default 120; below 10 the kernel's 50611, corrected to 10); without
  // CUSTOM the key is not evaluated.
  const std::string custom = "configuration.interpolator.function FCT_DLM|FCT_LOOK_AHEAD_CUSTOM\n";
  const std::pair<std::string, int> custom_sizes[] = {
      {custom, 120},
      {custom + "configuration.interpolator.number_blocks_lah 250\n", 250},
      {custom + "configuration.interpolator.number_blocks_lah 10\n", 10},
      {"configuration.interpolator.function FCT_DLM\n"
       "configuration.interpolator.number_blocks_lah 250\n",
       120}};
  for (const auto& [lines, blocks] : custom_sizes) {
    CAPTURE(lines);
    const ChannelLoad r = load_base_with_channel("look_ahead_custom", master + lines);
    INFO(all_diagnostics(r.result));
    CHECK(r.result.diagnostics.items().empty());
    REQUIRE(r.result.machine.has_value());
    CHECK(r.result.machine->channel.interpolator.look_ahead_blocks == blocks);
  }
  {
    const ChannelLoad r = load_base_with_channel(
        "look_ahead_large", master + custom + "configuration.interpolator.number_blocks_lah 600\n");
    REQUIRE(r.result.machine.has_value());
    CHECK(r.result.machine->channel.interpolator.look_ahead_blocks == 500);
    REQUIRE(r.result.diagnostics.items().size() == 1);
    const core::Diagnostic& w = r.result.diagnostics.items().front();
    CHECK(w.id == "NC3020");
    CHECK(w.severity == core::Severity::warning);
    CHECK(w.loc.line == 3);
    CHECK(w.message.find("limited to 500") != std::string::npos);
  }
  {
    const ChannelLoad r = load_base_with_channel(
        "look_ahead_small", master + custom + "configuration.interpolator.number_blocks_lah 5\n");
    REQUIRE(r.result.machine.has_value());
    CHECK(r.result.machine->channel.interpolator.look_ahead_blocks == 10);
    REQUIRE(r.result.diagnostics.items().size() == 1);
    const core::Diagnostic& w = r.result.diagnostics.items().front();
    CHECK(w.id == "50611");
    CHECK(w.severity == core::Severity::warning);
    CHECK(w.file == r.channel_file);
    CHECK(w.loc.line == 3);
    CHECK(w.message.find("corrected to 10") != std::string::npos);
  }
  {
    const ChannelLoad r = load_base_with_channel(
        "look_ahead_two",
        "configuration.interpolator.function FCT_LOOK_AHEAD_LOW|FCT_LOOK_AHEAD_HIGH|FCT_DLM\n" +
            master);
    const core::Diagnostic e = only_error(r.result);
    CHECK(e.id == "NC3007");
    CHECK(e.loc.line == 1);
    CHECK(e.message.find("FCT_LOOK_AHEAD_LOW and FCT_LOOK_AHEAD_HIGH") != std::string::npos);
  }
}

TEST_CASE(
    "P-CHAN-00041 / 00027 / 00081 / 00086: technology functions' synchronisation types by name or "
    "hex, PLC_INFO joined, and NCSIM-CHAN-650..653 execution times in ms") {
  const std::string head =
      "configuration.interpolator.function FCT_DLM\n"
      "conveyor_sync.log_number_master 4\n";
  const ChannelLoad r = load_base_with_channel("tech_ok", head +
                                                              "m_synch[6] MVS_SVS\n"
                                                              "m_synch[8] 0x00000008   # MNS_SNS\n"
                                                              "m_synch[9] NO_SYNCH\n"
                                                              "h_synch[2] PLC_INFO|MVS_SNS\n"
                                                              "spindel[0].s_synch 0x00020002\n"
                                                              "tool.synch MNS_SNS\n"
                                                              "ncsim.m_duration[6] 2500\n"
                                                              "ncsim.m_duration[7] 10\n"
                                                              "ncsim.h_duration[2] 40\n"
                                                              "ncsim.t_duration 4000\n");
  INFO(all_diagnostics(r.result));
  CHECK(r.result.diagnostics.items().empty());
  REQUIRE(r.result.machine.has_value());
  const TechTable& t = r.result.machine->channel.tech;
  CHECK(t.m.at(6).sync == TechSync::mvs_svs);
  CHECK(t.m.at(6).duration == doctest::Approx(2.5));
  CHECK(t.m.at(7).sync == TechSync::mos);  // a time alone keeps ncsim's default type
  CHECK(t.m.at(7).duration == doctest::Approx(0.01));
  CHECK(t.m.at(8).sync == TechSync::mns_sns);
  CHECK(t.m.at(9).sync == TechSync::none);
  CHECK(t.h.at(2).sync == TechSync::mvs_sns);
  CHECK(t.h.at(2).duration == doctest::Approx(0.04));
  CHECK(t.s.sync == TechSync::mvs_svs);
  CHECK(t.s.duration == 0.0);
  CHECK(t.t.sync == TechSync::mns_sns);
  CHECK(t.t.duration == doctest::Approx(4.0));
  CHECK(t.m.count(3) == 0);  // not listed: MOS with no time (TechFunction's default)
}

TEST_CASE(
    "P-CHAN-00041: MET_SVS, MNE_SNS, FAW_SYNCH and two base types are NC3013 not supported, an "
    "unknown name NC3003, a negative time NC3004, each at its line") {
  const std::string head =
      "configuration.interpolator.function FCT_DLM\n"
      "conveyor_sync.log_number_master 4\n";
  const std::pair<const char*, const char*> bad[] = {
      {"m_synch[7] MET_SVS", "NC3013"},       {"m_synch[7] MNE_SNS", "NC3013"},
      {"m_synch[7] MOS|FAW_SYNCH", "NC3013"}, {"m_synch[7] 0x00000006", "NC3013"},
      {"m_synch[7] 0x10000002", "NC3013"},    {"m_synch[7] MVS_FOO", "NC3003"},
      {"tool.synch 0x0000000G", "NC3003"},    {"ncsim.m_duration[7] -1", "NC3004"},
      {"m_synch[1000] MOS", "NC3009"}};
  for (const auto& [text, id] : bad) {
    CAPTURE(text);
    const ChannelLoad r = load_base_with_channel("tech_bad", head + text + "\n");
    const core::Diagnostic e = only_error(r.result);
    CHECK(e.id == id);
    CHECK(e.file == r.channel_file);
    CHECK(e.loc.line == 3);
    if (std::string(id) == "NC3013") CHECK(e.message.find("not supported") != std::string::npos);
  }
}

}  // namespace
}  // namespace ncsim::machines
