// Ids of conveyor tracking's channel side that had no test of their own (issue 14):
// - NC6211, the belt's share of the joints under #TRAFO ON (docs/conveyor.md "Conveyor tracking
//   under #TRAFO ON", program/program_kinematics.cpp ProgramSource::reserve_belt_share): a
//   transformed G01 block in PCS1 whose belt (1.1 x CONV_VEL) alone needs more than a joint's V
//   is the program error NC6211 at that block; with drives fast enough the same block runs;
// - NC9050, no catch-up exists (tracking/catch_up, channel/channel_conveyor.cpp): an X axis slower
// than
//   the belt cannot meet the moving workpiece; the run-time error names the axis.

#include <doctest/doctest.h>

#include <optional>
#include <string>

#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/diagnostic.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;

// A pick on a belt of CONV_VEL 18000 mm/min (300 mm/s), as seed 004 §4.9.2.
const char* const kPick =
    "%t\n"                              // 1
    "N10 #KIN ID[37]\n"                 // 2
    "N20 #TRAFO ON\n"                   // 3
    "N30 G01 X-150 Y0 Z-700 F60000\n"   // 4: waiting position
    "N40 #SYNC IN [CONV_VEL=18000]\n"   // 5
    "N50 G01 X-100 Y20 Z-700 F60000\n"  // 6: the catch-up (TCP motion)
    "N60 G01 Z-800 F30000\n"            // 7: down onto the workpiece (PCS1)
    "N70 #SYNC OUT\n"                   // 8
    "N80 G01 X200 Y150 Z-750 F60000\n"  // 9
    "N90 M30\n";                        // 10

struct Outcome {
  ipo::Status status = ipo::Status::finished;
  std::optional<core::Diagnostic> source_error;
  std::optional<channel::RunTimeError> error;
};

/// Runs the rig to its end: the status, the program error, the run-time error.
Outcome outcome(channel::test::ConveyorRig& rig) {
  Outcome r;
  r.status = channel::test::run_to_end(rig.ch, {}, 100'000);
  if (const core::Diagnostic* d = rig.src.error()) r.source_error = *d;
  r.error = rig.ch.run_time_error();
  return r;
}

/// The delta picker (workspace holding its working height) with the joints Y and Z at
/// `v_joint` [deg/s] (X, the channel's first axis, keeps its 720 deg/s: 50587 compares CONV_VEL
/// with it).
Outcome run(double v_joint) {
  machines::Machine m = interp::test::machine("delta_picker");
  m.channel.conveyor->workspace.lower = Eigen::Vector3d(-600, -600, -900);
  m.channel.conveyor->workspace.upper = Eigen::Vector3d(600, 600, 0);
  for (machines::AxisParams& a : m.axes)
    if (a.name == "Y" || a.name == "Z") a.dynamics.v_max = a.dynamics.v_rapid = v_joint;
  // The belt itself crawls (10 mm/s, below CONV_VEL: no 50653) so that the catch-up runs on
  // the slow joints; the reserve is for the belt CONV_VEL allows (1.1 x 300 mm/s).
  tracking::test::FakePort port(10.0);
  port.latch_at_ = 100;
  channel::test::ConveyorRig rig(kPick, m, channel::channel_config(m, kT), &port);
  return outcome(rig);
}

}  // namespace

TEST_CASE("NC6211: a PCS1 block whose belt share alone needs more than a joint's V") {
  const Outcome slow = run(30.0);
  if (slow.error) MESSAGE(slow.error->id << ": " << slow.error->message);
  REQUIRE(slow.source_error);
  MESSAGE(slow.source_error->id << ": " << slow.source_error->message);
  CHECK(slow.source_error->id == "NC6211");
  CHECK(slow.source_error->loc.line == 7);
  CHECK(slow.source_error->message.find("1.1 x CONV_VEL (330 mm/s)") != std::string::npos);
  CHECK(slow.source_error->message.find("P-AXIS-00212") != std::string::npos);
}

TEST_CASE("NC6211 not raised: the same block on drives that leave feed for the path") {
  const Outcome fast = run(720.0);
  if (fast.source_error) MESSAGE(fast.source_error->id << ": " << fast.source_error->message);
  if (fast.error) MESSAGE(fast.error->id << ": " << fast.error->message);
  CHECK(fast.status == ipo::Status::finished);
  CHECK_FALSE(fast.source_error);
}

namespace {

const char* const kCatchUp =
    "%t\n"                            // 1
    "N20 #SYNC IN [CONV_VEL=6000]\n"  // 2
    "N30 G01 X0 Y0 F6000\n"           // 3: the catch-up
    "N40 G01 X-100 F6000\n"           // 4
    "N50 #SYNC OUT\n"                 // 5
    "N60 M30\n";                      // 6

/// The laser portal with X at `v_x` [mm/s] and a belt at 108 mm/s (CONV_VEL 100 mm/s: within
/// 50653's 10 %; 50587 compares CONV_VEL, not the belt, with X's V).
Outcome catch_up(double v_x) {
  machines::Machine m = interp::test::machine("laser_portal");
  for (machines::AxisParams& a : m.axes)
    if (a.name == "X") a.dynamics.v_max = v_x;
  tracking::test::FakePort port(108.0);
  port.latch_at_ = 1;
  channel::test::ConveyorRig rig(kCatchUp, m, channel::channel_config(m, kT), &port);
  return outcome(rig);
}

}  // namespace

TEST_CASE("NC9050: a catch-up the X axis cannot run (the belt above its V) names the axis") {
  const Outcome slow = catch_up(105.0);  // the belt alone is faster than X
  if (slow.source_error) MESSAGE(slow.source_error->id << ": " << slow.source_error->message);
  REQUIRE(slow.status == ipo::Status::error);
  REQUIRE(slow.error);
  MESSAGE(slow.error->id << ": " << slow.error->message);
  CHECK(slow.error->id == "NC9050");
  CHECK(slow.error->line == 3);
  CHECK(slow.error->message.find("the catch-up after #SYNC IN of axis X") != std::string::npos);
  const Outcome fast = catch_up(1000.0);
  if (fast.error) MESSAGE(fast.error->id << ": " << fast.error->message);
  CHECK(fast.status == ipo::Status::finished);
}
