// The slope around the synchronisation (issue 14, sync-feed; seed 004 l.280 "When #SYNC IN is
// programmed, the program automatically switches over to a jerk-limited slope. The
// acceleration profile cannot be switched over within the #SYNC IN/OUT function").

#include <doctest/doctest.h>

#include <string>
#include <variant>
#include <vector>

#include "interp/test_support.hpp"

namespace {

using namespace ncsim;
using namespace ncsim::interp;

std::vector<SlopeType> motion_slopes(
    const std::string& text, const machines::Machine& machine = test::machine("laser_portal")) {
  const core::SourceFile file("test.nc", text);
  Interpreter interp(file, machine);
  std::vector<SlopeType> out;
  while (auto c = interp.next_decode_only())
    if (const auto* m = std::get_if<Motion>(&c->body)) out.push_back(m->modal.slope);
  REQUIRE(interp.error() == nullptr);
  return out;
}

}  // namespace

TEST_CASE("the jerk-limited slope is forced from #SYNC IN to #SYNC OUT, the program's after it") {
  const std::vector<SlopeType> s = motion_slopes(
      "%t\n#SLOPE [TYPE=STEP]\nG01 X1 F600\nS1[MC_TouchProbe Channel=1]\n"
      "#SYNC IN [CONV_VEL=6000]\nG01 X10 F600\nG01 X20\n#SYNC OUT\nG01 X30\nM30\n");
  REQUIRE(s.size() == 4);
  CHECK(s[0] == SlopeType::step);
  CHECK(s[1] == SlopeType::trapez);  // the catch-up
  CHECK(s[2] == SlopeType::trapez);  // machining in PCS1
  CHECK(s[3] == SlopeType::step);    // the channel's / program's slope again
}

TEST_CASE("#SLOPE inside #SYNC IN/OUT is refused (NC4506) and allowed again after #SYNC OUT") {
  const std::string head =
      "%t\nS1[MC_TouchProbe Channel=1]\n#SYNC IN [CONV_VEL=6000]\nG01 X10 F600\n";
  CHECK(test::run(head + "#SLOPE [TYPE=STEP]\n#SYNC OUT\nM30\n", "laser_portal").error_id ==
        "NC4506");
  CHECK(test::run(head + "#SYNC OUT\n#SLOPE [TYPE=STEP]\nG01 X0\nM30\n", "laser_portal")
            .error_id.empty());
}

TEST_CASE(
    "the start slope is the channel's P-CHAN-00071; #SLOPE DEFAULT restores it, also after "
    "#SYNC OUT; #SLOPE [TYPE=STEP] is STEP on any channel") {
  machines::Machine m = test::machine("laser_portal");
  m.channel.start_slope = machines::SlopeProfile::sin2;
  const std::vector<SlopeType> s = motion_slopes(
      "%t\nG01 X1 F600\n#SLOPE [TYPE=TRAPEZ]\nG01 X2\n#SLOPE DEFAULT\nG01 X3\n#SLOPE "
      "[TYPE=STEP]\nG01 X4\n"
      "S1[MC_TouchProbe Channel=1]\n#SYNC IN [CONV_VEL=6000]\nG01 X10 F600\n#SYNC OUT\n"
      "#SLOPE DEFAULT\nG01 X30\nM30\n",
      m);
  REQUIRE(s.size() == 6);
  CHECK(s[0] == SlopeType::sin2);    // no #SLOPE yet: P-CHAN-00071
  CHECK(s[1] == SlopeType::trapez);  // #SLOPE [TYPE=TRAPEZ]
  CHECK(s[2] == SlopeType::sin2);    // #SLOPE DEFAULT
  CHECK(s[3] == SlopeType::step);    // #SLOPE [TYPE=STEP]
  CHECK(s[4] == SlopeType::trapez);  // synchronised: the forced jerk-limited slope
  CHECK(s[5] == SlopeType::sin2);    // #SLOPE DEFAULT after #SYNC OUT
  // The bundled laser portal has no P-CHAN-00071: STEP, and DEFAULT returns to STEP.
  const std::vector<SlopeType> plain =
      motion_slopes("%t\nG01 X1 F600\n#SLOPE [TYPE=SIN2]\nG01 X2\n#SLOPE DEFAULT\nG01 X3\nM30\n");
  CHECK(plain == std::vector{SlopeType::step, SlopeType::sin2, SlopeType::step});
}

TEST_CASE("#SLOPE DEFAULT inside #SYNC IN/OUT is refused like any #SLOPE (NC4506)") {
  CHECK(test::run("%t\nS1[MC_TouchProbe Channel=1]\n#SYNC IN [CONV_VEL=6000]\nG01 X10 F600\n"
                  "#SLOPE DEFAULT\n#SYNC OUT\nM30\n",
                  "laser_portal")
            .error_id == "NC4506");
}
