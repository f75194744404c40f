// Channel::master_display() (ipo/channel_lag.cpp): the display variables of the cycle with
// synchro_lag, 0 before the frame moves, the axes' lag behind the workpiece while it moves.

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "ipo/channel.hpp"
#include "ipo/program_source.hpp"
#include "ipo/test_port.hpp"

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

}  // namespace

TEST_CASE("master_display: synchro_lag 0 before the frame moves, then the axes' lag (< 0.05 mm)") {
  const core::SourceFile file("t.nc", kHold);
  const machines::Machine& m = interp::test::machine("laser_portal");
  interp::Interpreter in(file, m);
  ipo::ProgramSource src(in, m);
  ipo::Channel ch(ipo::channel_config(m, 0.001), src);
  ipo::test::FakePort port(300.0);
  port.latch_at_ = 100;
  ch.attach_conveyor(&port);
  int tracking = 0;
  for (int guard = 0; guard < 100'000; ++guard) {
    if (ch.step() != ipo::Status::running) break;
    const ipo::ConveyorSync& s = *ch.conveyor_sync();
    const ipo::MasterDisplay d = ch.master_display();
    CHECK(d.current_pos_master == s.display().current_pos_master);
    if (!s.moving_frame()) {
      CHECK(d.synchro_lag == 0.0);
      continue;
    }
    // The machine's actual X against the workpiece: - the following error of X (the axis
    // lags its command), the belt's share is the same in the command and the workpiece.
    CHECK(d.synchro_lag == doctest::Approx(-ch.axes().following_error[0]).epsilon(1e-9));
    if (ch.cycle().line == 4 && s.phase() == ipo::SyncPhase::tracking) {
      ++tracking;
      if (tracking > 200) CHECK(std::abs(d.synchro_lag) < 0.05);  // settled, feedforward
    }
  }
  CHECK(tracking > 900);
}
