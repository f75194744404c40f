// The channel with conveyor tracking (issue 14; docs/conveyor.md "Synchronisation"): the
// attached Port is stepped every cycle; without #SYNC IN the axes run in MCS untouched.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

using Ran = channel::test::ConveyorRun;

// Runs `program` on `machine_name` (1 ms) with `port` attached (null: none).
Ran run(const std::string& program, conveyor::Port* port,
        const std::string& machine_name = "laser_portal") {
  return channel::test::run_conveyor(program, interp::test::machine(machine_name), port);
}

}  // namespace

TEST_CASE("the attached Port is stepped every cycle; MCS motion is untouched by it") {
  const std::string program = "%t\nN10 G01 X100 Y20 F6000\nN20 M30\n";
  tracking::test::FakePort port(300.0);
  const Ran with = run(program, &port);
  const Ran without = run(program, nullptr);
  REQUIRE(with.status == ipo::Status::finished);
  REQUIRE(with.axes.size() == without.axes.size());
  CHECK(port.steps_ == static_cast<long>(with.axes.size()));
  CHECK(port.t_ == doctest::Approx(0.001 * static_cast<double>(with.axes.size())));
  for (std::size_t k = 0; k < with.axes.size(); ++k)
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(with.axes[k].command[i] == without.axes[k].command[i]);
}

TEST_CASE("a channel without conveyor tracking ignores an attached Port") {
  tracking::test::FakePort port(300.0);
  const Ran r = run("%t\nN10 G01 X10 F6000\nN20 M30\n", &port, "portal_3x");
  CHECK(r.status == ipo::Status::finished);
  CHECK(port.steps_ == 0);
}

namespace {

struct Tracked {
  ipo::Status status = ipo::Status::finished;
  std::vector<std::uint32_t> line;
  std::vector<tracking::SyncPhase> phase;
  std::vector<std::array<double, 3>> x;       // command X, Y, Z (MCS)
  std::vector<std::array<double, 3>> offset;  // PCS1 offset on X, Y, Z
  std::vector<double> waited;
  std::optional<channel::RunTimeError> error;
  std::string source_error;
};

constexpr double kT = 0.001;

Tracked track(const std::string& program, tracking::test::FakePort* port) {
  const machines::Machine& m = interp::test::machine("laser_portal");
  channel::test::ConveyorRig rig(program, m, channel::channel_config(m, kT), port);
  const channel::Channel& ch = rig.ch;
  Tracked r;
  r.status = channel::test::run_to_end(
      rig.ch,
      [&] {
        const tracking::ConveyorSync& s = *ch.conveyor_sync();
        r.line.push_back(ch.cycle().line);
        r.phase.push_back(s.phase());
        r.x.push_back({ch.axes().command[0], ch.axes().command[1], ch.axes().command[2]});
        r.offset.push_back({s.offset(0), s.offset(1), s.offset(2)});
        r.waited.push_back(s.waited());
      },
      100'000);
  r.error = ch.run_time_error();
  if (const core::Diagnostic* d = rig.src.error()) r.source_error = d->id;
  return r;
}

// laser_portal: X v_max 1000 mm/s, A 10000 mm/s^2; workspace = soft limits X [-200, 4000].
const char* const kSync =
    "%t\n"                             // 1
    "N10 G01 X0 Y0 Z0 F6000\n"         // 2
    "N20 #SYNC IN [CONV_VEL=18000]\n"  // 3: 300 mm/s
    "N30 G01 X100 Y50 F6000\n"         // 4: the catch-up
    "N40 G04 0.5\n"                    // 5: standing still in PCS1
    "N50 G01 X150 F3000\n"             // 6: 50 mm/s relative to the workpiece
    "N60 #SYNC OUT\n"                  // 7
    "N70 G00 X-100 Y0\n"               // 8: the departure from the moving state
    "N80 M30\n";                       // 9

}  // namespace

TEST_CASE("#SYNC IN: catch-up, standing still in PCS1, F relative to the workpiece, departure") {
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 200;  // the workpiece is measured 0.2 s into the run
  const Tracked r = track(kSync, &port);
  if (r.error)
    MESSAGE(r.error->id << " line " << r.error->line << " t " << r.error->t << ": "
                        << r.error->message);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  const std::size_t n = r.x.size();
  std::size_t waiting = 0, catching = 0, dwell_tracking = 0, machining = 0;
  double v_rel_max = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    CAPTURE(k);
    if (r.phase[k] == tracking::SyncPhase::waiting) {
      ++waiting;
      CHECK(r.x[k][0] == doctest::Approx(0.0));  // the path stands while waiting
    }
    if (r.phase[k] == tracking::SyncPhase::catching_up) ++catching;
    if (r.phase[k] == tracking::SyncPhase::tracking && r.line[k] == 5) {
      ++dwell_tracking;  // X follows the belt exactly: PCS1 X stays at 100
      CHECK(r.x[k][0] - r.offset[k][0] == doctest::Approx(100.0).epsilon(1e-12));
      CHECK(r.x[k][1] == doctest::Approx(50.0));
    }
    if (r.phase[k] == tracking::SyncPhase::tracking && r.line[k] == 6 &&
        r.phase[k - 1] == tracking::SyncPhase::tracking) {
      ++machining;
      const double v_rel =
          ((r.x[k][0] - r.offset[k][0]) - (r.x[k - 1][0] - r.offset[k - 1][0])) / kT;
      v_rel_max = std::max(v_rel_max, v_rel);
    }
    // Continuity everywhere (catch-up -> tracking -> leaving -> departure): X within V.
    CHECK(std::fabs(r.x[k][0] - r.x[k - 1][0]) <= 1000.0 * kT * (1 + 1e-9));
  }
  CHECK(waiting >= 150);  // #SYNC IN came early; the latch at 0.2 s
  CHECK(r.waited.back() == doctest::Approx(0.001 * static_cast<double>(waiting)).epsilon(0.02));
  CHECK(catching > 10);
  CHECK(dwell_tracking >= 490);
  CHECK(machining > 900);  // 50 mm at 50 mm/s
  CHECK(v_rel_max == doctest::Approx(50.0).epsilon(1e-6));
  // Acceleration of X bounded by A = 10000 (a few % for the position-difference estimate).
  for (std::size_t k = 2; k < n; ++k) {
    const double a = (r.x[k][0] - 2 * r.x[k - 1][0] + r.x[k - 2][0]) / (kT * kT);
    CHECK(std::fabs(a) <= 10000.0 * 1.05);
  }
  // The departure ends at its MCS target at rest.
  CHECK(r.x.back()[0] == doctest::Approx(-100.0));
  CHECK(r.x.back()[1] == doctest::Approx(0.0));
  CHECK(r.phase.back() == tracking::SyncPhase::off);
}

TEST_CASE("a belt slowing down during the catch-up: the tool still ends standing still in PCS1") {
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 1;
  port.v_change_at_ = 60;  // inside the catch-up (it starts at step 3)
  port.v_new_ = 200.0;
  const Tracked r = track(kSync, &port);
  REQUIRE_FALSE(r.error);
  bool changed_while_catching = false;
  std::size_t dwell = 0;
  for (std::size_t k = 0; k < r.x.size(); ++k) {
    if (k == 60 && r.phase[k] == tracking::SyncPhase::catching_up) changed_while_catching = true;
    if (r.phase[k] == tracking::SyncPhase::tracking && r.line[k] == 5) {
      ++dwell;
      CHECK(r.x[k][0] - r.offset[k][0] == doctest::Approx(100.0).epsilon(1e-12));
    }
  }
  CHECK(changed_while_catching);
  CHECK(dwell >= 490);
}

TEST_CASE("#SYNC IN without a conveyor world attached is NC6001 naming the scenario [conveyor]") {
  const Tracked r = track(kSync, nullptr);
  CHECK(r.status == ipo::Status::error);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC6001");
  CHECK(r.error->line == 3);
  CHECK(r.error->message.find("[conveyor]") != std::string::npos);
}

TEST_CASE("50653: a belt more than 10 % above CONV_VEL stops the channel at #SYNC IN") {
  tracking::test::FakePort port(331.0);
  port.latch_at_ = 1;
  const Tracked r = track(kSync, &port);
  REQUIRE(r.error);
  CHECK(r.error->id == "50653");
  tracking::test::FakePort ok(329.0);
  ok.latch_at_ = 1;
  CHECK_FALSE(track(kSync, &ok).error);
}

TEST_CASE("NC9052: the belt carries the tool out of the workspace in the conveying direction") {
  tracking::test::FakePort port(300.0);
  port.latch_at_ = 1;
  const Tracked r = track(
      "%t\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 F6000\nN40 G04 20\nN50 #SYNC OUT\nN60 M30\n",
      &port);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC9052");
  CHECK(r.error->line == 4);
  CHECK(r.x.back()[0] <= 4000.0);
}

TEST_CASE("NC9054: #SYNC IN whose measured value never comes ends at ncsim's wait limit") {
  tracking::test::FakePort port(300.0);  // never latches
  const core::SourceFile file("t.nc", kSync);
  const machines::Machine& m = interp::test::machine("laser_portal");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  channel::ChannelConfig cfg = channel::channel_config(m, 0.001);
  cfg.measured_value_wait_max = 0.25;
  channel::Channel ch(std::move(cfg), src);
  ch.attach_conveyor(&port);
  ipo::Status s = ipo::Status::running;
  for (int guard = 0; guard < 100'000 && s == ipo::Status::running; ++guard)
    s = ch.step();
  REQUIRE(s == ipo::Status::error);
  REQUIRE(ch.run_time_error());
  CHECK(ch.run_time_error()->id == "NC9054");
  CHECK(ch.run_time_error()->line == 3);
  CHECK(ch.run_time_error()->t == doctest::Approx(0.25).epsilon(0.02));
}
