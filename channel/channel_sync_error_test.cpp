// The channel after a run-time error raised while synchronised (seed 004 §2.3; tracking/sync_error,
// channel/after_error.cpp; docs/conveyor.md "Errors while synchronised"): the path brakes to
// 0 in PCS1, the machine moves on with the belt and stops before X's soft limit; a belt that
// stands stops it with it. Laser portal: X soft limits [-200, 4000] mm, the conveyor workspace
// narrowed to X <= 3000 mm so that NC9052 comes 1000 mm before the soft limit.

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
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;
constexpr double kBelt = 300.0;  // [mm/s]

// The catch-up, then a slow PCS1 line (10 mm/s) the belt carries across X = 3000 mm.
const char* const kProgram =
    "%t\n"                             // 1
    "N10 G01 X0 Y0 Z0 F6000\n"         // 2
    "N20 #SYNC IN [CONV_VEL=18000]\n"  // 3
    "N30 G01 X100 Y50 F6000\n"         // 4: the catch-up
    "N40 G01 X400 F600\n"              // 5: 10 mm/s in PCS1 for 30 s
    "N50 #SYNC OUT\n"                  // 6
    "N60 M30\n";                       // 7

struct After {
  ipo::Status status = ipo::Status::finished;
  std::vector<double> t, x, x_rel, v_path, vx;
  std::optional<channel::RunTimeError> error;
  std::string note;
  bool audit_ok = false;
  std::string audit_first;
};

After run(long belt_stop_at = 0) {
  machines::Machine m = interp::test::machine("laser_portal");
  m.channel.conveyor->workspace.upper[0] = 3000.0;
  tracking::test::FakePort port(kBelt);
  port.latch_at_ = 1;
  if (belt_stop_at > 0) {
    port.v_change_at_ = belt_stop_at;
    port.v_new_ = 0.0;
  }
  channel::ChannelConfig cfg = channel::channel_config(m, kT);
  audit::Audit audit(cfg.path.axes, kT, cfg.path.start);
  channel::test::ConveyorRig rig(kProgram, m, cfg, &port, &audit);
  audit.set_setpoints(&rig.ch.setpoints());
  const channel::Channel& ch = rig.ch;
  After r;
  r.status = channel::test::run_to_end(
      rig.ch,
      [&] {
        const tracking::ConveyorSync& s = *ch.conveyor_sync();
        r.t.push_back(ch.cycle().t);
        r.x.push_back(ch.axes().command[0]);
        r.x_rel.push_back(ch.cycle().x[0]);
        r.v_path.push_back(ch.cycle().path.v);
        r.vx.push_back(ch.setpoints()[0].v);
        (void)s;
      },
      100'000);
  r.error = ch.run_time_error();
  r.note = ch.after_error_note();
  r.audit_ok = audit.verdict().ok();
  if (!audit.verdict().violations.empty()) {
    const audit::Violation& v = audit.verdict().violations.front();
    r.audit_first =
        std::to_string(v.t) + " " + std::to_string(v.value) + " > " + std::to_string(v.limit);
  }
  return r;
}

std::size_t index_at(const After& r, double t) {
  return static_cast<std::size_t>(std::lower_bound(r.t.begin(), r.t.end(), t - 1e-9) - r.t.begin());
}

}  // namespace

TEST_CASE(
    "an error while synchronised: the path brakes, the tool follows the belt and stops "
    "before the soft limit, the run ends with the error") {
  const After r = run();
  REQUIRE(r.status == ipo::Status::error);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC9052");  // the original error: id, line, time
  CHECK(r.error->line == 5);
  MESSAGE(r.note);
  CHECK(r.note.find("NC9052") != std::string::npos);
  CHECK(r.note.find("soft limit") != std::string::npos);
  // The stream goes on after the error's time.
  const std::size_t e = index_at(r, r.error->t);
  REQUIRE(e < r.t.size());
  CHECK(r.x[e] > 3000.0);
  CHECK(r.x[e - 1] <= 3000.0);
  REQUIRE(r.t.size() > e + 1000);
  // The path brakes to 0 in PCS1 within a fraction of a second, then stands on the workpiece.
  const std::size_t b = index_at(r, r.error->t + 0.5);
  CHECK(r.v_path[e] > 9.0);
  for (std::size_t k = b; k < r.t.size(); ++k)
    CHECK(r.v_path[k] == 0.0);
  // While the path stands and the axes follow the belt, X moves at the belt's velocity.
  const std::size_t f = index_at(r, r.error->t + 1.0);
  CHECK(r.x[f + 1] - r.x[f] == doctest::Approx(kBelt * kT).epsilon(1e-9));
  // The machine stops before X's soft limit 4000 mm, within a cycle's travel of it.
  const double x_max = *std::max_element(r.x.begin(), r.x.end());
  CHECK(x_max <= 4000.0);
  CHECK(x_max >= 4000.0 - kBelt * kT - 1e-6);
  CHECK(r.vx.back() == 0.0);
  CHECK(r.x.back() == x_max);
  // About (4000 - 3000) / 300 s of following (less the stop's own distance).
  CHECK(r.t.back() - r.error->t == doctest::Approx(1000.0 / kBelt).epsilon(0.02));
  if (!r.audit_ok) MESSAGE("audit: " << r.audit_first);
  CHECK(r.audit_ok);  // no limit exceeded after the error either
}

TEST_CASE(
    "an error while synchronised with the belt stopped meanwhile: the machine stands "
    "with the belt and the run ends at once") {
  // The belt stops 1 s after NC9052 (10 s of belt to X = 3000, the catch-up before).
  const After free = run();
  REQUIRE(free.error);
  const long stop_at = static_cast<long>(std::lround((free.error->t + 1.0) / kT));
  const After r = run(stop_at);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC9052");
  CHECK(r.error->t == free.error->t);
  MESSAGE(r.note);
  CHECK(r.note.find("stood with the belt") != std::string::npos);
  const double x_stop = r.x.back();
  CHECK(x_stop < 4000.0 - 100.0);
  CHECK(r.t.back() <= static_cast<double>(stop_at) * kT + 0.002);
}

TEST_CASE(
    "an error while synchronised on a static unit (x_virtual) ends the run at once, without "
    "the following of 004 §2.3") {
  // docs/conveyor.md "On a static unit (x_virtual): decision, the run ends at once": no real
  // X could follow the belt. The belt steps from 100 to 400 mm/s (above 1.1 x CONV_VEL 300)
  // while the saw runs its line with the belt feed: 50653, and the run ends in that cycle.
  const machines::Machine m = interp::test::machine("static_saw");
  tracking::test::FakePort port(100.0);
  port.latch_at_ = 1;
  port.v_change_at_ = 3000;
  port.v_new_ = 400.0;
  channel::test::ConveyorRig rig(
      "%t\nN10 G0 X0 Y0 C0\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G0 X0 Y0\nN40 G1 X-2000 Y0 F100\n"
      "N50 #SYNC OUT\nN60 M30\n",
      m, channel::channel_config(m, kT), &port);
  std::vector<double> t;
  bool tracking_before = false;
  const ipo::Status status = channel::test::run_to_end(
      rig.ch,
      [&] {
        t.push_back(rig.ch.cycle().t);
        if (rig.ch.cycle().t < 2.9) tracking_before = rig.ch.conveyor_sync()->synchronised();
      },
      100'000);
  CHECK(tracking_before);  // the error comes while synchronised, on N40
  REQUIRE(status == ipo::Status::error);
  const std::optional<channel::RunTimeError> error = rig.ch.run_time_error();
  REQUIRE(error);
  CHECK(error->id == "50653");
  CHECK(error->line == 5);
  CHECK(rig.ch.after_error_note().empty());
  REQUIRE_FALSE(t.empty());
  CHECK(t.back() <= error->t + 1e-9);  // no cycle after the error's
}
