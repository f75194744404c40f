// #SYNC IN FEED_CONT > 0 and FEED_CONT_AUTO under #TRAFO ON (issue 14, trafo-feed;
// docs/conveyor.md S-1 "Under #TRAFO ON"): the catch-up is a TCP motion (004 l.609) with the
// TCP dynamics derived from the joints (tracking/trafo_sync); it meets the workpiece at the
// relative velocity S-1's rule leaves (FEED_CONT, the link to the first PCS1 block, that block's
// entry cap), and the path takes over at that velocity without a stop. On the delta picker.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "channel/trafo_test_support.hpp"
#include "interp/test_support.hpp"
#include "program/trafo.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;
constexpr double kBelt = 100.0;  // [mm/s] along +X (CONV_VEL 6000 mm/min)

using channel::test::picker;

struct Run {
  ipo::Status status = ipo::Status::finished;
  std::vector<tracking::SyncPhase> phase;
  std::vector<std::array<double, 3>> tcp;  // FK of the joint commands (MCS)
  std::vector<double> v_relative;          // ConveyorSync::v_relative()
  std::vector<double> t;                   // the cycle's time [s]
  std::optional<channel::RunTimeError> error;
  std::optional<channel::RunTimeError> warning;  // NC6210
  audit::Verdict verdict;
  std::size_t handover = 0;  // the first tracking cycle after the catch-up
};

Run run(const std::string& program, const machines::Machine& m = picker()) {
  tracking::test::FakePort port(kBelt);
  port.latch_at_ = 100;
  channel::ChannelConfig cfg = channel::channel_config(m, kT);
  REQUIRE(cfg.path.joints);
  const auto trafo = program::machine_trafo(m, cfg.path);
  REQUIRE(trafo);
  audit::Audit audit(cfg.path.axes, kT, cfg.path.start);
  audit.set_joint_limits(cfg.path.joints->joints, cfg.path.start, true);
  channel::test::ConveyorRig rig(program, m, std::move(cfg), &port, &audit);
  const channel::Channel& ch = rig.ch;
  Run r;
  r.status = channel::test::run_to_end(
      rig.ch,
      [&] {
        if (ch.transformed()) audit.on_joints(ch.cycle(), ch.joints());
        const tracking::ConveyorSync& s = *ch.conveyor_sync();
        if (r.handover == 0 && !r.phase.empty() &&
            r.phase.back() == tracking::SyncPhase::catching_up &&
            s.phase() == tracking::SyncPhase::tracking)
          r.handover = r.phase.size();
        r.phase.push_back(s.phase());
        const auto& q = ch.axes().command;
        const auto p = trafo->kinematics->forward(Eigen::Vector3d(q[0], q[1], q[2]));
        REQUIRE(p.ok());
        r.tcp.push_back({p.value[0], p.value[1], p.value[2]});
        r.v_relative.push_back(s.v_relative());
        r.t.push_back(ch.cycle().t);
      },
      100'000);
  r.error = ch.run_time_error();
  r.warning = ch.trafo_warning();
  r.verdict = audit.verdict();
  if (r.error)
    MESSAGE(r.error->id << " line " << r.error->line << " t " << r.error->t << ": "
                        << r.error->message);
  if (r.warning) MESSAGE("warning " << r.warning->id << ": " << r.warning->message);
  for (const audit::Violation& v : r.verdict.violations)
    MESSAGE("audit: axis " << int(v.axis) << " t " << v.t << " value " << v.value << " limit "
                           << v.limit);
  return r;
}

// The TCP's velocity relative to the workpiece in cycle k (X, Y) [mm/s].
std::array<double, 2> relative(const Run& r, std::size_t k) {
  return {(r.tcp[k][0] - r.tcp[k - 1][0]) / kT - kBelt, (r.tcp[k][1] - r.tcp[k - 1][1]) / kT};
}

// Waiting at X-150, the catch-up along +X to X-100 (PCS1), then `contour`.
std::string nc_program(const char* sync_in, const char* contour) {
  return std::string(
             "%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-150 Y0 Z-700 F60000\n"
             "N40 #SYNC IN [CONV_VEL=6000 ") +
         sync_in + "]\nN50 G01 X-100 Y0 Z-700 F60000\n" + contour +
         "N80 G04 0.05\nN90 #SYNC OUT\nN100 G01 X0 Y0 Z-700 F60000\nN110 M30\n";
}

// The path's VELOJUMP velocity of a 90 degree corner between X and Y (000 l.108).
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

TEST_CASE("#TRAFO ON, FEED_CONT=600 straight on: the TCP meets the workpiece at 10 mm/s") {
  const Run r = run(nc_program("FEED_CONT=600", "N60 G01 X-50 F600\n"));
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  REQUIRE(r.handover > 2);
  CHECK(r.v_relative[r.handover] == doctest::Approx(10.0));
  // The relative velocity stays at 10 mm/s across the hand-over: no dip towards 0 (the
  // hand-over cycle itself still holds the catch-up's last, slightly faster, part).
  CHECK(relative(r, r.handover)[0] >= 10.0);
  CHECK(relative(r, r.handover)[0] <= 10.2);
  for (std::size_t k = r.handover + 1; k < r.handover + 50; ++k) {
    CAPTURE(k);
    const auto v = relative(r, k);
    CHECK(v[0] == doctest::Approx(10.0).epsilon(1e-3));
    CHECK(std::fabs(v[1]) < 1e-6);
  }
  for (std::size_t k = r.handover - 20; k < r.handover; ++k) {
    CAPTURE(k);
    CHECK(relative(r, k)[0] >= 10.0 - 1e-6);
  }
  CHECK_FALSE(r.warning);
  CHECK(r.verdict.violation_count == 0);
}

TEST_CASE("#TRAFO ON, FEED_CONT=6000 into a 90 degree corner: the path's VELOJUMP velocity") {
  const machines::Machine m = picker();
  const double v_jump = velojump_90(m);
  REQUIRE(v_jump < 100.0);  // the reduction shows
  const Run r = run(nc_program("FEED_CONT=6000", "N60 G01 Y20 F6000\n"), m);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  REQUIRE(r.handover > 2);
  CHECK(r.v_relative[r.handover] == doctest::Approx(v_jump));
  const auto before = relative(r, r.handover - 1);
  // The cycle before still ends the catch-up's jerk phase towards the meeting velocity.
  CHECK(before[0] == doctest::Approx(v_jump).epsilon(0.05));
  // After it the TCP leaves along +Y from v_jump, accelerating towards F within Y's A.
  const auto after = relative(r, r.handover + 1);
  CHECK(std::fabs(after[0]) < 1e-3);
  const double a_y = channel::channel_config(m, kT).path.axes[1].a_max;
  CHECK(after[1] >= v_jump * 0.98);
  CHECK(after[1] <= v_jump + 2.0 * a_y * kT);
  CHECK_FALSE(r.warning);
  CHECK(r.verdict.violation_count == 0);
}

TEST_CASE("#TRAFO ON, FEED_CONT=600 into a very short block: what its braking allows") {
  const machines::Machine m = picker();
  const Run r = run(nc_program("FEED_CONT=600", "N60 G01 X-99.99 F600\n"), m);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  REQUIRE(r.handover > 2);
  // The block of 0.01 mm ends in a stop (the dwell): FEED_CONT's 10 mm/s is lowered to the
  // look-ahead's entry cap, the velocity from which the path brakes to 0 within 0.01 mm with
  // the TCP's limits under the transform (the planner's joint-derived ones).
  const double v = r.v_relative[r.handover];
  CHECK(v > 1.0);
  CHECK(v < 10.0 - 1.0);
  // Over the block the TCP covers 0.01 mm relative to the workpiece and then stands on it.
  double s = 0.0;
  std::size_t k = r.handover;
  for (; k < r.tcp.size() && r.phase[k] == tracking::SyncPhase::tracking; ++k) {
    const double dv = relative(r, k)[0];
    s += dv * kT;
    if (std::fabs(dv) < 1e-9 && s > 0.005) break;
  }
  CHECK(s == doctest::Approx(0.01).epsilon(0.05));
  CHECK(r.verdict.violation_count == 0);
}

TEST_CASE("#TRAFO ON, FEED_CONT_AUTO: the first block's feed, and at rest before a dwell") {
  SUBCASE("straight on at the block's feed") {
    const Run r = run(nc_program("FEED_CONT_AUTO", "N60 G01 X0 F3000\n"));
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE_FALSE(r.error);
    REQUIRE(r.handover > 2);
    CHECK(r.v_relative[r.handover] == doctest::Approx(50.0));
    // The hand-over cycle itself still holds the catch-up's last, slightly faster, part.
    CHECK(relative(r, r.handover)[0] == doctest::Approx(50.0).epsilon(5e-3));
    for (std::size_t k = r.handover + 1; k < r.handover + 20; ++k)
      CHECK(relative(r, k)[0] == doctest::Approx(50.0).epsilon(1e-3));
    CHECK(r.verdict.violation_count == 0);
  }
  SUBCASE("nothing to continue into (a dwell follows): at rest, as FEED_CONT=0") {
    const Run r = run(nc_program("FEED_CONT_AUTO", ""));
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE_FALSE(r.error);
    CHECK(r.handover > 2);
    CHECK(r.v_relative[r.handover] == 0.0);
    CHECK(r.verdict.violation_count == 0);
  }
  SUBCASE("the pick of the bundled test: down in Z after the catch-up") {
    const Run r =
        run("%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-150 Y0 Z-700 F60000\n"
            "N40 #SYNC IN [CONV_VEL=6000 FEED_CONT_AUTO]\nN50 G01 X-100 Y20 Z-700 F60000\n"
            "N60 G01 Z-800 F30000\nN70 G04 0.1\nN80 #SYNC OUT\nN90 M30\n");
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE_FALSE(r.error);
    REQUIRE(r.handover > 2);
    // The catch-up comes along X/Y, the block goes down Z: a 90 degree corner.
    CHECK(r.v_relative[r.handover] > 0.0);
    CHECK(r.v_relative[r.handover] <= velojump_90(picker()) * (1 + 1e-9) + 1e-9);
    CHECK(r.verdict.violation_count == 0);
  }
}

TEST_CASE(
    "#TRAFO ON, seeded: any FEED_CONT and first block: runs through, f as reduced, joints "
    "inside") {
  // ncsim's own generator (no library distribution: the same numbers everywhere).
  std::uint64_t state = 0x7AF0FEEDu;
  auto uniform = [&](double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  double jerk = 0.0;  // the largest joint |j| over its J
  for (int n = 0; n < 6; ++n) {
    const double f = uniform(0.0, 12000.0);  // [mm/min]
    const bool automatic = uniform(0.0, 1.0) < 0.25;
    const double angle = uniform(-3.14159, 3.14159);
    const double length = uniform(0.0, 1.0) < 0.3 ? uniform(0.005, 0.5) : uniform(5.0, 40.0);
    const double feed = uniform(600.0, 12000.0);  // [mm/min]
    char text[512];
    std::snprintf(
        text, sizeof text,
        "%%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X-150 Y0 Z-700 F60000\n"
        "N40 #SYNC IN [CONV_VEL=6000 %s]\nN50 G01 X%.4f Y%.4f Z-700 F60000\n"
        "N60 G91 G01 X%.6f Y%.6f F%.3f\nN70 G90 G04 0.05\nN80 #SYNC OUT\nN90 M30\n",
        automatic ? "FEED_CONT_AUTO" : (std::string("FEED_CONT=") + std::to_string(f)).c_str(),
        uniform(-120.0, -60.0), uniform(-40.0, 40.0), length * std::cos(angle),
        length * std::sin(angle), feed);
    CAPTURE(text);
    const Run r = run(text);
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE_FALSE(r.error);
    REQUIRE(r.handover > 2);
    const double v = r.v_relative[r.handover];
    CHECK(v >= 0.0);
    CHECK(v <= (automatic ? feed / 60.0 : std::min(f, feed) / 60.0) * (1 + 1e-9));
    CHECK_FALSE(r.warning);
    // Every joint keeps its v, a and j throughout (the audit's own checks and tolerance): the
    // catch-up by its TCP dynamics (tcp_dynamics covers the third-derivative term), the PCS1
    // block after the hand-over by the belt's share of the joints' velocity, acceleration and
    // jerk reserved for it (belt-jerk: tracking::belt_share, docs/conveyor.md "Machining in PCS1").
    CHECK(r.verdict.violation_count == 0);
    for (const audit::AxisAudit& j : r.verdict.joints)
      if (j.j_limit > 0.0) jerk = std::max(jerk, std::max(j.j_closed, j.j_diff) / j.j_limit);
  }
  MESSAGE("largest joint |j| / J over the runs: " << jerk);
}

TEST_CASE("#TRAFO ON, seeded: catch-ups met at rest keep every joint's v, a and j") {
  std::uint64_t state = 0x7AF0AE57u;
  auto uniform = [&](double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int n = 0; n < 6; ++n) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "%%t\nN10 #KIN ID[37]\nN20 #TRAFO ON\nN30 G01 X%.4f Y%.4f Z%.4f F60000\n"
                  "N40 #SYNC IN [CONV_VEL=6000]\nN50 G01 X%.4f Y%.4f Z%.4f F60000\n"
                  "N60 G04 0.05\nN70 #SYNC OUT\nN80 M30\n",
                  uniform(-250.0, -100.0), uniform(-150.0, 150.0), uniform(-850.0, -650.0),
                  uniform(-120.0, 60.0), uniform(-150.0, 150.0), uniform(-850.0, -650.0));
    CAPTURE(text);
    const Run r = run(text);
    REQUIRE(r.status == ipo::Status::finished);
    REQUIRE_FALSE(r.error);
    REQUIRE(r.handover > 2);
    CHECK(r.v_relative[r.handover] == 0.0);
    CHECK_FALSE(r.warning);
    CHECK(r.verdict.violation_count == 0);
  }
}
