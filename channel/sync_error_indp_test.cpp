// An error while synchronised with an INDP axis moving (seed 004 §2.3; trafo-feed, issue 14;
// channel/after_error_indp.cpp; docs/conveyor.md "Errors while synchronised", "With INDP
// axes"): the INDP axis brakes jerk-limited on its own ramp, the path axes follow the belt and
// brake before X's soft limit, the run ends with the original error when everything stands.
// Laser portal: X soft limits [-200, 4000] mm, the conveyor workspace narrowed to X <= 3000 mm
// so that NC9052 comes 1000 mm before the soft limit; Z [-100, 300] mm.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "channel/channel.hpp"
#include "channel/channel_test_support.hpp"
#include "interp/test_support.hpp"
#include "tracking/test_port.hpp"

namespace {

using namespace ncsim;

constexpr double kT = 0.001;
constexpr double kBelt = 300.0;  // [mm/s]

// The catch-up, Z on its own at 20 mm/s for 12.5 s, a slow PCS1 line the belt carries across
// X = 3000 mm after about 10 s.
const char* const kProgram =
    "%t\n"                                    // 1
    "N10 G01 X0 Y0 Z0 F6000\n"                // 2
    "N20 #SYNC IN [CONV_VEL=18000]\n"         // 3
    "N30 G01 X100 Y50 F6000\n"                // 4: the catch-up
    "N35 Z[INDP_ASYN G01 POS250 FEED1200]\n"  // 5: Z independent
    "N40 G01 X400 F600\n"                     // 6: 10 mm/s in PCS1 for 30 s
    "N50 #WAIT INDP [Z]\n"                    // 7
    "N60 #SYNC OUT\n"                         // 8
    "N70 M30\n";                              // 9

struct After {
  ipo::Status status = ipo::Status::finished;
  std::vector<double> t, x, z, vx, vz, az;
  std::optional<channel::RunTimeError> error;
  std::string note;
  audit::Verdict verdict;
};

After run(const char* program = kProgram, long belt_stop_at = 0) {
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
  channel::test::ConveyorRig rig(program, m, cfg, &port, &audit);
  audit.set_setpoints(&rig.ch.setpoints());
  const channel::Channel& ch = rig.ch;
  After r;
  r.status = channel::test::run_to_end(
      rig.ch,
      [&] {
        r.t.push_back(ch.cycle().t);
        r.x.push_back(ch.axes().command[0]);
        r.z.push_back(ch.axes().command[2]);
        r.vx.push_back(ch.setpoints()[0].v);
        r.vz.push_back(ch.setpoints()[2].v);
        r.az.push_back(ch.setpoints()[2].a);
      },
      100'000);
  r.error = ch.run_time_error();
  r.note = ch.after_error_note();
  r.verdict = audit.verdict();
  if (r.error)
    MESSAGE(r.error->id << " line " << r.error->line << " t " << r.error->t << ": "
                        << r.error->message);
  for (const audit::Violation& v : r.verdict.violations)
    MESSAGE("audit: axis " << int(v.axis) << " t " << v.t << " value " << v.value << " limit "
                           << v.limit);
  return r;
}

std::size_t index_at(const After& r, double t) {
  return static_cast<std::size_t>(std::lower_bound(r.t.begin(), r.t.end(), t - 1e-9) - r.t.begin());
}

}  // namespace

TEST_CASE(
    "an error while synchronised with an INDP axis moving: it brakes on its own ramp, the "
    "path axes follow the belt to the soft limit, the run ends with the error") {
  const After r = run();
  REQUIRE(r.status == ipo::Status::error);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC9052");  // the original error: id, line
  CHECK(r.error->line == 6);
  MESSAGE(r.note);
  CHECK(r.note.find("INDP axis Z braked on its own ramp") != std::string::npos);
  CHECK(r.note.find("soft limit") != std::string::npos);
  const std::size_t e = index_at(r, r.error->t);
  REQUIRE(e < r.t.size());
  // Z was moving at 20 mm/s when the error came, and stands within 0.1 s, short of its target.
  CHECK(r.vz[e - 1] == doctest::Approx(20.0).epsilon(1e-6));
  const std::size_t zs = index_at(r, r.error->t + 0.1);
  REQUIRE(zs < r.t.size());
  CHECK(r.vz[zs] == 0.0);
  CHECK(r.z.back() == r.z[zs]);
  CHECK(r.z.back() < 250.0);
  CHECK(r.z.back() > r.z[e]);  // it braked forward, not back
  // Z decelerates (a < 0) over several cycles: a ramp, not a jump to rest.
  std::size_t braking = 0;
  for (std::size_t k = e; k < zs; ++k)
    if (r.az[k] < 0.0) ++braking;
  CHECK(braking >= 2);
  // X follows the belt meanwhile and long after Z stood, and stops before its soft limit.
  const std::size_t f = index_at(r, r.error->t + 1.0);
  REQUIRE(f + 1 < r.t.size());
  CHECK(r.x[f + 1] - r.x[f] == doctest::Approx(kBelt * kT).epsilon(1e-9));
  const double x_max = *std::max_element(r.x.begin(), r.x.end());
  CHECK(x_max <= 4000.0);
  CHECK(x_max >= 4000.0 - kBelt * kT - 1e-6);
  CHECK(r.vx.back() == 0.0);
  CHECK(r.t.back() - r.error->t == doctest::Approx(1000.0 / kBelt).epsilon(0.02));
  CHECK(r.verdict.violation_count == 0);  // Z's own limits and the path axes' hold
}

TEST_CASE(
    "INDP while synchronised: an axis the belt does not move (Z) runs on its own, POS in MCS; "
    "one the belt moves (X) is not supported and ends the run at once") {
  SUBCASE("Z: the program runs through, Z reaches its target while X follows the belt") {
    const After r =
        run("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
            "N35 Z[INDP_ASYN G01 POS50 FEED3000]\nN40 G01 X150 F600\nN50 #WAIT INDP [Z]\n"
            "N55 G04 0.1\nN60 #SYNC OUT\nN70 M30\n");
    REQUIRE_FALSE(r.error);
    REQUIRE(r.status == ipo::Status::finished);
    CHECK(r.z.back() == doctest::Approx(50.0));
    CHECK(*std::max_element(r.vz.begin(), r.vz.end()) == doctest::Approx(50.0));
    CHECK(r.verdict.violation_count == 0);
  }
  SUBCASE("X: NC6001 at its line; the run ends at once, no axis jumps to the refused target") {
    const After r =
        run("%t\nN10 G01 X0 Y0 Z0 F6000\nN20 #SYNC IN [CONV_VEL=18000]\nN30 G01 X100 Y50 F6000\n"
            "N35 X[INDP_ASYN G01 POS250 FEED3000]\nN40 G01 Y100 F600\nN50 #SYNC OUT\nN60 M30\n");
    REQUIRE(r.error);
    CHECK(r.error->id == "NC6001");
    CHECK(r.error->line == 5);
    CHECK(r.error->message.find("while synchronised (PCS1)") != std::string::npos);
    CHECK(r.note.empty());  // no synchronisation kept (decision, docs/conveyor.md)
    CHECK(r.t.back() <= r.error->t + 1e-9);
    CHECK(r.verdict.violation_count == 0);
  }
}

TEST_CASE(
    "an error while synchronised with an INDP axis, the belt stopped meanwhile: the machine "
    "stands with the belt once the INDP axis stands too") {
  const After free = run();
  REQUIRE(free.error);
  const long stop_at = static_cast<long>(std::lround((free.error->t + 1.0) / kT));
  const After r = run(kProgram, stop_at);
  REQUIRE(r.error);
  CHECK(r.error->id == "NC9052");
  CHECK(r.error->t == free.error->t);
  MESSAGE(r.note);
  CHECK(r.note.find("stood with the belt") != std::string::npos);
  CHECK(r.note.find("INDP axis Z braked on its own ramp") != std::string::npos);
  CHECK(r.z.back() == free.z.back());  // Z stood long before, where it stood without the stop
  CHECK(r.vz.back() == 0.0);
  CHECK(r.x.back() < 4000.0 - 100.0);
  CHECK(r.t.back() <= static_cast<double>(stop_at) * kT + 0.002);
  // (No audit here: the FakePort's belt steps from 300 mm/s to 0 in one cycle, and X with it.)
}
