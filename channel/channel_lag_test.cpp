// Channel::master_display() (channel/channel_lag.cpp): the display variables of the cycle with
// synchro_lag, 0 before the frame moves, the axes' lag behind the workpiece while it moves.

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "program/trafo.hpp"
#include "tracking/synchro_lag.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

// laser_portal, a belt at 300 mm/s (FakePort: no dead time, the latch is the truth).
const char* const kHold =
    "%t\n"
    "N10 #SYNC IN [CONV_VEL=18000]\n"
    "N20 G01 X100 Y50 F6000\n"  // the catch-up
    "N30 G04 1\n"               // held in PCS1
    "N40 #SYNC OUT\n"
    "N50 G00 X-100 Y0\n"
    "N60 M30\n";

// The delta picker on a 100 mm/s belt: a pick under #TRAFO ON (channel/trafo_conveyor_test.cpp).
const char* const kPick =
    "%t\n"
    "N10 #KIN ID[37]\n"
    "N20 #TRAFO ON\n"
    "N30 G01 X-150 Y0 Z-700 F60000\n"
    "N40 #SYNC IN [CONV_VEL=6000]\n"
    "N50 G01 X-100 Y20 Z-700 F60000\n"  // the catch-up
    "N60 G01 Z-800 F30000\n"            // down onto the workpiece (PCS1)
    "N70 G04 0.2\n"
    "N80 G01 Z-750 F30000\n"
    "N90 #SYNC OUT\n"
    "N100 M30\n";

}  // namespace

TEST_CASE("master_display: synchro_lag 0 before the frame moves, then the axes' lag (< 0.05 mm)") {
  const core::SourceFile file("t.nc", kHold);
  const machines::Machine& m = interp::test::machine("laser_portal");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  channel::Channel ch(channel::channel_config(m, 0.001), src);
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 100;
  ch.attach_conveyor(&port);
  int tracking = 0;
  for (int guard = 0; guard < 100'000; ++guard) {
    if (ch.step() != ipo::Status::running) break;
    const tracking::ConveyorSync& s = *ch.conveyor_sync();
    const tracking::MasterDisplay d = ch.master_display();
    CHECK(d.current_pos_master == s.display().current_pos_master);
    if (!s.moving_frame()) {
      CHECK(d.synchro_lag == 0.0);
      continue;
    }
    // The machine's actual X against the workpiece: - the following error of X (the axis
    // lags its command), the belt's share is the same in the command and the workpiece.
    CHECK(d.synchro_lag == doctest::Approx(-ch.axes().following_error[0]).epsilon(1e-9));
    if (ch.cycle().line == 4 && s.phase() == tracking::SyncPhase::tracking) {
      ++tracking;
      if (tracking > 200) CHECK(std::abs(d.synchro_lag) < 0.05);  // settled, feedforward
    }
  }
  CHECK(tracking > 900);
}

TEST_CASE("master_display under #TRAFO ON: synchro_lag is the actual TCP's against the workpiece") {
  // The joints' actual positions through the forward transform against the commanded TCP
  // (tracking::tcp_lag); it read 0 under #TRAFO ON before (session 27), which tune-delay worked
  // around with its own forward transform.
  machines::Machine m = interp::test::machine("delta_picker");
  m.channel.conveyor->workspace.lower = Eigen::Vector3d(-600, -600, -900);
  m.channel.conveyor->workspace.upper = Eigen::Vector3d(600, 600, 0);
  channel::ChannelConfig cfg = channel::channel_config(m, 0.001);
  const auto trafo = program::machine_trafo(m, cfg.path);
  REQUIRE(trafo);
  const planner::JointMap forward = program::forward_map(trafo->kinematics, trafo->slots);
  tracking::test::FakePort port(100.0);
  port.latch_at_ = 100;
  channel::test::ConveyorRig rig(kPick, m, std::move(cfg), &port);
  const channel::Channel& ch = rig.ch;
  int transformed = 0;
  double largest = 0.0;
  for (int guard = 0; guard < 100'000 && rig.ch.step() == ipo::Status::running; ++guard) {
    const tracking::ConveyorSync& s = *ch.conveyor_sync();
    if (!s.moving_frame() || !ch.transformed()) continue;
    ++transformed;
    std::array<double, planner::kMaxAxes> tcp{};
    for (std::size_t i = 0; i < ch.axis_count(); ++i)
      tcp[i] = ch.tcp()[i].p;
    const auto want = tracking::tcp_lag(s, std::span<const double>(tcp.data(), ch.axis_count()),
                                        ch.axes().actual, forward);
    REQUIRE(want);
    CHECK(ch.master_display().synchro_lag == *want);
    largest = std::max(largest, std::abs(*want));
  }
  CHECK_FALSE(ch.run_time_error());
  CHECK(transformed > 300);
  CHECK(largest > 1e-3);  // the joints lag their commands: the TCP lags the workpiece
}
