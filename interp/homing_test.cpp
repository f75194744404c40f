// What G74 may home, decided when the block is decoded (--- static-saw, docs/homing.md): 20137
// with an active coupling (isg-language.md l.148), NC9104 the conveyor / an encoder axis, NC9105
// a spindle (G74 S1), NC9106 no axis or an order number that is not a whole number >= 1.

#include <doctest/doctest.h>

#include <string>

#include "interp/test_support.hpp"

namespace {

using namespace ncsim;
using namespace ncsim::interp;

const std::string kSync = "%t\nS1[MC_TouchProbe Channel=1]\n#SYNC IN [CONV_VEL=6000]\n";

}  // namespace

TEST_CASE("G74 with an active coupling is error 20137 at its block: #SYNC IN, #TRAFO, #CAXTRACK") {
  const test::Run sync = test::run(kSync + "G01 X10 F600\nG74 Y1\nM30\n", "laser_portal");
  CHECK(sync.error_id == "20137");
  CHECK(sync.error_line == 5);
  CHECK(sync.error_message.find("#SYNC IN") != std::string::npos);
  const test::Run trafo = test::run("%t\n#TRAFO ON\nG74 X1\nM30\n", "delta_picker");
  CHECK(trafo.error_id == "20137");
  CHECK(trafo.error_line == 3);
  const test::Run cax = test::run("%t\n#CAXTRACK ON [AX=C]\nG74 Y1\nM30\n", "static_saw");
  CHECK(cax.error_id == "20137");
  CHECK(cax.error_message.find("#CAXTRACK") != std::string::npos);
  // After the coupling ends, G74 is fine again.
  CHECK(
      test::run(kSync + "G01 X10 F600\n#SYNC OUT\nG74 Y1\nM30\n", "laser_portal").error_id.empty());
  CHECK(test::run("%t\n#CAXTRACK ON [AX=C]\n#CAXTRACK OFF\nG74 Y1 C1\nM30\n", "static_saw")
            .error_id.empty());
}

TEST_CASE("G74 S1 (a spindle, here the conveyor) is NC9105 before its S is passed on") {
  const test::Run r = test::run("%t\nG74 S1\nM30\n", "laser_portal");
  CHECK(r.error_id == "NC9105");
  CHECK(r.error_line == 2);
  CHECK(r.lines.empty());  // no S1 technology function went out
}

TEST_CASE("G74 of the conveyor when it is an axis word (an encoder axis) is NC9104") {
  machines::Machine m = test::machine("laser_portal_encoder");
  machines::AxisParams* enc = nullptr;
  for (machines::AxisParams& a : m.axes)
    if (a.encoder_only) enc = &a;
  REQUIRE(enc != nullptr);
  enc->name = "B";  // an axis address, not the spindle's S
  const core::SourceFile file("test.nc", "%t\nG74 X1 B2\nM30\n");
  Interpreter in(file, m);
  while (in.next_decode_only()) {
  }
  REQUIRE(in.error() != nullptr);
  CHECK(in.error()->id == "NC9104");
  CHECK(in.error()->message.find("axis B") != std::string::npos);
}

TEST_CASE("G74 without an axis or with an order that is not a whole number >= 1 is NC9106") {
  CHECK(test::run("%t\nG74\nM30\n").error_id == "NC9106");
  CHECK(test::run("%t\nG74 X0\nM30\n").error_id == "NC9106");
  CHECK(test::run("%t\nG74 X1.5\nM30\n").error_id == "NC9106");
  CHECK(test::run("%t\nG74 X-1\nM30\n").error_id == "NC9106");
  const test::Run ok = test::run("%t\nG74 Z1 X2 Y2\nM30\n");
  CHECK(ok.error_id.empty());
  CHECK(ok.lines.at(0) == "2: HOME Z=1 X=2 Y=2");  // in the programmed order
}
