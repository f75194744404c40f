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

std::vector<SlopeType> motion_slopes(const std::string& text) {
  const core::SourceFile file("test.nc", text);
  Interpreter interp(file, test::machine("laser_portal"));
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
