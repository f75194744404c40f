// #TRAFO with the 6-axis articulated robot (#KIN ID[45], machines/arm6_belt) in the channel
// loop (docs/ipo.md "Kinematics in run and time", docs/machines.md "Kinematic 45"): the TCP and
// the tool orientation planned in Cartesian space, the six joints X, Y, Z, A, B, C receiving
// the inverse with their own limits (audited); singular, unreachable and wrapping targets as
// the kinematic's positioned errors.

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
#include "machines/arm_kinematics.hpp"
#include "program/program_source.hpp"
#include "program/trafo.hpp"

namespace {

using namespace ncsim;

struct Result {
  std::vector<ipo::Cycle> cycles;
  std::vector<channel::AxesState> axes;  ///< after each cycle
  std::vector<bool> transformed;         ///< per cycle
  audit::Verdict verdict;
  std::optional<core::Diagnostic> source_error;
  std::optional<channel::RunTimeError> error;
};

Result run(const std::string& text, const machines::Machine& m) {
  const core::SourceFile file("t.nc", text);
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  channel::ChannelConfig cfg = channel::channel_config(m, 0.001);
  REQUIRE(cfg.path.joints);
  audit::Audit audit(cfg.path.axes, 0.001, cfg.path.start);
  audit.set_joint_limits(cfg.path.joints->joints, cfg.path.start, true);
  channel::test::Recorder rec;
  channel::test::AuditedRecorder both(&audit, &rec);
  channel::Channel ch(std::move(cfg), src, &both);
  Result r;
  channel::test::run_to_end(ch, [&] {
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

const machines::Machine& arm() {
  return interp::test::machine("arm6_belt");
}

// The start pose (joint 5 at 90 deg: the tool down), then #TRAFO ON.
constexpr const char* kStart =
    "N10 #KIN ID[45]\n"
    "N20 G01 X0 Y0 Z0 A0 B90 C0 F20000\n"
    "N30 #TRAFO ON\n";

TEST_CASE("kinematic 45 in the channel: the joints follow the TCP line inside their limits") {
  const Result r = run(std::string(kStart) +
                           "N40 G01 X700 Y-300 Z250 F120000\n"
                           "N50 G01 X400 Y700 Z200 C45\n"  // across the front, the tool turning
                           "N60 M30\n",
                       arm());
  REQUIRE_FALSE(r.source_error);
  REQUIRE_FALSE(r.error);
  CHECK(r.verdict.ok());
  // The six joints are the axes: each cycle's commands map forward onto the path's TCP.
  const auto built = machines::make_kinematics(45, arm().channel.trafos[0].param);
  REQUIRE(built.kinematics);
  std::size_t checked = 0;
  double q1_max = 0.0, q6_min = 0.0, q6_max = 0.0;
  for (std::size_t k = 0; k < r.cycles.size(); ++k) {
    if (!r.transformed[k]) continue;
    machines::KinAxes q{};
    for (std::size_t i = 0; i < 6; ++i)
      q[i] = r.axes[k].command[i];
    const machines::KinAxesResult p = built.kinematics->forward_axes(q);
    REQUIRE(p.ok());
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(std::abs(p.value[i] - r.cycles[k].x[i]) < 1e-6);
    CHECK(std::abs(std::remainder(p.value[5] - r.cycles[k].x[5], 360.0)) < 1e-6);
    q1_max = std::max(q1_max, q[0]);
    q6_min = std::min(q6_min, q[5]);
    q6_max = std::max(q6_max, q[5]);
    ++checked;
  }
  CHECK(checked > 500);
  CHECK(q1_max > 60.0);           // joint 1 turned towards the belt
  CHECK(q6_max - q6_min > 30.0);  // joint 6 follows joint 1 and the programmed C
  // The last TCP is the programmed one.
  REQUIRE_FALSE(r.cycles.empty());
  CHECK(r.cycles.back().x[0] == doctest::Approx(400.0));
  CHECK(r.cycles.back().x[1] == doctest::Approx(700.0));
  CHECK(r.cycles.back().x[5] == doctest::Approx(45.0));
}

TEST_CASE("kinematic 45 in the channel: a singular target is NC3204 at its line") {
  // Straight above joint 1 with the tool down: the wrist centre on the axis.
  const Result r = run(std::string(kStart) +
                           "N40 G01 X600 Y0 Z300 F60000\n"
                           "N50 G01 X0.2 Y0 Z300\n"
                           "N60 M30\n",
                       arm());
  REQUIRE(r.source_error);
  CHECK(r.source_error->id == "NC3204");
  CHECK(r.source_error->loc.line == 5);
  CHECK(r.source_error->message.find("shoulder singularity") != std::string::npos);
  // The block before it ran to its end.
  REQUIRE_FALSE(r.cycles.empty());
  CHECK(r.cycles.back().x[0] == doctest::Approx(600.0));
}

TEST_CASE("kinematic 45 in the channel: out of reach is NC3201, a joint limit NC3202") {
  const Result far = run(std::string(kStart) + "N40 G01 X1800 Y0 Z300 F60000\nN50 M30\n", arm());
  REQUIRE(far.source_error);
  CHECK(far.source_error->id == "NC3201");
  CHECK(far.source_error->loc.line == 4);
  // Behind the base joint 1 would need about 180 deg, beyond its 170.
  const Result behind =
      run(std::string(kStart) + "N40 G01 X-700 Y20 Z300 F60000\nN50 M30\n", arm());
  REQUIRE(behind.source_error);
  CHECK(behind.source_error->id == "NC3202");
  CHECK(behind.source_error->message.find("joint 1") != std::string::npos);
}

TEST_CASE("kinematic 45 in the channel: a path turning joint 1 across +-180 deg is NC3202") {
  // Joints 1 and 6 free over the whole -180..180: both ends reachable, the line between them
  // behind the base crosses joint 1's range end.
  machines::Machine m = arm();
  m.channel.trafos[0].param[11] = -180.0;  // joint 1
  m.channel.trafos[0].param[12] = 180.0;
  m.channel.trafos[0].param[21] = -180.0;  // joint 6, which follows joint 1 with the tool down
  m.channel.trafos[0].param[22] = 180.0;
  for (machines::AxisParams& a : m.axes)
    if (a.name == "X" || a.name == "C") a.soft_limits = {-180.0, 180.0};
  const Result r = run(std::string(kStart) +
                           "N40 G01 X0 Y700 Z300 F60000\n"
                           "N50 G01 X-700 Y300 Z300\n"
                           "N60 G01 X-700 Y-300 Z300\n"
                           "N70 M30\n",
                       m);
  REQUIRE(r.source_error);
  CHECK(r.source_error->id == "NC3202");
  INFO(r.source_error->message);
  CHECK(r.source_error->loc.line == 6);
  CHECK(r.source_error->message.find("across its +-180 deg range end") != std::string::npos);
}

}  // namespace
