// G74 in the channel (--- static-saw, docs/homing.md): each axis drives to P-AXIS-00152 at
// P-AXIS-00219 (capped at P-AXIS-00212) as a PTP motion with its own slope, the lowest order
// first, equal orders together; the path stands meanwhile and goes on from the homed position.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
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

using Run = channel::test::AuditedRun;

// portal_3x with X homing to 100 at 50 mm/s, Y to 50 at 25 mm/s, Z to -20 at 10 mm/s.
machines::Machine homing_machine() {
  machines::Machine m = interp::test::machine("portal_3x");
  m.axes[0].reference_position = 100.0;
  m.axes[0].homing_velocity = 50.0;
  m.axes[1].reference_position = 50.0;
  m.axes[1].homing_velocity = 25.0;
  m.axes[2].reference_position = -20.0;
  m.axes[2].homing_velocity = 10.0;
  return m;
}

Run run(const std::string& program, const machines::Machine& m) {
  const core::SourceFile file("t.nc", program);
  interp::Interpreter in(file, m, interp::Options{});
  program::ProgramSource src(in, m);
  channel::ChannelConfig cfg = channel::channel_config(m, 0.001);
  audit::Audit audit(cfg.path.axes, cfg.path.channel.t_cycle, cfg.path.start);
  channel::test::Recorder rec;
  channel::test::AuditedRecorder tee(&audit, &rec);
  channel::Channel ch(std::move(cfg), src, &tee);
  src.answer_positions_from(&ch.axes().command);  // as run and time wire it
  return channel::test::finish(ch, rec, audit);
}

// Index of the first cycle in which axis `i` moves (|v| > 0), or cycles.size().
std::size_t first_moving(const std::vector<ipo::Cycle>& cycles, std::size_t i) {
  for (std::size_t k = 0; k < cycles.size(); ++k)
    if (std::fabs(cycles[k].v[i]) > 0.0) return k;
  return cycles.size();
}

// Index of the last cycle in which axis `i` moves within cycles [0, end).
std::size_t last_moving(const std::vector<ipo::Cycle>& cycles, std::size_t i, std::size_t end) {
  std::size_t last = 0;
  for (std::size_t k = 0; k < end; ++k)
    if (std::fabs(cycles[k].v[i]) > 0.0) last = k;
  return last;
}

double peak_v(const std::vector<ipo::Cycle>& cycles, std::size_t i, std::size_t end) {
  double v = 0.0;
  for (std::size_t k = 0; k < end; ++k)
    v = std::max(v, std::fabs(cycles[k].v[i]));
  return v;
}

}  // namespace

TEST_CASE("G74 Z1 X2 Y2: Z homes first, then X and Y together, each at its P-AXIS-00219") {
  const Run r = run("%h\nN10 G74 Z1 X2 Y2\nN20 G01 X110 F600\nN30 M30\n", homing_machine());
  REQUIRE(r.status == ipo::Status::finished);
  CHECK_FALSE(r.error);
  CHECK(r.verdict.ok());
  // The homing cycles carry the G74 line (`time --blocks` counts them there).
  std::size_t end = 0;
  while (end < r.cycles.size() && r.cycles[end].line == 2)
    ++end;
  REQUIRE(end > 0);
  REQUIRE(end < r.cycles.size());
  CHECK(r.cycles[end].line == 3);
  const std::size_t z0 = first_moving(r.cycles, 2);
  const std::size_t x0 = first_moving(r.cycles, 0);
  const std::size_t y0 = first_moving(r.cycles, 1);
  CHECK(z0 < x0);
  CHECK(x0 == y0);                            // equal numbers home together
  CHECK(last_moving(r.cycles, 2, end) < x0);  // Z in position before X starts
  CHECK(r.cycles[end - 1].x[0] == doctest::Approx(100.0));
  CHECK(r.cycles[end - 1].x[1] == doctest::Approx(50.0));
  CHECK(r.cycles[end - 1].x[2] == doctest::Approx(-20.0));
  CHECK(peak_v(r.cycles, 0, end) == doctest::Approx(50.0).epsilon(1e-6));
  CHECK(peak_v(r.cycles, 1, end) == doctest::Approx(25.0).epsilon(1e-6));
  CHECK(peak_v(r.cycles, 2, end) == doctest::Approx(10.0).epsilon(1e-6));
  // At least the travel at the homing velocity: X 100 mm at 50 mm/s after Z 20 mm at 10 mm/s.
  CHECK(static_cast<double>(end) * 0.001 > 2.0 + 2.0);
  // The path goes on from the homed position: X 100 -> 110, Y and Z stay.
  CHECK(r.cycles.back().x[0] == doctest::Approx(110.0));
  CHECK(r.cycles.back().x[1] == doctest::Approx(50.0));
  CHECK(r.cycles.back().x[2] == doctest::Approx(-20.0));
}

TEST_CASE("G74 caps P-AXIS-00219 at P-AXIS-00212 and homes an axis already there at once") {
  machines::Machine m = homing_machine();
  m.axes[0].homing_velocity = 10.0 * m.axes[0].dynamics.v_max;
  m.axes[0].reference_position = 600.0;  // long enough to reach P-AXIS-00212
  const Run r = run("%h\nN10 G74 X1\nN20 G74 X1\nN30 M30\n", m);
  REQUIRE(r.status == ipo::Status::finished);
  CHECK(r.verdict.ok());
  CHECK(peak_v(r.cycles, 0, r.cycles.size()) ==
        doctest::Approx(m.axes[0].dynamics.v_max).epsilon(1e-6));
  CHECK(r.cycles.back().x[0] == doctest::Approx(600.0));
  // N20: X stands on its reference point; homing it again moves nothing.
  std::size_t n20 = 0;
  for (std::size_t k = 0; k < r.cycles.size(); ++k)
    if (r.cycles[k].line == 3) {
      CHECK(r.cycles[k].v[0] == 0.0);
      ++n20;
    }
  CHECK(n20 <= 3);
}

TEST_CASE("G74 to a P-AXIS-00152 beyond the soft limit stops at the G74 line before X moves") {
  machines::Machine m = homing_machine();
  m.axes[0].reference_position = m.axes[0].soft_limits.pos + 10.0;
  const Run r = run("%h\nN10 G74 X1\nN20 M30\n", m);
  CHECK(r.status == ipo::Status::error);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC5502");
  CHECK(r.error->line == 2);
  CHECK(r.error->message.find("G74") != std::string::npos);
  for (const ipo::Cycle& c : r.cycles)
    CHECK(c.v[0] == 0.0);
}
