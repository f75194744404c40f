// #SYNC IN FEED_CONT > 0 and FEED_CONT_AUTO (issue 14, sync-feed; docs/conveyor.md S-1, S-7):
// the catch-up meets the workpiece at a relative velocity "reduced as required" (004 l.284) to
// what the first PCS1 block allows, and the path takes over at that velocity without a stop.

#include "tracking/sync_entry.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "interp/test_support.hpp"
#include "jerk/jerk.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;
constexpr double kBelt = 300.0;  // [mm/s]

struct Run {
  ipo::Status status = ipo::Status::finished;
  std::vector<tracking::SyncPhase> phase;
  std::vector<std::array<double, 3>> x;  // command X, Y, Z (MCS)
  std::vector<double> v_relative;        // ConveyorSync::v_relative()
  std::optional<channel::RunTimeError> error;
  audit::Verdict verdict;
  std::size_t handover = 0;  // the first tracking cycle after the catch-up
};

// laser_portal (X, Y: V 1000 mm/s, A 10000 mm/s^2), the belt at 300 mm/s, audited on the
// setpoints as `ncsim time --audit` does.
Run run(const std::string& program,
        const machines::Machine& m = interp::test::machine("laser_portal"), double belt = kBelt) {
  tracking::test::FakePort port(belt);
  port.latch_at_ = 1;
  channel::test::AuditedConveyorRig audited(program, m, channel::channel_config(m, kT), &port);
  const channel::Channel& ch = audited.rig.ch;
  Run r;
  r.status = channel::test::run_to_end(
      audited.rig.ch,
      [&] {
        const tracking::ConveyorSync& s = *ch.conveyor_sync();
        if (r.handover == 0 && !r.phase.empty() &&
            r.phase.back() == tracking::SyncPhase::catching_up &&
            s.phase() == tracking::SyncPhase::tracking)
          r.handover = r.phase.size();
        r.phase.push_back(s.phase());
        r.x.push_back({ch.axes().command[0], ch.axes().command[1], ch.axes().command[2]});
        r.v_relative.push_back(s.v_relative());
      },
      100'000);
  r.error = ch.run_time_error();
  r.verdict = audited.audit.verdict();
  if (r.error)
    MESSAGE(r.error->id << " line " << r.error->line << " t " << r.error->t << ": "
                        << r.error->message);
  channel::test::message_violations(r.verdict);
  return r;
}

// The tool's velocity relative to the workpiece in cycle k (PCS1: the belt moves along +X).
std::array<double, 2> relative(const Run& r, std::size_t k) {
  return {(r.x[k][0] - r.x[k - 1][0]) / kT - kBelt, (r.x[k][1] - r.x[k - 1][1]) / kT};
}

std::string nc_program(const char* sync_in, const char* contour) {
  return std::string("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000 ") + sync_in +
         "]\nN30 G01 X100 Y0 F6000\n" + contour + "N80 G04 0.05\nN90 #SYNC OUT\nN100 M30\n";
}

// The VELOJUMP velocity of a 90 degree corner between X and Y (000 l.108).
double velojump_90(const machines::Machine& m) {
  const channel::ChannelConfig cfg = channel::channel_config(m, kT);
  double v = 1e300;
  for (std::size_t i = 0; i < 2; ++i) {
    const planner::AxisLimits& l = cfg.path.axes[i];
    v = std::min(v, l.c0 * std::min(l.a_max, l.d_max) * kT);
  }
  return v;
}

}  // namespace

TEST_CASE("FEED_CONT=600 into a straight continuation: the path takes over at 10 mm/s, no step") {
  const Run r = run(nc_program("FEED_CONT=600", "N40 G01 X200 F600\n"));
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE(r.handover > 2);
  CHECK(r.v_relative[r.handover] == doctest::Approx(10.0));
  // The relative velocity stays at 10 mm/s across the hand-over (the catch-up ends there at
  // acceleration 0, the block starts there at F): no dip towards 0.
  for (std::size_t k = r.handover; k < r.handover + 50; ++k) {
    CAPTURE(k);
    const auto v = relative(r, k);
    CHECK(v[0] == doctest::Approx(10.0).epsilon(1e-3));
    CHECK(std::fabs(v[1]) < 1e-9);
  }
  // Before it the catch-up slows down to 10 mm/s relative within its A (its last cycle's mean
  // is above 10 mm/s), and never below.
  for (std::size_t k = r.handover - 20; k < r.handover; ++k) {
    CAPTURE(k);
    CHECK(relative(r, k)[0] >= 10.0);
    CHECK(std::fabs(relative(r, k + 1)[0] - relative(r, k)[0]) <= 10000.0 * kT);
  }
  CHECK(r.verdict.violation_count == 0);
}

TEST_CASE("FEED_CONT=6000 into a 90 degree corner is reduced to the VELOJUMP velocity") {
  const machines::Machine& m = interp::test::machine("laser_portal");
  const double v_jump = velojump_90(m);
  REQUIRE(v_jump < 100.0);  // the reduction shows
  const Run r = run(nc_program("FEED_CONT=6000", "N40 G01 Y100 F6000\n"), m);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE(r.handover > 2);
  CHECK(r.v_relative[r.handover] == doctest::Approx(v_jump));
  // The catch-up arrives along +X at v_jump, the block leaves along +Y: each axis steps by at
  // most v_jump (the planner's own corner rule), and the audit agrees.
  const auto before = relative(r, r.handover - 1);
  CHECK(before[0] == doctest::Approx(v_jump).epsilon(0.02));
  const auto after = relative(r, r.handover + 1);
  CHECK(std::fabs(after[0]) < 1e-6);
  CHECK(after[1] == doctest::Approx(v_jump).epsilon(0.02));
  CHECK(r.verdict.violation_count == 0);
}

TEST_CASE("FEED_CONT=600 into a very short block is reduced to what its braking allows") {
  const machines::Machine& m = interp::test::machine("laser_portal");
  const Run r = run(nc_program("FEED_CONT=600", "N40 G01 X100.01 F600\n"), m);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE(r.handover > 2);
  // The block of 0.01 mm ends in a stop (the dwell): its entry cap is the velocity from which
  // the path brakes to 0 within 0.01 mm (the look-ahead's backward pass).
  const channel::ChannelConfig cfg = channel::channel_config(m, kT);
  const planner::AxisLimits& x = cfg.path.axes[0];
  const double v_brake = jerk::entry_velocity_for_exit(0.0, 0.01, x.d_max, x.j_max);
  REQUIRE(v_brake < 10.0);
  CHECK(r.v_relative[r.handover] == doctest::Approx(v_brake).epsilon(1e-6));
  CHECK(r.verdict.violation_count == 0);
}

TEST_CASE("FEED_CONT_AUTO: the largest relative velocity the first block takes (S-7)") {
  const machines::Machine& m = interp::test::machine("laser_portal");
  SUBCASE("straight on at the block's feed") {
    const Run r = run(nc_program("FEED_CONT_AUTO", "N40 G01 X400 F6000\n"), m);
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE(r.handover > 2);
    CHECK(r.v_relative[r.handover] == doctest::Approx(100.0));
    for (std::size_t k = r.handover; k < r.handover + 20; ++k)
      CHECK(relative(r, k)[0] == doctest::Approx(100.0).epsilon(1e-3));
    CHECK(r.verdict.violation_count == 0);
  }
  SUBCASE("a fast block: its entry cap is the PCS1 velocity split's (S-5)") {
    // F = 1000 mm/s along +X: X keeps 1000 - 1.1 x 300 = 670 mm/s relative, so the catch-up
    // meets at 670 and X runs at 970 mm/s in MCS, inside its V.
    const Run r = run(nc_program("FEED_CONT_AUTO", "N40 G01 X800 F60000\n"), m);
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE(r.handover > 2);
    CHECK(r.v_relative[r.handover] == doctest::Approx(670.0));
    CHECK(relative(r, r.handover + 1)[0] == doctest::Approx(670.0).epsilon(1e-3));
    CHECK(r.verdict.violation_count == 0);
  }
  SUBCASE("into a corner at the VELOJUMP velocity") {
    const Run r = run(nc_program("FEED_CONT_AUTO", "N40 G01 Y100 F6000\n"), m);
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE(r.handover > 2);
    CHECK(r.v_relative[r.handover] == doctest::Approx(velojump_90(m)));
    CHECK(r.verdict.violation_count == 0);
  }
  SUBCASE("nothing to continue into (a dwell follows): at rest, as FEED_CONT=0") {
    const Run r = run(nc_program("FEED_CONT_AUTO", ""), m);
    REQUIRE(r.status == ipo::Status::finished);
    CHECK(r.handover > 2);
    CHECK(r.v_relative[r.handover] == 0.0);
    CHECK(r.verdict.violation_count == 0);
  }
}

TEST_CASE("sync_entry: the smallest of FEED_CONT, the link and the entry cap, and which") {
  planner::AxisLimits l;
  l.v_max = 1000.0;
  l.v_reference = 1000.0;
  l.a_max = l.d_max = 10000.0;
  l.j_max = 1e6;
  const std::array<planner::AxisLimits, 3> axes{l, l, l};
  planner::PreparedSegment seg;  // a line along +Y
  seg.path = planner::Chain(
      planner::Segment::line(3, 0b111, planner::AxisVec{}, planner::AxisVec{0.0, 100.0, 0.0}), 0);
  const planner::AxisVec along_x{1.0, 0.0, 0.0};
  const planner::AxisVec along_y{0.0, 1.0, 0.0};
  tracking::SyncEntry e = tracking::sync_entry(50.0, along_y, &seg, 100.0, axes, kT);
  CHECK(e.v == 50.0);
  CHECK(e.limit == tracking::EntryLimit::asked);
  e = tracking::sync_entry(50.0, along_x, &seg, 100.0, axes, kT);
  CHECK(e.v == doctest::Approx(10.0));  // VELOJUMP 1 x 10000 x 0.001 over a step of 1
  CHECK(e.limit == tracking::EntryLimit::corner);
  e = tracking::sync_entry(1e300, along_y, &seg, 30.0, axes, kT);
  CHECK(e.v == 30.0);
  CHECK(e.limit == tracking::EntryLimit::entry_cap);
  e = tracking::sync_entry(50.0, along_y, nullptr, 100.0, axes, kT);
  CHECK(e.v == 0.0);
  CHECK(e.limit == tracking::EntryLimit::nothing);
  // A reversal: the step is 2 per unit velocity on Y.
  const planner::AxisVec minus_y{0.0, -1.0, 0.0};
  CHECK(tracking::sync_entry(50.0, minus_y, &seg, 100.0, axes, kT).v == doctest::Approx(5.0));
}

// Under #TRAFO ON it runs (channel/trafo_feed_test.cpp).
TEST_CASE("FEED_CONT > 0 on a static unit is NC9060 (004 l.438)") {
  SUBCASE("static processing unit (P-CHAN-00364 x_virtual): NC9060 at the #SYNC IN line") {
    for (const char* feed : {"FEED_CONT=600", "FEED_CONT_AUTO"}) {
      CAPTURE(feed);
      const Run r =
          run(std::string("%t\nN20 #SYNC IN [CONV_VEL=18000 ") + feed + "]\nN30 G01 X10\nN40 M30\n",
              interp::test::machine("static_saw"));
      REQUIRE(r.error);
      CHECK(r.error->id == "NC9060");
      CHECK(r.error->line == 2);
      CHECK(r.error->message.find("x_virtual") != std::string::npos);
      CHECK(r.error->message.find("l.438") != std::string::npos);
    }
  }
  SUBCASE("static processing unit: FEED_CONT=0 is FEED_CONT absent (no error at #SYNC IN)") {
    const Run r = run("%t\nN20 #SYNC IN [CONV_VEL=18000 FEED_CONT=0]\nN30 G01 X10\nN40 M30\n",
                      interp::test::machine("static_saw"));
    if (r.error) CHECK(r.error->id != "NC9060");
  }
}

TEST_CASE(
    "a FEED_CONT no axis can meet is reduced to the largest the catch-up plans; the "
    "moving hand-over is due in the cycle of the meeting") {
  tracking::test::FakePort port(kBelt);
  const axes::Dynamics d{1000.0, 5000.0, 5000.0, 50000.0};
  const std::vector<tracking::SyncAxis> ax{
      tracking::SyncAxis{"X", 0, d}, tracking::SyncAxis{"Y", 1, d}, tracking::SyncAxis{"Z", 2, d}};
  tracking::ConveyorSync sync(machines::ConveyorSyncChannel{}, ax, kT);
  sync.attach(&port);
  interp::SyncIn in;
  in.conv_vel = kBelt;
  in.feed_cont_auto = true;
  REQUIRE_FALSE(sync.sync_in(in));
  CHECK(std::isinf(sync.feed_cont_wanted()));
  port.latches_.push_back(0.0);
  std::uint64_t k = 0;
  REQUIRE_FALSE(sync.step(static_cast<double>(++k) * kT));
  REQUIRE(sync.phase() == tracking::SyncPhase::latched);
  // Along +X: the belt's 300 mm/s and 800 mm/s relative would need X at 1100 > V 1000.
  const std::array<axes::MotionState, 3> start{};
  const std::array<double, 3> target{200.0, 0.0, 0.0};
  const planner::AxisVec u = sync.catch_up_direction(start, target);
  CHECK(u[0] == doctest::Approx(1.0));
  REQUIRE(sync.start_catch_up(start, target, 800.0) == axes::Result::ok);
  CHECK(sync.v_relative() < 700.0 + 1e-6);
  CHECK(sync.v_relative() > 600.0);  // the bisection's largest that plans, below V - belt
  const double t_meet = sync.catch_up().duration();
  // The hand-over is announced for the cycle that contains the meeting, with its lag in it.
  while (!sync.handover_lag()) {
    REQUIRE(sync.phase() == tracking::SyncPhase::catching_up);
    REQUIRE_FALSE(sync.step(static_cast<double>(++k) * kT));
    REQUIRE(static_cast<double>(k) * kT < 10.0);
  }
  const double lag = *sync.handover_lag();
  CHECK(lag >= 0.0);
  CHECK(lag < kT);
  REQUIRE_FALSE(sync.step(static_cast<double>(++k) * kT));
  CHECK(sync.phase() == tracking::SyncPhase::tracking);
  CHECK(sync.synchronised());
  CHECK(t_meet == doctest::Approx(static_cast<double>(k - 2) * kT + lag).epsilon(1e-12));
}

TEST_CASE("seeded: any FEED_CONT, direction, first block and belt: audit clean, f as reduced") {
  // ncsim's own generator (no library distribution: the same numbers everywhere).
  std::uint64_t state = 0x5EEDF00Du;
  auto uniform = [&](double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  const machines::Machine& m = interp::test::machine("laser_portal");
  for (int n = 0; n < 12; ++n) {
    const double belt = uniform(50.0, 300.0);
    const double f = uniform(0.0, 12000.0);  // [mm/min]
    const bool automatic = uniform(0.0, 1.0) < 0.25;
    const double angle = uniform(-3.14159, 3.14159);
    const double length = uniform(0.0, 1.0) < 0.3 ? uniform(0.005, 0.5) : uniform(5.0, 60.0);
    const double feed = uniform(600.0, 12000.0);  // [mm/min]
    char text[512];
    std::snprintf(
        text, sizeof text,
        "%%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=%.6f %s]\n"
        "N30 G01 X%.4f Y%.4f F6000\nN40 G91 G01 X%.6f Y%.6f F%.3f\nN50 G90 G04 0.05\n"
        "N60 #SYNC OUT\nN70 M30\n",
        belt * 60.0,
        automatic ? "FEED_CONT_AUTO" : (std::string("FEED_CONT=") + std::to_string(f)).c_str(),
        uniform(60.0, 150.0), uniform(0.0, 80.0), length * std::cos(angle),
        length * std::sin(angle), feed);
    CAPTURE(text);
    const Run r = run(text, m, belt);
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE(r.handover > 2);
    const double v = r.v_relative[r.handover];
    CHECK(v >= 0.0);
    CHECK(v <= (automatic ? feed / 60.0 : std::min(f, feed) / 60.0) * (1 + 1e-9));
    CHECK(r.verdict.violation_count == 0);
  }
}
