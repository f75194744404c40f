// Zero offsets (TF5200 PROG-206487307, G53..G59, G159) where the programmed values are not
// axis values: under #TRAFO ON (the kinematic's Cartesian TCP) and between #SYNC IN and
// #SYNC OUT (PCS1 on the belt). ncsim does not shift them there: a non-zero offset of an axis
// whose absolute value the block programs is NC4102 at that axis word (docs/interp.md "Zero
// offsets under #CS").
#include <doctest/doctest.h>

#include <string>

#include "interp/interpreter.hpp"
#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

/// The error that ends `text` on bundled machine `machine`, or nullopt.
std::optional<core::Diagnostic> error_of(const std::string& text, const std::string& machine) {
  const core::SourceFile file("t.nc", text);
  const machines::Machine& m = test::machine(machine);
  Interpreter interp(file, m, {});
  for (std::size_t n = 0; n < 10000 && interp.next_decode_only(); ++n) {
  }
  if (const auto* e = interp.error()) return *e;
  return std::nullopt;
}

/// True when `e` is NC4102 at `line` (and `column`, unless 0).
bool nc4102_at(const std::optional<core::Diagnostic>& e, std::uint32_t line,
               std::uint32_t column = 0) {
  return e && e->id == "NC4102" && e->loc.line == line && (column == 0 || e->loc.column == column);
}

const char* kTrafo = "%t\nV.G.NP[1].V.X = 10\nG54\n#KIN ID[37]\n#TRAFO ON\n";

TEST_CASE("a zero offset under #TRAFO ON is NC4102 at the axis word, naming offset and group") {
  const auto e = error_of(std::string(kTrafo) + "G01 Y1 X2 F600\nM30\n", "delta_picker");
  REQUIRE(nc4102_at(e, 6, 8));  // the X word
  CHECK(e->message.find("zero offset 10 of axis X (G54, V.G.NP[1].V.X) under #TRAFO ON") !=
        std::string::npos);
}

TEST_CASE("under #TRAFO ON an axis without offset, G53 or an incremental move run") {
  CHECK_FALSE(error_of(std::string(kTrafo) + "G01 Y1 Z-700 F600\nM30\n", "delta_picker"));
  CHECK_FALSE(error_of(std::string(kTrafo) + "G53\nG01 X2 F600\nM30\n", "delta_picker"));
  // G91: the offset enters at the next absolute value only (PROG-206487307), so nothing shifts.
  CHECK_FALSE(error_of(std::string(kTrafo) + "G91 G01 X2 F600\nM30\n", "delta_picker"));
}

TEST_CASE("under #TRAFO ON a G161 absolute circle centre with an offset is NC4102 too") {
  CHECK(nc4102_at(error_of(std::string(kTrafo) + "G161 G02 I5 J0 F600\nM30\n", "delta_picker"), 6));
}

TEST_CASE("G159=n names its group in the NC4102 text") {
  const auto e =
      error_of("%t\nV.G.NP[12].V.Y = -3\nG159=12\n#KIN ID[37]\n#TRAFO ON\nG01 Y1 F600\nM30\n",
               "delta_picker");
  REQUIRE(e);
  CHECK(e->message.find("(G159=12, V.G.NP[12].V.Y)") != std::string::npos);
}

const char* kSync =
    "%t\nV.G.NP[2].V.Y = 5\nG55\nS1[MC_TouchProbe Channel=1]\n#SYNC IN [CONV_VEL=6000]\n";

TEST_CASE("a zero offset between #SYNC IN and #SYNC OUT is NC4102 at the axis word") {
  const auto e = error_of(std::string(kSync) + "G01 X10 Y1 F600\n#SYNC OUT\nM30\n", "laser_portal");
  REQUIRE(nc4102_at(e, 6, 9));  // the Y word
  CHECK(e->message.find("under #SYNC IN") != std::string::npos);
  // X has no offset: it runs.
  CHECK_FALSE(error_of(std::string(kSync) + "G01 X10 F600\n#SYNC OUT\nM30\n", "laser_portal"));
}

TEST_CASE("after #SYNC OUT the zero offset shifts the axis again") {
  const test::Run r =
      test::run(std::string(kSync) + "G01 X10 F600\n#SYNC OUT\nG01 Y1\nM30\n", "laser_portal");
  REQUIRE_MESSAGE(r.error_id.empty(), r.error_message);
  bool shifted = false;
  for (const auto& l : r.lines)
    shifted = shifted || (l.rfind("8: G01", 0) == 0 && l.find("Y=6.0000") != std::string::npos);
  CHECK(shifted);
}

}  // namespace
}  // namespace ncsim::interp
