// #MACHINE DATA at run time (program/machine_data.hpp; seed 004 §2.1.4 l.391, isg-language.md
// §5.10): the conveyor axis's filters and delay time change with the path standing; any other
// parameter is NC6001 at its line.

#include "program/machine_data.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

using Ran = channel::test::ConveyorRun;

// `program` on laser_portal (1 ms; S is its conveyor axis) with `port` attached (null: none).
Ran run(const std::string& program, conveyor::Port* port) {
  return channel::test::run_conveyor(program, interp::test::machine("laser_portal"), port, 100'000);
}

interp::MachineData setting(std::uint8_t axis, std::string_view id, std::string_view key,
                            double value) {
  interp::MachineData md;
  md.axis = axis;
  md.settings.push_back(interp::MachineSetting{id, key, std::nullopt, value, ""});
  return md;
}

}  // namespace

TEST_CASE("#MACHINE DATA: only the conveyor axis's filter and delay parameters run") {
  const machines::Machine& m = interp::test::machine("laser_portal");
  const machines::AxisParams* belt = m.conveyor_axis();
  REQUIRE(belt != nullptr);
  const auto s = static_cast<std::uint8_t>(belt - m.axes.data());
  const auto x = static_cast<std::uint8_t>(m.find_axis("X") - m.axes.data());
  CHECK_FALSE(program::machine_data_unsupported(
      setting(s, "P-AXIS-00626", "conv_sync.delay_time", 0.02), m));
  CHECK_FALSE(program::machine_data_unsupported(
      setting(s, "NCSIM-AXIS-006", "conv_sync.order_pos_filter", 8), m));
  const auto limit =
      program::machine_data_unsupported(setting(x, "P-AXIS-00212", "getriebe[0].vb_max", 500.0), m);
  REQUIRE(limit);
  CHECK(limit->find("P-AXIS-00212") != std::string::npos);
  CHECK(limit->find("axis X") != std::string::npos);
  // A filter key on an axis that is not the conveyor's is not a filter change either.
  CHECK(program::machine_data_unsupported(setting(x, "P-AXIS-00626", "conv_sync.delay_time", 0.02),
                                          m));

  machines::ConveyorAxisParams p = *belt->conveyor;
  interp::MachineData md = setting(s, "P-AXIS-00626", "conv_sync.delay_time", 0.02);
  md.settings.push_back(
      interp::MachineSetting{"P-AXIS-00620", "conv_sync.enable_filter", std::nullopt, 0.0, ""});
  md.settings.push_back(
      interp::MachineSetting{"P-AXIS-00623", "conv_sync.order_v_filter", std::nullopt, 5.0, ""});
  const machines::ConveyorAxisParams q = program::apply_machine_data(p, md);
  CHECK(q.delay_time == 0.02);
  CHECK_FALSE(q.enable_filter);
  CHECK(q.order_v_filter == 5);
  CHECK(q.order_pos_filter == p.order_pos_filter);  // untouched
  CHECK(q.order_post_v_filter == p.order_post_v_filter);
}

TEST_CASE("#MACHINE DATA on the conveyor's filters reaches the Port with the path standing") {
  tracking::test::FakePort port(0.0);
  const Ran r =
      run("%t\nN10 G01 X10 F6000\nN20 #MACHINE DATA [AX=S P-AXIS-00626=20000 P-AXIS-00623=5]\n"
          "N30 G01 X20\nN40 M30\n",
          &port);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  REQUIRE(r.source_error.empty());
  REQUIRE(port.params_);
  CHECK(port.params_->delay_time == doctest::Approx(0.02));  // 20000 us
  CHECK(port.params_->order_v_filter == 5);
  CHECK(port.params_->order_pos_filter == 4);  // the list's, unchanged
  CHECK(port.params_->enable_filter);
  // "An active path interpolation stops until the value takes effect" (§5.10): N10 ends at
  // rest on X 10 in the cycle the change comes (port step k is cycle k - 1's), N30 after it.
  REQUIRE(port.params_at_ >= 2);
  const auto k = static_cast<std::size_t>(port.params_at_);
  REQUIRE(k < r.axes.size());
  CHECK(r.axes[k - 2].command[0] < 10.0);
  CHECK(r.axes[k - 1].command[0] == 10.0);
  CHECK(r.axes[k].command[0] - 10.0 < 0.01);  // the first cycle of N30, jerk-limited from rest
  CHECK(r.axes.back().command[0] == 20.0);
}

TEST_CASE("#MACHINE DATA of any other parameter is NC6001 at its line after the blocks before") {
  tracking::test::FakePort port(0.0);
  const Ran r =
      run("%t\nN10 G01 X10 F6000\nN20 #MACHINE DATA [AX=X P-AXIS-00212=500]\nN30 G01 X20\nM30\n",
          &port);
  CHECK(r.source_error == "NC6001");
  CHECK(r.source_line == 3);
  CHECK(r.source_message.find("P-AXIS-00212") != std::string::npos);
  REQUIRE_FALSE(r.axes.empty());
  CHECK(r.axes.back().command[0] == doctest::Approx(10.0));
  CHECK_FALSE(port.params_);
}

TEST_CASE("#MACHINE DATA of the filters without a conveyor world is NC6001 naming it") {
  const Ran r = run("%t\nN10 #MACHINE DATA [AX=S P-AXIS-00626=20000]\nN20 M30\n", nullptr);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC6001");
  CHECK(r.error->message.find("[conveyor]") != std::string::npos);
}

TEST_CASE("#MACHINE DATA of the filters on a world that cannot change them is NC6001 at its line") {
  tracking::test::FakePort port(0.0);
  port.takes_params_ = false;
  const Ran r =
      run("%t\nN10 G01 X10 F6000\nN20 #MACHINE DATA [AX=S P-AXIS-00626=20000]\nN30 G01 X20\n"
          "N40 M30\n",
          &port);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC6001");
  CHECK(r.error->line == 3);
  CHECK(r.error->message.find("on this conveyor world") != std::string::npos);
  CHECK_FALSE(port.params_);
  REQUIRE_FALSE(r.axes.empty());
  CHECK(r.axes.back().command[0] == 10.0);  // N10 ran to its end, N30 never started
}

TEST_CASE("NC9061: #MACHINE DATA of the filters while synchronised, at its line") {
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 1;
  const Ran r =
      run("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
          "N40 #MACHINE DATA [AX=S P-AXIS-00626=0]\nN50 #SYNC OUT\nN60 M30\n",
          &port);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC9061");
  CHECK(r.error->line == 5);
  CHECK_FALSE(port.params_);
  // Before #SYNC IN and after #SYNC OUT the same change runs.
  tracking::test::FakePort after(300.0);
  after.latch_at_ = 1;
  const Ran ok =
      run("%t\nN10 #MACHINE DATA [AX=S P-AXIS-00626=0]\nN20 G01 X0 Y0 Z0 F6000\n"
          "N30 #SYNC IN [CONV_VEL=18000]\nN40 G01 X100 Y50 F6000\nN50 #SYNC OUT\n"
          "N60 G00 X-100 Y0\nN70 #MACHINE DATA [AX=S P-AXIS-00626=1000]\nN80 M30\n",
          &after);
  REQUIRE_FALSE(ok.error);
  REQUIRE(after.params_);
  CHECK(after.params_->delay_time == doctest::Approx(0.001));
}
