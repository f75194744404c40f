// The channel's slope P-CHAN-00071 `prog_start.slope.profile` through the planner: a program
// without #SLOPE runs on the list's profile, and `#SLOPE DEFAULT` returns to it
// (isg-language.md §5.5, PROG-207190411: "0 step, 1 trapez, 2 sin2, 3 HSC").

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "audit/time.hpp"
#include "core/source_file.hpp"
#include "interp/test_support.hpp"
#include "program/program_source.hpp"

namespace {

using namespace ncsim;

// portal_3x with P-CHAN-00071 = `profile`.
machines::Machine portal_with(machines::SlopeProfile profile) {
  machines::Machine m = interp::test::machine("portal_3x");
  m.channel.start_slope = profile;
  return m;
}

std::vector<planner::SlopeType> move_slopes(const std::string& text, const machines::Machine& m) {
  const core::SourceFile file("t.nc", text);
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  std::vector<planner::SlopeType> out;
  ipo::Item item;
  while (src.next(item))
    if (const auto* mv = std::get_if<planner::Move>(&item)) out.push_back(mv->slope);
  REQUIRE(src.error() == nullptr);
  return out;
}

audit::TimeResult time_of(const std::string& text, const machines::Machine& m) {
  const core::SourceFile file("t.nc", text);
  interp::Interpreter in(file, m);
  program::ProgramSource src(in, m);
  return audit::machining_time(program::machine_config(m, 0.001), src);
}

// portal_3x X: A+ = A- = 3000 mm/s^2 (P-AXIS-00001/00002), ramp times 60000 us, so the feed
// jerk J = 3000 / 0.06 = 50000 mm/s^3; T = 1 ms. A 1000 mm line at F6000 (100 mm/s):
//  STEP (acceleration-limited, planned with j = A / T, docs/planner.md):
//    L / v + v / A + A / j = 10 + 1/30 + 0.001 s;
//  TRAPEZ (jerk-limited; v = 100 < A^2 / J = 180, so A is not reached and each ramp takes
//    2 sqrt(v / J)): L / v + 2 sqrt(v / J) = 10 + 0.0894427 s.
constexpr double kStepTime = 1000.0 / 100.0 + 100.0 / 3000.0 + 0.001;
const double kTrapezTime = 1000.0 / 100.0 + 2.0 * std::sqrt(100.0 / 50000.0);

// The time of a cycle-rounded run is the closed form rounded up to the 1 ms cycle.
void check_rounded_time(const audit::TimeResult& r, double exact) {
  REQUIRE(r.status == ipo::Status::finished);
  CHECK(r.total >= exact - 1e-9);
  CHECK(r.total < exact + 0.001 + 1e-9);
}

}  // namespace

TEST_CASE("P-CHAN-00071 = 0: a program without #SLOPE is planned acceleration-limited (STEP)") {
  const machines::Machine m = portal_with(machines::SlopeProfile::step);
  const std::string program = "N10 G01 X1000 F6000\nN20 M30\n";
  CHECK(move_slopes(program, m) == std::vector{planner::SlopeType::step});
  check_rounded_time(time_of(program, m), kStepTime);
}

TEST_CASE("P-CHAN-00071 = 1: a program without #SLOPE is planned jerk-limited (TRAPEZ)") {
  const machines::Machine m = portal_with(machines::SlopeProfile::trapez);
  const std::string program = "N10 G01 X1000 F6000\nN20 M30\n";
  CHECK(move_slopes(program, m) == std::vector{planner::SlopeType::trapez});
  const audit::TimeResult r = time_of(program, m);
  check_rounded_time(r, kTrapezTime);
  CHECK(r.total > kStepTime + 0.05);  // the jerk limit costs 2 sqrt(v/J) - v/A - T = 55 ms
}

TEST_CASE("P-CHAN-00071 = 2: SIN2 is the start slope") {
  CHECK(move_slopes("N10 G01 X10 F6000\nN20 M30\n", portal_with(machines::SlopeProfile::sin2)) ==
        std::vector{planner::SlopeType::sin2});
}

TEST_CASE("#SLOPE DEFAULT returns to the list's P-CHAN-00071, not to STEP") {
  const std::string program =
      "N10 G01 X10 F6000\n"
      "N20 #SLOPE [TYPE=STEP]\n"
      "N30 X20\n"
      "N40 #SLOPE DEFAULT\n"
      "N50 X30\n"
      "N60 #SLOPE [TYPE=SIN2]\n"
      "N70 X40\n"
      "N80 #SLOPE DEFAULT\n"
      "N90 X1040\n"
      "N100 M30\n";
  using S = planner::SlopeType;
  CHECK(move_slopes(program, portal_with(machines::SlopeProfile::trapez)) ==
        std::vector{S::trapez, S::step, S::trapez, S::sin2, S::trapez});
  CHECK(move_slopes(program, portal_with(machines::SlopeProfile::step)) ==
        std::vector{S::step, S::step, S::step, S::sin2, S::step});
  // The restored slope is what the planner uses: a line after #SLOPE DEFAULT takes the closed-form
  // time of the list's profile.
  const std::string alone =
      "N10 #SLOPE [TYPE=STEP]\nN20 #SLOPE DEFAULT\nN30 G01 X1000 F6000\nN40 M30\n";
  check_rounded_time(time_of(alone, portal_with(machines::SlopeProfile::trapez)), kTrapezTime);
  check_rounded_time(time_of(alone, portal_with(machines::SlopeProfile::step)), kStepTime);
}
