#pragma once
// channel/trafo_test_support.hpp: the set-up the conveyor tests under #TRAFO ON share (tests only):
// the picker, a tracked and audited run (track()) and the far-side check of the joints.

#include <doctest/doctest.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "machines/machine.hpp"
#include "program/trafo.hpp"
#include "scenario/loader.hpp"
#include "scenario/player.hpp"
#include "tracking/test_port.hpp"

namespace ncsim::channel::test {

/// The delta picker with a conveyor workspace that holds its working height (the bundled
/// list's +-500 mm does not: programs/pick_and_place).
inline machines::Machine picker() {
  machines::Machine m = interp::test::machine("delta_picker");
  m.channel.conveyor->workspace.lower = Eigen::Vector3d(-600, -600, -900);
  m.channel.conveyor->workspace.upper = Eigen::Vector3d(600, 600, 0);
  return m;
}

/// The cycle of the tracked runs [s].
inline constexpr double kTrafoTestCycle = 0.001;

// Runs on the picker, tracked and audited (joints included) as `ncsim time --audit` does.
/// A run under #TRAFO ON tracked cycle by cycle (track()).
struct Tracked {
  ipo::Status status = ipo::Status::finished;
  std::vector<std::uint32_t> line;
  std::vector<tracking::SyncPhase> phase;
  std::vector<std::array<double, 3>> tcp;     // FK of the joint commands (MCS)
  std::vector<std::array<double, 3>> offset;  // PCS1 offset on X, Y, Z
  std::vector<ipo::JointSetpoint> joints;
  std::optional<RunTimeError> error;
  std::optional<RunTimeError> warning;
  audit::Verdict verdict;
  std::string source_error;
};

// `override_percent`: a path override from t = 0 on a REDUCED_ABOVE_100 channel (a scenario
// event, docs/scenario.md); null: none, the machine's override type.
inline Tracked track(const std::string& program, tracking::test::FakePort* port,
                     const machines::Machine& m = picker(),
                     const char* override_percent = nullptr) {
  ChannelConfig cfg = channel_config(m, kTrafoTestCycle);
  REQUIRE(cfg.path.joints);
  // The scenario outlives the player that plays it (scenario::Player keeps a reference).
  const core::SourceFile toml("s.toml", std::string("[[event]]\nat = 0.0\noverride = ") +
                                            (override_percent ? override_percent : "100") + "\n");
  const scenario::LoadResult loaded = scenario::parse_scenario(toml);
  REQUIRE(loaded.scenario);
  std::optional<scenario::Player> player;
  if (override_percent != nullptr) {
    cfg.path.override_type = ipo::OverrideType::reduced_above_100;
    player.emplace(*loaded.scenario);
  }
  const auto trafo = program::machine_trafo(m, cfg.path);
  REQUIRE(trafo);
  audit::Audit audit(cfg.path.axes, kTrafoTestCycle, cfg.path.start);
  audit.set_joint_limits(cfg.path.joints->joints, cfg.path.start, true);
  ConveyorRig rig(program, m, std::move(cfg), port, &audit);
  if (player) rig.ch.play(&*player);
  const Channel& ch = rig.ch;
  Tracked r;
  r.status = run_to_end(
      rig.ch,
      [&] {
        if (ch.transformed()) audit.on_joints(ch.cycle(), ch.joints());
        const tracking::ConveyorSync& s = *ch.conveyor_sync();
        r.line.push_back(ch.cycle().line);
        r.phase.push_back(s.phase());
        const auto& q = ch.axes().command;
        const auto p = trafo->kinematics->forward(Eigen::Vector3d(q[0], q[1], q[2]));
        REQUIRE(p.ok());
        r.tcp.push_back({p.value[0], p.value[1], p.value[2]});
        r.offset.push_back({s.offset(0), s.offset(1), s.offset(2)});
        r.joints.push_back(ch.joints());
      },
      100'000);
  r.error = ch.run_time_error();
  r.warning = ch.trafo_warning();
  r.verdict = audit.verdict();
  if (const core::Diagnostic* d = rig.src.error()) r.source_error = d->id + ": " + d->message;
  return r;
}

// `program` tracked on a belt at `belt` [mm/s] that latches at cycle 100 (track()); it must run
// to its end without a program or a run-time error.
inline Tracked track_clean(const std::string& program, double belt,
                           const machines::Machine& m = picker(),
                           const char* override_percent = nullptr) {
  tracking::test::FakePort port(belt);
  port.latch_at_ = 100;
  Tracked r = track(program, &port, m, override_percent);
  if (!r.source_error.empty()) MESSAGE(r.source_error);
  if (r.error)
    MESSAGE(r.error->id << " line " << r.error->line << " t " << r.error->t << ": "
                        << r.error->message);
  REQUIRE(r.status == ipo::Status::finished);
  REQUIRE_FALSE(r.error);
  return r;
}

// Lines first..last, tracked with the belt on top, use the joints' jerk (more than `used` of J)
// and keep every joint's a and j (the delta's A 20000 deg/s^2, J 500000 deg/s^3): no audit
// violation, no warning.
inline void check_far_side(const Tracked& r, std::uint32_t first, std::uint32_t last, double belt,
                           double used = 0.5) {
  double a = 0.0, j = 0.0;  // the lines' largest joint |a| / A and |j| / J
  std::size_t cycles = 0;
  for (std::size_t k = 0; k < r.joints.size(); ++k) {
    if (r.phase[k] != tracking::SyncPhase::tracking || r.line[k] < first || r.line[k] > last)
      continue;
    ++cycles;
    for (std::size_t i = 0; i < 3; ++i) {
      a = std::max(a, std::fabs(r.joints[k].a[i]) / 20000.0);
      j = std::max(j, std::fabs(r.joints[k].j[i]) / 500000.0);
    }
  }
  MESSAGE("belt " << belt << " mm/s: joint |a| / A " << a << ", |j| / J " << j << ", "
                  << r.verdict.violation_count << " audit violations");
  for (const auto& v : r.verdict.violations)
    MESSAGE("violation: axis " << int(v.axis) << " joint " << v.joint << " value " << v.value
                               << " limit " << v.limit << " t " << v.t);
  CHECK(cycles > 100);
  CHECK(j > used);  // the lines use the joints' jerk
  CHECK(j <= 1.0 + 1e-3);
  CHECK_FALSE(r.warning);
  CHECK(r.verdict.violation_count == 0);
}

}  // namespace ncsim::channel::test
