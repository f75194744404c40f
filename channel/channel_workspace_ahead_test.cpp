// The workspace hold's prediction across block ends (seed 004 §2.1.3, §4.4.2; docs/conveyor.md
// "Workspace: the hold methods", "Across block ends"): a -X contour split into short blocks
// holds the line as one block does, for both methods and factors 950 and 1000; an arc after a
// short line; the audit clean; never beyond the hold line + P-CHAN-00367 (NC9080).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "interp/test_support.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;
constexpr double kBelt = 100.0;  // [mm/s], CONV_VEL 6000 mm/min

struct Run {
  ipo::Status status = ipo::Status::finished;
  std::optional<channel::RunTimeError> error;
  double min_x = 1e9;      // the TCP's minimum MCS X while the -X run is active [mm]
  long run_end = -1;       // first cycle of the block after the run
  double v_max_run = 0.0;  // highest path velocity in the run [mm/s]
  bool audit_ok = false;
  std::string audit_first;
};

// `first`..`last`: the source lines of the -X run; `after` the line that follows it.
Run run(const std::string& program, bool optimised, double factor, std::uint32_t first,
        std::uint32_t last, std::uint32_t after) {
  machines::Machine m = interp::test::machine("laser_portal");
  m.channel.conveyor->optimised_monitoring = optimised;
  m.channel.conveyor->hold_limit_vel_factor = factor;
  tracking::test::FakePort port(kBelt);
  port.latch_at_ = 1;
  channel::ChannelConfig cfg = channel::channel_config(m, kT);
  audit::Audit audit(cfg.path.axes, kT, cfg.path.start);
  channel::test::ConveyorRig rig(program, m, cfg, &port, &audit);
  audit.set_setpoints(&rig.ch.setpoints());
  const channel::Channel& ch = rig.ch;
  Run r;
  r.status = channel::test::run_to_end(
      rig.ch,
      [&] {
        const std::uint32_t line = ch.cycle().line;
        if (line >= first && line <= last) {
          r.min_x = std::min(r.min_x, ch.axes().command[0]);
          r.v_max_run = std::max(r.v_max_run, ch.cycle().path.v);
        }
        if (line == after && r.run_end < 0) r.run_end = static_cast<long>(ch.cycle().index);
      },
      60'000);
  r.error = ch.run_time_error();
  r.audit_ok = audit.verdict().ok();
  if (!audit.verdict().violations.empty()) {
    const audit::Violation& v = audit.verdict().violations.front();
    r.audit_first =
        std::to_string(v.t) + " " + std::to_string(v.value) + " > " + std::to_string(v.limit);
  }
  return r;
}

const char* const kOne =
    "%t\n"                            // 1
    "N20 #SYNC IN [CONV_VEL=6000]\n"  // 2
    "N30 G01 X0 Y0 F6000\n"           // 3: the catch-up
    "N40 G01 X-600 F12000\n"          // 4: into the line
    "N50 G01 Y100\n"                  // 5
    "N60 #SYNC OUT\n"                 // 6
    "N70 G00 X0 Y0\n"                 // 7
    "N80 M30\n";                      // 8

// The same line in 5 blocks of one feed (the planner chains them into one entry).
const char* const kFive =
    "%t\n"                            // 1
    "N20 #SYNC IN [CONV_VEL=6000]\n"  // 2
    "N30 G01 X0 Y0 F6000\n"           // 3
    "N40 G01 X-120 F12000\n"          // 4
    "N41 X-240\n"                     // 5
    "N42 X-360\n"                     // 6
    "N43 X-480\n"                     // 7
    "N44 X-600\n"                     // 8
    "N50 G01 Y100\n"                  // 9
    "N60 #SYNC OUT\n"                 // 10
    "N70 G00 X0 Y0\n"                 // 11
    "N80 M30\n";                      // 12

// The same 5 blocks, each its own look-ahead entry (feeds 1 mm/min apart: different caps).
const char* const kFiveEntries =
    "%t\n"                            // 1
    "N20 #SYNC IN [CONV_VEL=6000]\n"  // 2
    "N30 G01 X0 Y0 F6000\n"           // 3
    "N40 G01 X-120 F12000\n"          // 4
    "N41 X-240 F12001\n"              // 5
    "N42 X-360 F12000\n"              // 6
    "N43 X-480 F12001\n"              // 7
    "N44 X-600 F12000\n"              // 8
    "N50 G01 Y100\n"                  // 9
    "N60 #SYNC OUT\n"                 // 10
    "N70 G00 X0 Y0\n"                 // 11
    "N80 M30\n";                      // 12

void report(const Run& r) {
  if (r.error) MESSAGE(r.error->id << " line " << r.error->line << ": " << r.error->message);
  if (!r.audit_ok) MESSAGE("audit: " << r.audit_first);
}

}  // namespace

TEST_CASE("a -X line in 5 blocks holds the line as the one block does (both methods, 950, 1000)") {
  for (const bool optimised : {false, true})
    for (const double factor : {1.0, 0.95}) {
      CAPTURE(optimised);
      CAPTURE(factor);
      const Run one = run(kOne, optimised, factor, 4, 4, 5);
      report(one);
      REQUIRE(one.status == ipo::Status::finished);
      // One look-ahead entry of 5 blocks, and 5 entries of one block each.
      for (const char* program : {kFive, kFiveEntries}) {
        const Run five = run(program, optimised, factor, 4, 8, 9);
        report(five);
        MESSAGE("one: min X " << one.min_x << " mm, end " << one.run_end << "; five: min X "
                              << five.min_x << " mm, end " << five.run_end);
        REQUIRE(five.status == ipo::Status::finished);  // no NC9080
        CHECK(five.audit_ok);
        CHECK(std::fabs(five.min_x - one.min_x) <= 0.5);
        CHECK(std::abs(five.run_end - one.run_end) <= 1);
        CHECK(five.min_x >= -190.0 - 1e-9);  // never beyond the hold line
      }
      CHECK(one.audit_ok);
    }
}

namespace {

// A Y block right before the -X run, at 500 mm/s: the simple method enters the run capped.
const char* const kYThenRun =
    "%t\n"                            // 1
    "N20 #SYNC IN [CONV_VEL=6000]\n"  // 2
    "N30 G01 X-80 Y0 F6000\n"         // 3: the catch-up, 110 mm inside the line
    "N40 G01 Y300 F30000\n"           // 4: across the belt
    "N41 G01 X-200 Y300.5\n"          // 5: against it, almost along -X
    "N42 X-600 Y301\n"                // 6
    "N50 G01 Y400\n"                  // 7
    "N60 #SYNC OUT\n"                 // 8
    "N70 G00 X0 Y0\n"                 // 9
    "N80 M30\n";                      // 10

}  // namespace

TEST_CASE("simple method: the run after a Y block is entered at factor x v_conv") {
  for (const double factor : {1.0, 0.95}) {
    CAPTURE(factor);
    const Run r = run(kYThenRun, false, factor, 5, 6, 7);
    report(r);
    REQUIRE(r.status == ipo::Status::finished);
    CHECK(r.audit_ok);
    CHECK(r.v_max_run <= factor * kBelt + 1e-6);  // capped over the whole run
    CHECK(r.min_x >= -190.0);
  }
}

namespace {

// A short -X line, then a quarter arc into the line at 500 mm/s (X -50 .. -350).
const char* const kLineArc =
    "%t\n"                            // 1
    "N20 #SYNC IN [CONV_VEL=6000]\n"  // 2
    "N30 G01 X0 Y0 F6000\n"           // 3
    "N40 G01 X-50 F30000\n"           // 4: short line
    "N50 G02 X-350 Y300 I0 J300\n"    // 5: quarter arc, -X turning to +Y
    "N60 G01 Y400\n"                  // 6
    "N70 #SYNC OUT\n"                 // 7
    "N80 G00 X0 Y0\n"                 // 8
    "N90 M30\n";                      // 9

}  // namespace

TEST_CASE("an arc after a short line: both methods keep the line, the audit clean") {
  for (const bool optimised : {false, true})
    for (const double factor : {1.0, 0.95}) {
      CAPTURE(optimised);
      CAPTURE(factor);
      const Run r = run(kLineArc, optimised, factor, 4, 5, 6);
      report(r);
      MESSAGE("min X " << r.min_x << " mm, v max " << r.v_max_run);
      REQUIRE(r.status == ipo::Status::finished);
      CHECK(r.audit_ok);
      CHECK(r.min_x >= -190.0 - 1e-9);
      if (optimised) CHECK(r.min_x <= -185.0);  // runs at its feed up to near the line
    }
}
