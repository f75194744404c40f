// An error while synchronised under #TRAFO ON (seed 004 §2.3 with §2.2 l.609, l.687;
// tracking/sync_error_trafo, channel/after_error_trafo.cpp; docs/conveyor.md "Errors while
// synchronised"): the delta picker grips a workpiece on a 100 mm/s belt; the belt speeds up to
// 120 mm/s (50653, more than 10 % above CONV_VEL) while it grips. The TCP keeps following the
// belt on its line (Y, Z unchanged), brakes before the conveyor workspace's X face 600 mm, the
// joints keep their limits, and the run ends with 50653 at the dwell's line and time.

#include "tracking/sync_error_trafo.hpp"

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
#include "channel/trafo_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"
#include "program/trafo.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;

using channel::test::picker;

const char* const kGrip =
    "%t\n"                              // 1
    "N10 #KIN ID[37]\n"                 // 2
    "N20 #TRAFO ON\n"                   // 3
    "N30 G01 X-150 Y0 Z-700 F60000\n"   // 4: waiting position
    "N40 #SYNC IN [CONV_VEL=6000]\n"    // 5
    "N50 G01 X-100 Y20 Z-700 F60000\n"  // 6: the catch-up (TCP motion)
    "N60 G01 Z-800 F30000\n"            // 7: down onto the workpiece (PCS1)
    "N70 G04 10\n"                      // 8: a long grip: the belt speeds up meanwhile
    "N80 G01 Z-750 F30000\n"            // 9
    "N90 #SYNC OUT\n"                   // 10
    "N100 M30\n";                       // 11

struct After {
  ipo::Status status = ipo::Status::finished;
  std::vector<double> t;
  std::vector<std::array<double, 3>> tcp;  // FK of the joint commands (MCS)
  std::optional<channel::RunTimeError> error;
  std::optional<channel::RunTimeError> warning;
  std::string note;
  audit::Verdict verdict;
};

After run(double belt_new, long change_at, std::optional<long> stop_at = std::nullopt,
          double x_face = 600.0) {
  machines::Machine m = picker();
  m.channel.conveyor->workspace.upper[0] = x_face;
  tracking::test::FakePort port(100.0);
  port.latch_at_ = 100;
  port.v_change_at_ = change_at;
  port.v_new_ = belt_new;
  if (stop_at) {
    port.v_change2_at_ = *stop_at;
    port.v_new2_ = 0.0;
  }
  channel::ChannelConfig cfg = channel::channel_config(m, kT);
  REQUIRE(cfg.path.joints);
  const auto trafo = program::machine_trafo(m, cfg.path);
  REQUIRE(trafo);
  audit::Audit audit(cfg.path.axes, kT, cfg.path.start);
  audit.set_joint_limits(cfg.path.joints->joints, cfg.path.start, true);
  channel::test::ConveyorRig rig(kGrip, m, std::move(cfg), &port, &audit);
  const channel::Channel& ch = rig.ch;
  After r;
  r.status = channel::test::run_to_end(
      rig.ch,
      [&] {
        if (ch.transformed()) audit.on_joints(ch.cycle(), ch.joints());
        r.t.push_back(ch.cycle().t);
        const auto& q = ch.axes().command;
        const auto p = trafo->kinematics->forward(Eigen::Vector3d(q[0], q[1], q[2]));
        REQUIRE(p.ok());
        r.tcp.push_back({p.value[0], p.value[1], p.value[2]});
      },
      100'000);
  r.error = ch.run_time_error();
  r.warning = ch.trafo_warning();
  r.note = ch.after_error_note();
  r.verdict = audit.verdict();
  return r;
}

std::size_t index_at(const After& r, double t) {
  return static_cast<std::size_t>(std::lower_bound(r.t.begin(), r.t.end(), t - 1e-9) - r.t.begin());
}

}  // namespace

TEST_CASE(
    "under #TRAFO ON an error while synchronised: the TCP follows the belt on its line and "
    "brakes before the workspace face, the joints keep their limits") {
  const After r = run(120.0, 1500);
  REQUIRE(r.status == ipo::Status::error);
  REQUIRE(r.error);
  CHECK(r.error->id == "50653");
  CHECK(r.error->line == 8);
  CHECK(r.error->t == doctest::Approx(1.5).epsilon(0.01));
  MESSAGE(r.note);
  CHECK(r.note.find("under #TRAFO ON") != std::string::npos);
  CHECK(r.note.find("X face 600 mm (P-CHAN-00859)") != std::string::npos);
  const std::size_t e = index_at(r, r.error->t);
  REQUIRE(r.t.size() > e + 1000);
  // Following: the TCP moves at the belt's 120 mm/s along X, Y and Z stay on the workpiece.
  const std::size_t f = index_at(r, r.error->t + 1.0);
  CHECK((r.tcp[f + 1][0] - r.tcp[f][0]) / kT == doctest::Approx(120.0).epsilon(1e-4));
  for (std::size_t k = e; k < r.tcp.size(); ++k) {
    CAPTURE(k);
    CHECK(r.tcp[k][1] == doctest::Approx(20.0).epsilon(1e-6));
    CHECK(r.tcp[k][2] == doctest::Approx(-800.0).epsilon(1e-6));
  }
  // The TCP stands before the face, within a cycle's belt travel of it (the stop's margin).
  double x_max = -1e9;
  for (const auto& p : r.tcp)
    x_max = std::max(x_max, p[0]);
  CHECK(x_max <= 600.0 + 1e-6);
  CHECK(x_max >= 600.0 - 120.0 * kT - 1e-3);
  CHECK(r.tcp.back()[0] == doctest::Approx(x_max).epsilon(1e-9));
  const std::size_t last = r.tcp.size() - 1;
  CHECK(std::fabs(r.tcp[last][0] - r.tcp[last - 1][0]) < 1e-4);  // at rest (< 0.1 mm/s)
  // The joints: the audit clean after the error. The belt's own step from 100 to 120 mm/s in
  // one cycle (the test's world, not a motion ncsim plans) is a jerk step of every joint in the
  // error's cycle and the next: the only violations allowed, and the only NC6210 (the jerk of a
  // joint at the step; trafo-checks: before, NC6210 checked v and a only and said nothing).
  REQUIRE(r.warning);
  MESSAGE("t=" << r.warning->t << ": " << r.warning->message);
  CHECK(r.warning->message.find("|j|") != std::string::npos);
  CHECK(r.warning->t >= r.error->t - 1.5 * kT);
  CHECK(r.warning->t <= r.error->t + 1.5 * kT);
  std::size_t later = 0;
  for (const auto& v : r.verdict.violations) {
    if (v.t <= r.error->t + 1.5 * kT) continue;
    ++later;
    MESSAGE("violation: axis " << int(v.axis) << " joint " << v.joint << " value " << v.value
                               << " limit " << v.limit << " t " << v.t);
  }
  CHECK(later == 0);
}

TEST_CASE("under #TRAFO ON a belt stopped after the error stops the TCP with it") {
  const After free = run(120.0, 1500);
  REQUIRE(free.error);
  const long stop_at = static_cast<long>(std::lround((free.error->t + 1.0) / kT));
  const After r = run(120.0, 1500, stop_at);
  REQUIRE(r.error);
  CHECK(r.error->id == "50653");
  MESSAGE(r.note);
  CHECK(r.note.find("stood with the belt") != std::string::npos);
  CHECK(r.tcp.back()[0] < 600.0 - 100.0);
  CHECK(r.t.back() <= static_cast<double>(stop_at) * kT + 0.01);
}

TEST_CASE(
    "under #TRAFO ON the TCP beyond the workspace face when the error comes (NC9052): the "
    "run ends at once") {
  // The belt carries the gripping TCP across X = 0 at 100 mm/s (no 50653).
  const After r = run(100.0, 1, std::nullopt, 0.0);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC9052");
  CHECK(r.error->line == 8);
  CHECK(r.note.empty());
  CHECK(r.t.back() <= r.error->t + 1e-9);
  CHECK(r.tcp.back()[0] <= 0.2);
}

TEST_CASE("the TCP's after-error limits: the workspace faces on X, Y, Z, the joints' elsewhere") {
  const machines::Machine m = picker();
  channel::ChannelConfig cfg = channel::channel_config(m, kT);
  REQUIRE(cfg.path.joints);
  std::vector<tracking::AfterErrorAxis> joints;
  for (std::size_t i = 0; i < cfg.path.axes.size(); ++i)
    joints.push_back(tracking::after_error_axis(cfg.path.axes[i], {}));
  ipo::AxisVec tcp{};
  tcp[0] = 100.0;
  tcp[2] = -800.0;
  const auto lim =
      tracking::tcp_after_error_axes(cfg.path.joints->inverse, {0, 1, 2}, joints,
                                     m.channel.conveyor->workspace, Eigen::Vector3d(1, 0, 0), tcp);
  REQUIRE(lim);
  for (std::size_t k = 0; k < 3; ++k) {
    CAPTURE(k);
    const tracking::AfterErrorAxis& a = (*lim)[k];
    CHECK(a.soft.max_enabled);
    CHECK(a.soft.min_enabled);
    CHECK(a.soft.max_position == m.channel.conveyor->workspace.upper[static_cast<int>(k)]);
    CHECK(a.soft.min_position == m.channel.conveyor->workspace.lower[static_cast<int>(k)]);
    CHECK(a.a_max > 0.0);
    CHECK(a.j_max > 0.0);
    CHECK(a.d_max == a.a_max);
  }
  for (std::size_t i = 3; i < joints.size(); ++i)
    CHECK((*lim)[i].v_max == joints[i].v_max);  // the gripper keeps its own
  // A TCP the transform cannot map: none.
  ipo::AxisVec far{};
  far[0] = 1e5;
  CHECK_FALSE(tracking::tcp_after_error_axes(cfg.path.joints->inverse, {0, 1, 2}, joints,
                                             m.channel.conveyor->workspace,
                                             Eigen::Vector3d(1, 0, 0), far));
}
