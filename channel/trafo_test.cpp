// #TRAFO in the channel loop (docs/ipo.md "Kinematics in run and time"): the delta picker
// (#KIN ID[37], machines/delta_picker) planned in Cartesian space with its drives' own limits;
// the axes receive the joints; the switch ON / OFF with the path standing; a TCP target outside
// the workspace is the kinematic's positioned error.

#include "program/trafo.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "machines/delta_kinematics.hpp"
#include "program/program_source.hpp"
#include "scenario/loader.hpp"
#include "scenario/player.hpp"

namespace {

using namespace ncsim;

using channel::test::Recorder;

struct Result {
  ipo::Status status = ipo::Status::finished;
  std::vector<ipo::Cycle> cycles;
  std::vector<channel::AxesState> axes;  ///< after each cycle
  std::vector<bool> transformed;         ///< per cycle
  audit::Verdict verdict;
  std::optional<core::Diagnostic> source_error;
  std::optional<channel::RunTimeError> error;
};

Result run(const std::string& text, scenario::Player* player = nullptr,
           ipo::OverrideType type = ipo::OverrideType::reduced) {
  const core::SourceFile file("t.nc", text);
  const machines::Machine& m = interp::test::machine("delta_picker");
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  channel::ChannelConfig cfg = channel::channel_config(m, 0.001);
  cfg.path.override_type = type;
  REQUIRE(cfg.path.joints);
  audit::Audit audit(cfg.path.axes, 0.001, cfg.path.start);
  audit.set_joint_limits(cfg.path.joints->joints, cfg.path.start, true);
  Recorder rec;
  channel::test::AuditedRecorder both(&audit, &rec);
  channel::Channel ch(std::move(cfg), src, &both);
  ch.play(player);
  Result r;
  r.status = channel::test::run_to_end(ch, [&] {
    if (ch.transformed()) audit.on_joints(ch.cycle(), ch.joints());
    r.axes.push_back(ch.axes());
    r.transformed.push_back(ch.transformed());
  });
  r.cycles = std::move(rec.cycles);
  r.verdict = audit.verdict();
  if (const core::Diagnostic* d = src.error()) r.source_error = *d;
  r.error = ch.run_time_error();
  return r;
}

machines::DeltaKinematics picker() {
  // machines/delta_picker/channel.lis trafo[0] (docs/machines.md "Kinematic 37").
  machines::DeltaGeometry g;
  g.r_effector = 48.0;
  g.r_base = 200.0;
  g.l_lower = 1050.0;
  g.l_upper = 465.544;
  return machines::DeltaKinematics(g);
}

}  // namespace

TEST_CASE("a delta-robot move under #TRAFO ON keeps every joint inside its own v, a, j") {
  // The seed's pick positions at F350000 (5833 mm/s): far above what the drives allow, so
  // the joints (720 deg/s, 20000 deg/s^2, 500000 deg/s^3, machines/delta_picker) set the pace.
  const Result r =
      run("N10 #KIN ID[37]\n"
          "N20 #TRAFO ON\n"
          "N25 #SLOPE [TYPE=TRAPEZ]\n"
          "N30 G01 X-100 Y0 Z-700 F350000\n"
          "N40 G01 X-50 Y0 Z-800\n"
          "N50 G01 X-50 Y0 Z-750\n"
          "N60 G01 X100 Y150 Z-760\n"
          "N70 G02 X100 Y150 I-50 J0\n"
          "N80 M30\n");
  REQUIRE_FALSE(r.source_error);
  REQUIRE_FALSE(r.error);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.verdict.ok());
  REQUIRE(r.verdict.joints.size() >= 3);
  const machines::Machine& m = interp::test::machine("delta_picker");
  double used = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const audit::AxisAudit& j = r.verdict.joints[i];
    const machines::Dynamics& d = m.axes[i].dynamics;
    CHECK(std::max(j.v_closed, j.v_diff) <= d.v_max * (1 + 1e-9));
    CHECK(std::max(j.a_closed, j.a_diff) <= j.a_limit * (1 + 1e-9));
    CHECK(j.j_closed <= j.j_limit * (1 + 1e-9));
    CHECK(j.j_closed > 0.0);  // TRAPEZ: the jerk is audited
    used = std::max({used, j.v_closed / j.v_limit, j.a_closed / j.a_limit, j.j_closed / j.j_limit});
  }
  CHECK(used > 0.5);  // the joints are what limits the path
  MESSAGE("largest joint use of a limit: " << used);
  // Every transformed cycle: the axes' command is the inverse transform of the TCP.
  const machines::DeltaKinematics kin = picker();
  std::size_t checked = 0;
  for (std::size_t k = 0; k < r.cycles.size(); k += 37) {
    if (!r.transformed[k]) continue;
    const ipo::Cycle& c = r.cycles[k];
    const auto q = kin.inverse(Eigen::Vector3d(c.x[0], c.x[1], c.x[2]));
    REQUIRE(q.ok());
    for (Eigen::Index i = 0; i < 3; ++i)
      CHECK(r.axes[k].command[static_cast<std::size_t>(i)] ==
            doctest::Approx(q.value[i]).epsilon(1e-12));
    ++checked;
  }
  CHECK(checked > 10);
  // The TCP ends on the circle's end point, the contour audit saw no deviation.
  CHECK(r.cycles.back().x[0] == doctest::Approx(100.0).epsilon(1e-9));
  CHECK(r.cycles.back().x[1] == doctest::Approx(150.0).epsilon(1e-9));
  CHECK(r.verdict.contour_max < 1e-6);
}

TEST_CASE("#TRAFO ON / OFF: the path stands at each switch, the joints run on continuously") {
  const Result r =
      run("N10 #KIN ID[37]\n"
          "N20 G01 X10 Y-5 Z12 F6000\n"  // axis move: the drives in degrees
          "N30 #TRAFO ON\n"              // X, Y, Z become the TCP (re-based at decode)
          "N40 G01 X-100 Y0 Z-700 F60000\n"
          "N50 G01 X50 Y20 Z-780\n"
          "N60 #TRAFO OFF\n"  // back to drive angles
          "N70 G01 X0 Y0 Z0 F6000\n"
          "N80 M30\n");
  REQUIRE_FALSE(r.source_error);
  REQUIRE_FALSE(r.error);
  CHECK(r.status == ipo::Status::finished);
  CHECK(r.verdict.ok());
  // Three phases: axes, TCP, axes.
  int switches = 0;
  for (std::size_t k = 1; k < r.cycles.size(); ++k) {
    if (r.transformed[k] == r.transformed[k - 1]) continue;
    ++switches;
    // The path stood at the end of the cycle before the switch.
    CHECK(r.cycles[k - 1].path.v == 0.0);
    CHECK(r.cycles[k].line == (r.transformed[k] ? 4u : 7u));  // N40, N70
  }
  CHECK(switches == 2);
  // The joints are continuous across the switches: no step beyond v_max T in any cycle.
  const machines::Machine& m = interp::test::machine("delta_picker");
  for (std::size_t k = 1; k < r.axes.size(); ++k)
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(std::abs(r.axes[k].command[i] - r.axes[k - 1].command[i]) <=
            m.axes[i].dynamics.v_max * 0.001 * (1 + 1e-6));
  // The last axis move ends on its programmed drive angles.
  for (std::size_t i = 0; i < 3; ++i)
    CHECK(r.axes.back().command[i] == 0.0);
  // Before ON the axes were the drive angles of N20.
  bool saw_n20_end = false;
  for (std::size_t k = 0; k < r.cycles.size(); ++k)
    if (r.cycles[k].line == 2 && r.axes[k].command[0] == 10.0 && r.axes[k].command[2] == 12.0)
      saw_n20_end = true;
  CHECK(saw_n20_end);
}

TEST_CASE("a TCP target outside the delta's workspace: the kinematic's error at its line") {
  const Result r =
      run("N10 #KIN ID[37]\n"
          "N20 #TRAFO ON\n"
          "N30 G01 X-100 Y0 Z-700 F60000\n"
          "N40 G01 X0 Y0 Z-2000\n"  // 2 m below the base: the arms cannot reach
          "N50 M30\n");
  REQUIRE(r.source_error);
  CHECK(r.source_error->id == "NC3201");
  CHECK(r.source_error->loc.line == 4);
  CHECK(r.source_error->message.find("Z-2000") != std::string::npos);
  // The blocks before it ran to their end.
  REQUIRE_FALSE(r.cycles.empty());
  CHECK(r.cycles.back().x[0] == doctest::Approx(-100.0).epsilon(1e-9));
  CHECK(r.cycles.back().x[2] == doctest::Approx(-700.0).epsilon(1e-9));
  CHECK_FALSE(r.error);
}

TEST_CASE("a path that leaves the workspace between reachable end points is refused too") {
  // Both ends reachable, the straight line between them passes far outside (through the
  // base plane's far side).
  const Result r =
      run("N10 #KIN ID[37]\n"
          "N20 #TRAFO ON\n"
          "N30 G01 X-100 Y0 Z-700 F60000\n"
          "N40 G02 X-100 Y0 I1500 J0\n"  // a full circle of R 1500 mm: out of reach
          "N50 M30\n");
  REQUIRE(r.source_error);
  CHECK(r.source_error->id == "NC3201");
  CHECK(r.source_error->loc.line == 4);
  CHECK(r.source_error->message.find("path point") != std::string::npos);
}

TEST_CASE("a path override above 100 % under #TRAFO ON: the raised cap keeps the joints' limits") {
  // issue 12: REDUCED_ABOVE_100 raises the level up to the G00 velocity along the path
  // (000 l.360); under #TRAFO ON that is the joints' rapid rule (ipo/override_trafo.cpp), never
  // the Cartesian stand-ins (the cap itself: ipo/override_test.cpp). At F6000 (100 mm/s) 150 %
  // and 1000 % run faster, and the audit shows the joints inside their v, a, j either way.
  const char* const program =
      "N10 #KIN ID[37]\n"
      "N20 #TRAFO ON\n"
      "N30 G01 X-100 Y0 Z-700 F6000\n"
      "N40 G01 X150 Y100 Z-760\n"
      "N50 M30\n";
  auto with = [&](const char* percent) {
    const std::string text = std::string("[[event]]\nat = 0.0\noverride = ") + percent + "\n";
    const core::SourceFile toml("s.toml", text);
    scenario::LoadResult loaded = scenario::parse_scenario(toml);
    REQUIRE(loaded.scenario);
    scenario::Player player(*loaded.scenario);
    return run(program, &player, ipo::OverrideType::reduced_above_100);
  };
  const Result base = with("100");
  const Result raised = with("150");
  const Result capped = with("1000");
  for (const Result* r : {&base, &raised, &capped}) {
    if (r->error) MESSAGE(r->error->id << ": " << r->error->message);
    REQUIRE_FALSE(r->error);
    CHECK(r->status == ipo::Status::finished);
    for (const auto& v : r->verdict.violations)
      MESSAGE("violation: axis " << int(v.axis) << " joint " << v.joint << " value " << v.value
                                 << " limit " << v.limit << " t " << v.t);
    CHECK(r->verdict.ok());
  }
  // Faster above 100 %, 1000 % faster still (this short stroke is acceleration-bound).
  const double t100 = base.cycles.back().t;
  const double t150 = raised.cycles.back().t;
  const double t1000 = capped.cycles.back().t;
  MESSAGE("t at 100 / 150 / 1000 %: " << t100 << " / " << t150 << " / " << t1000);
  CHECK(t150 < t100 * 0.85);
  CHECK(t1000 < t150);
  CHECK(t1000 > t100 / 10.0);
  // The joints never exceed their rapid velocity at 1000 %.
  double vq = 0.0;
  for (std::size_t k = 1; k < capped.axes.size(); ++k)
    for (std::size_t i = 0; i < 3; ++i)
      vq = std::max(vq,
                    std::fabs(capped.axes[k].command[i] - capped.axes[k - 1].command[i]) / 0.001);
  CHECK(vq <= 720.0 * (1 + 1e-6));
}
