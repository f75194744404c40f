// Issue 9's interpreter-semantic lows, each from its reproduction: the word that is wrong is
// blamed, values that cannot be are refused, and what the manual allows is a warning.
#include <doctest/doctest.h>

#include <sstream>

#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

using test::run;

const char* kProbe = "%t\nS1[MC_TouchProbe Channel=1]\n";

TEST_CASE("#SYNC IN [CONVEYOR=Q9] blames the word: no such axis [NC4103]") {
  auto r =
      run(std::string(kProbe) + "#SYNC IN [CONVEYOR=Q9, CONV_VEL=6000]\nM30\n", "laser_portal");
  CHECK(r.error_id == "NC4103");
  CHECK(r.error_line == 3);
  CHECK(r.error_message.find("CONVEYOR=Q9") != std::string::npos);
}

TEST_CASE("#SYNC IN [CONVEYOR=X] blames the word: X is no conveyor axis [NC4501]") {
  auto r = run(std::string(kProbe) + "#SYNC IN [CONVEYOR=X, CONV_VEL=6000]\nM30\n", "laser_portal");
  CHECK(r.error_id == "NC4501");
  CHECK(r.error_message.find("CONVEYOR=X is not a conveyor axis") != std::string::npos);
}

TEST_CASE("CONV_VEL 0 or negative is NC4030; a duplicated CONV_VEL is NC4507") {
  CHECK(run(std::string(kProbe) + "#SYNC IN [CONV_VEL=0]\nM30\n", "laser_portal").error_id ==
        "NC4030");
  CHECK(run(std::string(kProbe) + "#SYNC IN [CONV_VEL=-100]\nM30\n", "laser_portal").error_id ==
        "NC4030");
  auto dup =
      run(std::string(kProbe) + "#SYNC IN [CONV_VEL=6000 CONV_VEL=3000]\nM30\n", "laser_portal");
  CHECK(dup.error_id == "NC4507");
  CHECK(dup.error_message.find("CONV_VEL is given twice") != std::string::npos);
}

TEST_CASE("FEED_CONT is mm/min in the program and mm/s in the command") {
  auto r = run(std::string(kProbe) +
                   "#SYNC IN [CONV_VEL=6000 FEED_CONT=600]\nG01 X1 F600\n#SYNC OUT [FEED_CONT=60]\n"
                   "M30\n",
               "laser_portal");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(2) == "3: SYNC_IN S conv_vel=100.0000 latch=0.0000 FEED_CONT=10.0000");
  CHECK(r.lines.at(5) == "5: SYNC_OUT FEED_CONT=1.0000");
  CHECK(run(std::string(kProbe) + "#SYNC IN [CONV_VEL=6000 FEED_CONT=-1]\nM30\n", "laser_portal")
            .error_id == "NC4030");
}

TEST_CASE("Options::conv_vel replaces every #SYNC IN's CONV_VEL, whatever its unit (sweep)") {
  Options o;
  o.conv_vel = 250.0;  // [mm/s]
  auto r = run(std::string(kProbe) +
                   "#SYNC IN [CONV_VEL=6000]\nG01 X1 F600\n#SYNC OUT\n"
                   "S1[MC_TouchProbe Channel=1]\n#SYNC IN [CONV_VEL=2 VEL_RESOLUTION=m/s]\nM30\n",
               "laser_portal", o);
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(2) == "3: SYNC_IN S conv_vel=250.0000 latch=0.0000");
  bool second = false;
  for (const std::string& l : r.lines)
    second = second || l == "7: SYNC_IN S conv_vel=250.0000 latch=0.0000";
  CHECK(second);
  // The programmed word is still checked where it stands; 50587 takes the value used
  // (laser_portal's X: 1000 mm/s).
  auto zero = run(std::string(kProbe) + "#SYNC IN [CONV_VEL=0]\nM30\n", "laser_portal", o);
  CHECK(zero.error_id == "NC4030");
  CHECK(zero.error_line == 3);
  // A missing or doubled CONV_VEL stays NC4507: the option replaces a value, not the word.
  CHECK(run(std::string(kProbe) + "#SYNC IN\nM30\n", "laser_portal", o).error_id == "NC4507");
  auto dup =
      run(std::string(kProbe) + "#SYNC IN [CONV_VEL=6000 CONV_VEL=3000]\nM30\n", "laser_portal", o);
  CHECK(dup.error_id == "NC4507");
  CHECK(dup.error_line == 3);
  o.conv_vel = 1200.0;
  auto fast = run(std::string(kProbe) + "#SYNC IN [CONV_VEL=6000]\nM30\n", "laser_portal", o);
  CHECK(fast.error_id == "50587");
  CHECK(fast.error_line == 3);
}

TEST_CASE("M30 while synchronised is warning NC4516, not silence (seed 004 §2.1.1.2)") {
  core::SourceFile file("test.nc",
                        std::string(kProbe) + "#SYNC IN [CONV_VEL=6000]\nG01 X1 F600\nM30\n");
  Interpreter interp(file, test::machine("laser_portal"));
  while (interp.next_decode_only()) {
  }
  CHECK(interp.error() == nullptr);
  bool warned = false;
  for (const auto& d : interp.diagnostics().items())
    warned = warned || (d.id == "NC4516" && d.loc.line == 5);
  CHECK(warned);
}

TEST_CASE("trace names the subroutine file of its lines; main-program lines stay bare") {
  core::SourceFile file = core::SourceFile::load(test::source_root() / "interp/testdata/l_main.nc");
  std::ostringstream out;
  core::DiagnosticList diags;
  write_trace(file, test::machine(), TraceOptions{}, out, diags);
  std::istringstream lines(out.str());
  std::string first, second;
  std::getline(lines, first);
  std::getline(lines, second);
  CHECK(first.starts_with("sub_move.nc:2: G00 X=4.0000"));
  CHECK(second.starts_with("5: G00 X=4.0000 Y=8.0000"));
}

TEST_CASE("check finds an arc whose extent leaves the soft limits although its ends do not") {
  // portal_3x: X in [-1, 800] mm. A full circle from X=610 around X=810 reaches X=1010.
  core::SourceFile file("test.nc", "%t\nG00 X610 Y100\nG02 X610 Y100 I200 J0 F600\nM30\n");
  const auto diags = check_semantics(file, test::machine(), {});
  bool found = false;
  for (const auto& d : diags.items()) {
    found = found || (d.id == "NC4601" && d.loc.line == 3 &&
                      d.message.find("the arc reaches X=1010") != std::string::npos);
  }
  CHECK(found);
  // A half circle that stays inside is fine; one crossing only through its bulge is not.
  core::SourceFile inside("test.nc", "%t\nG00 X100 Y100\nG02 X300 Y100 I100 J0 F600\nM30\n");
  CHECK(check_semantics(inside, test::machine(), {}).items().empty());
  // Ends at X=700 inside, but counter-clockwise around (700, 250) the arc bulges to X=850.
  core::SourceFile bulge("test.nc", "%t\nG00 X700 Y100\nG03 X700 Y400 I0 J150 F600\nM30\n");
  const auto bulge_diags = check_semantics(bulge, test::machine(), {});
  bool bulges = false;
  for (const auto& d : bulge_diags.items())
    bulges = bulges || d.message.find("the arc reaches X=850") != std::string::npos;
  CHECK(bulges);
  // Clockwise the same ends go round the other side, to X=550: inside.
  core::SourceFile other("test.nc", "%t\nG00 X700 Y100\nG02 X700 Y400 I0 J150 F600\nM30\n");
  CHECK(check_semantics(other, test::machine(), {}).items().empty());
}

TEST_CASE("check finds a spline point beyond the soft limits") {
  core::SourceFile file("test.nc",
                        "%t\nG01 X0 Y0 F600\n#SPLINE ON\nX100 Y10\nX900 Y0\nX200 Y5\n"
                        "#SPLINE OFF\nM30\n");
  const auto diags = check_semantics(file, test::machine(), {});
  REQUIRE(diags.items().size() == 1);
  CHECK(diags.items()[0].id == "NC4601");
  CHECK(diags.items()[0].loc.line == 5);
}

TEST_CASE("the extent of a quarter arc covers only the quadrant points it passes") {
  Motion m;
  m.kind = MotionKind::arc_ccw;
  m.start[0] = 10.0;  // from (10, 0) ccw around the origin to (0, 10)
  m.end[1] = 10.0;
  m.arc = Arc{0.0, 0.0, 0, 1, 10.0, false};
  auto [lo, hi] = arc_extent(m);
  CHECK(lo[0] == doctest::Approx(0.0));
  CHECK(hi[0] == doctest::Approx(10.0));
  CHECK(lo[1] == doctest::Approx(0.0));
  CHECK(hi[1] == doctest::Approx(10.0));
  m.kind = MotionKind::arc_cw;  // the other way round: the long way through (-10, 0), (0, -10)
  auto [lo2, hi2] = arc_extent(m);
  CHECK(lo2[0] == doctest::Approx(-10.0));
  CHECK(lo2[1] == doctest::Approx(-10.0));
}

TEST_CASE("a string longer than its declared STRING[5] is NC4014") {
  CHECK(run("%t\n#VAR\nV.P.S : STRING[5] = \"abcdef\"\n#ENDVAR\nM30\n").error_id == "NC4014");
  auto assign = run("%t\n#VAR\nV.P.S : STRING[5] = \"abc\"\n#ENDVAR\nV.P.S = \"abcdef\"\nM30\n");
  CHECK(assign.error_id == "NC4014");
  CHECK(assign.error_line == 5);
  CHECK(run("%t\n#VAR\nV.P.S : STRING[5] = \"abc\"\n#ENDVAR\nV.P.S = \"abcde\"\nM30\n")
            .error_id.empty());
  CHECK(run("%t\n#VAR\nV.P.S : STRING[127]\n#ENDVAR\nM30\n").error_id == "NC4014");
}

}  // namespace
}  // namespace ncsim::interp
