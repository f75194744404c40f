// The channel's INDP axes: an axis the INDP layer owns is driven with its PTP setpoint through
// position control and the monitors, shows in the cycle (Cycle::independent), and goes back to
// the path when the path programs it after the motion; a path block that moves it while its
// INDP motion runs is NC6103. The INDP commands themselves come from the program through the
// channel's events (docs/ipo.md "INDP axes and technology functions"); here they are given
// through Channel::indp(), the hook conveyor tracking also uses.

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"

namespace {

using namespace ncsim;

using channel::test::Recorder;

using Run = channel::test::AuditedRun;

// Runs `program` on portal_3x (1 ms); before the first cycle axis `axis` gets `move`.
Run run(const std::string& program, std::size_t axis, const channel::IndpMove& move) {
  const core::SourceFile file("t.nc", program);
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m, interp::Options{});
  program::ProgramSource src(in, m);
  channel::ChannelConfig cfg = channel::channel_config(m, 0.001);
  audit::Audit audit(cfg.path.axes, cfg.path.channel.t_cycle, cfg.path.start);
  Recorder rec;
  channel::test::AuditedRecorder tee(&audit, &rec);
  channel::Channel ch(std::move(cfg), src, &tee);
  REQUIRE_FALSE(ch.indp().command(axis, move));
  return channel::test::finish(ch, rec, audit);
}

channel::IndpMove to(double target, double feed) {
  channel::IndpMove m;
  m.target = target;
  m.feed = feed;
  return m;
}

}  // namespace

TEST_CASE("an INDP axis runs beside the path through the channel, audited on its own limits") {
  // Y moves 0 -> 40 at 20 mm/s (2 s and the ramps) while the path moves X for 3 s.
  const Run r = run("%i\nN10 G01 X30 F600\nN20 M30\n", 1, to(40.0, 20.0));
  CHECK(r.status == ipo::Status::finished);
  CHECK_FALSE(r.error);
  REQUIRE(r.cycles.size() > 2000);
  CHECK(r.cycles.back().x[0] == 30.0);
  CHECK(r.cycles.back().x[1] == 40.0);
  CHECK((r.cycles.front().independent & 2u) != 0);
  double vy = 0.0;
  for (const ipo::Cycle& c : r.cycles)
    vy = std::max(vy, std::abs(c.v[1]));
  CHECK(vy == doctest::Approx(20.0).epsilon(1e-6));
  CHECK(r.verdict.ok());
  CHECK(r.verdict.contour_max < 1e-9);  // Y is not part of the X block's contour
}

TEST_CASE("the path takes an axis back when it programs it after its INDP motion") {
  // The INDP motion to 0 is shorter than an increment: Y is owned and in position at once.
  const Run back = run("%i\nN10 G01 X10 Y10 F600\nN20 M30\n", 1, to(0.0, 100.0));
  CHECK_FALSE(back.error);
  REQUIRE_FALSE(back.cycles.empty());
  CHECK(back.cycles.back().x[1] == 10.0);
  CHECK(back.cycles.back().independent == 0);
  CHECK(back.verdict.ok());
  // The INDP motion left Y at 40, N20 starts Y where the interpreter has it (0): NC6103.
  const Run r = run("%i\nN10 G01 X30 F600\nN20 G01 Y40 X0\nN30 M30\n", 1, to(40.0, 100.0));
  REQUIRE(r.error);
  CHECK(r.error->id == std::string(channel::kIndpPathId));
  CHECK(r.error->line == 3);
}

TEST_CASE("a path block that moves an axis while its INDP motion runs stops with NC6103") {
  const Run r = run("%i\nN10 G01 X1 Y1 F600\nN20 M30\n", 1, to(40.0, 5.0));
  REQUIRE(r.error);
  CHECK(r.error->id == std::string(channel::kIndpPathId));
  CHECK(r.error->message.find("#WAIT INDP") != std::string::npos);
  CHECK(r.cycles.empty());
}

TEST_CASE("the INDP target beyond the soft limit is refused before the axis moves") {
  const core::SourceFile file("t.nc", "%i\nN10 M30\n");
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m, interp::Options{});
  program::ProgramSource src(in, m);
  channel::Channel ch(channel::channel_config(m, 0.001), src);
  const double limit = m.axes[1].soft_limits.pos;
  const auto e = ch.indp().command(1, to(limit + 1.0, 10.0));
  REQUIRE(e);
  CHECK(e->id == "NC5502");
  CHECK_FALSE(ch.indp().owned(1));
}

TEST_CASE("M / H functions are output in the cycle the next block starts, in program order") {
  const core::SourceFile file("t.nc",
                              "%t\nN10 G01 X10 F3000\nN20 M50\nN30 X20\nN40 H7 M51\nN50 M30\n");
  const machines::Machine& m = interp::test::machine("portal_3x");
  interp::Interpreter in(file, m, interp::Options{});
  program::ProgramSource src(in, m);
  channel::Channel ch(channel::channel_config(m, 0.001), src);
  std::vector<channel::TechOutput> out;
  double t_x20_start = -1.0;
  ipo::Status s;
  while ((s = ch.step()) == ipo::Status::running) {
    if (t_x20_start < 0.0 && ch.cycle().line == 4) t_x20_start = ch.cycle().t;
    out.insert(out.end(), ch.tech_outputs().begin(), ch.tech_outputs().end());
  }
  out.insert(out.end(), ch.tech_outputs().begin(), ch.tech_outputs().end());
  CHECK(s == ipo::Status::finished);
  REQUIRE(out.size() == 3);
  CHECK(out[0].kind == interp::TechKind::m);
  CHECK(out[0].value == 50.0);
  CHECK(out[0].line == 3);
  CHECK(out[0].t == doctest::Approx(t_x20_start));
  CHECK(out[1].line == 5);
  CHECK(out[2].line == 5);
  CHECK(out[1].t >= out[0].t);
}
