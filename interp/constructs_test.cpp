// The construct list, one test per construct or error id not covered in
// interpreter_test.cpp / eval_test.cpp (audit table: docs/interp.md "Test audit").
#include <doctest/doctest.h>

#include <cstdio>

#include "interp/test_support.hpp"
#include "machines/kinematics.hpp"

namespace ncsim::interp {
namespace {

using test::run;

/// All commands of a program (for fields the trace line does not show).
struct Commands {
  std::vector<Command> items;
  std::string error_id;
  std::uint32_t error_line = 0;
  std::vector<std::string> warnings;
};

Commands commands(const std::string& text, const machines::Machine& machine) {
  core::SourceFile file("test.nc", text);
  Interpreter interp(file, machine);
  Commands out;
  while (out.items.size() < 1000) {
    auto c = interp.next_decode_only();
    if (!c) break;
    out.items.push_back(std::move(*c));
  }
  if (const auto* e = interp.error()) {
    out.error_id = e->id;
    out.error_line = e->loc.line;
  }
  for (const auto& d : interp.diagnostics().items()) {
    if (d.severity != core::Severity::error) out.warnings.push_back(d.id);
  }
  return out;
}

Commands commands(const std::string& text, const std::string& machine_name = "portal_3x") {
  return commands(text, test::machine(machine_name));
}

const Motion& motion(const Commands& c, std::size_t k) {
  return std::get<Motion>(c.items.at(k).body);
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

// Splines: G151 / G150 are #SPLINE ON / OFF (isg-language.md §2.4, §5.4)

TEST_CASE("G151 ... G150 stream the points of one spline like #SPLINE ON/OFF") {
  auto r = run("%t\nG01 F600\nG151\nX1\nX2 Y1\nX3\nG150\nM30\n");
  REQUIRE(r.error_id.empty());
  REQUIRE(r.lines.size() == 6);
  CHECK(r.lines[0] == "3: SPLINE_BEGIN AKIMA frame=MCS start X=0.0000 Y=0.0000 Z=0.0000");
  CHECK(r.lines[1] == "4: SPLINE_POINT 1 X=1.0000 Y=0.0000 Z=0.0000 F=10.0000 frame=MCS");
  CHECK(r.lines[2] == "5: SPLINE_POINT 2 X=2.0000 Y=1.0000 Z=0.0000 F=10.0000 frame=MCS");
  CHECK(r.lines[3] == "6: SPLINE_POINT 3 X=3.0000 Y=1.0000 Z=0.0000 F=10.0000 frame=MCS");
  CHECK(r.lines[4] == "7: SPLINE_END AKIMA points=4");
  auto hash = run("%t\nG01 F600\n#SPLINE ON\nX1\nX2 Y1\nX3\n#SPLINE OFF\nM30\n");  // same semantics
  CHECK(hash.lines == r.lines);
}

TEST_CASE("a point programmed in the G150 block is not part of the spline") {
  auto r = run("%t\nG01 F600\nG151\nX1\nX2\nG150 X5 Y5\nM30\n");
  REQUIRE(r.error_id.empty());
  REQUIRE(r.lines.size() == 6);
  CHECK(r.lines[3] == "6: SPLINE_END AKIMA points=3");
  CHECK(r.lines[4] == "6: G01 X=5.0000 Y=5.0000 Z=0.0000 F=10.0000");
}

TEST_CASE("G150 enforces the minimum point counts: Akima 3, B-spline 4 [NC4401]") {
  auto akima = run("%t\nG01 F600\nG151\nX1\nG150\nM30\n");
  CHECK(akima.error_id == "NC4401");
  CHECK(akima.error_line == 5);
  auto bspline = run("%t\nG01 F600\n#SPLINE TYPE BSPLINE\nG151\nX1\nX2\nG150\nM30\n");
  CHECK(bspline.error_id == "NC4401");
  auto ok = run("%t\nG01 F600\n#SPLINE TYPE BSPLINE\nG151\nX1\nX2\nX3\nG150\nM30\n");
  CHECK(ok.lines.at(4) == "8: SPLINE_END BSPLINE points=4");
}

TEST_CASE("G150 without G151 is NC4403, and so is #SPLINE OFF without ON") {
  CHECK(run("%t\nG150\nM30\n").error_id == "NC4403");
  CHECK(run("%t\n#SPLINE OFF\nM30\n").error_id == "NC4403");
}

TEST_CASE("an arc inside a spline is NC4402") {
  CHECK(run("%t\nG01 F600\nG151\nX1\nG02 X3 Y0 I1 J0\nM30\n").error_id == "NC4402");
}

TEST_CASE("a spline while polynomial contouring is active is error 120255") {
  CHECK(run("%t\nG01 F600\nG261\nG151\nM30\n").error_id == "120255");
}

// Subroutines

TEST_CASE("L calls a subroutine file next to the program; data passes through P and V.P.") {
  core::SourceFile file = core::SourceFile::load(test::source_root() / "interp/testdata/l_main.nc");
  const machines::Machine& m = test::machine();
  Interpreter interp(file, m);
  std::vector<Command> cs;
  while (auto c = interp.next_decode_only())
    cs.push_back(*c);
  REQUIRE(interp.error() == nullptr);
  REQUIRE(cs.size() == 3);
  CHECK(to_trace_line(cs[0], m).starts_with("2: G00 X=4.0000 Y=0.0000 Z=0.0000 frame=MCS"));
  CHECK(cs[0].file != 0);
  CHECK(interp.file_name(cs[0].file).find("sub_move.nc") != std::string::npos);
  CHECK(cs[1].file == 0);
  CHECK(to_trace_line(cs[1], m).starts_with("5: G00 X=4.0000 Y=8.0000 Z=4.0000 frame=MCS"));
}

TEST_CASE("L naming a file that does not exist is NC4301 at the call") {
  core::SourceFile file =
      core::SourceFile::load(test::source_root() / "interp/testdata/l_missing.nc");
  Interpreter interp(file, test::machine());
  CHECK(!interp.next().has_value());
  REQUIRE(interp.error() != nullptr);
  CHECK(interp.error()->id == "NC4301");
  CHECK(interp.error()->loc.line == 2);
}

TEST_CASE("M29 returns from a subroutine like M17") {
  auto r = run("%L SUB\nG00 X7\nM29\n%main\nLL SUB\nG00 Y1\nM30\n");
  REQUIRE(r.error_id.empty());
  REQUIRE(r.lines.size() == 3);
  CHECK(r.lines[1] == "6: G00 X=7.0000 Y=1.0000 Z=0.0000");
}

TEST_CASE("M30 inside a subroutine ends the program with warning NC4305") {
  auto c = commands("%L SUB\nM30\n%main\nLL SUB\nG00 X1\nM30\n");
  CHECK(c.error_id.empty());
  REQUIRE(c.items.size() == 1);
  CHECK(c.warnings == std::vector<std::string>{"NC4305"});
}

TEST_CASE(
    "L CYCLE to a file nowhere is NC4301; MODAL_MOVE is NC4304; an indirect call needs a "
    "STRING variable [NC4303]") {
  CHECK(run("%t\nL CYCLE [NAME=abc.ecy]\nM30\n").error_id == "NC4301");
  CHECK(run("%t\nL CYCLE [NAME=abc.ecy MODAL_MOVE]\nM30\n").error_id == "NC4304");
  CHECK(run("%t\nL CYCLE [@P1=2]\nM30\n").error_id == "NC4304");
  CHECK(run("%t\nV.P.X = 1\nL V.P.X\nM30\n").error_id == "NC4303");
}

// Variables

TEST_CASE("#DELETE removes a variable: a later read is NC4011") {
  auto ok = run("%t\nV.P.A = 2\nG00 X[V.P.A]\n#DELETE V.P.A\nM30\n");
  CHECK(ok.error_id.empty());
  auto r = run("%t\nV.P.A = 2\n#DELETE V.P.A\nG00 X[V.P.A]\nM30\n");
  CHECK(r.error_id == "NC4011");
  CHECK(r.error_line == 4);
}

TEST_CASE("#VAR declares typed variables and 0-based arrays with initialisers") {
  auto r =
      run("%t\n#VAR\nV.P.ARR[3] : REAL = [5, 10, 15]\nV.P.N : SGN16 = 3\n#ENDVAR\n"
          "V.P.N = 7.9\nG00 X[V.P.ARR[2]] Y[V.P.N]\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) == "7: G00 X=15.0000 Y=7.0000 Z=0.0000");  // integers truncate
}

TEST_CASE("an array index that is itself a variable reads the element it names") {
  // Regression: the index expression used the same scratch reference as the array, so
  // V.P.ARR[P2] read P2[1] (NC4010) instead of V.P.ARR[1].
  auto r =
      run("%t\n#VAR\nV.P.ARR[3] : REAL = [5, 10, 15]\n#ENDVAR\nP2 = 1\n"
          "G00 X[V.P.ARR[P2]] Y[V.P.ARR[P2 + 1]] Z[V.P.ARR[V.P.ARR[0] - 4]]\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) == "6: G00 X=10.0000 Y=15.0000 Z=10.0000");
}

TEST_CASE("an integer variable out of its type's range is NC4013") {
  CHECK(run("%t\n#VAR\nV.P.B : UNS08\n#ENDVAR\nV.P.B = 300\nM30\n").error_id == "NC4013");
}

TEST_CASE("an array index beyond the declared size is NC4015") {
  CHECK(run("%t\n#VAR\nV.P.A[2] : REAL\n#ENDVAR\nV.P.A[2] = 1\nM30\n").error_id == "NC4015");
}

TEST_CASE("a V.L. variable used without declaration is NC4011") {
  CHECK(run("%t\nV.L.X = 1\nM30\n").error_id == "NC4011");
}

TEST_CASE("a number assigned to a STRING variable is NC4014") {
  CHECK(run("%t\n#VAR\nV.P.S : STRING[10] = \"a\"\n#ENDVAR\nV.P.S = 3\nM30\n").error_id ==
        "NC4014");
}

TEST_CASE("declaring a V.E. variable is error 20908") {
  CHECK(run("%t\n#VAR\nV.E.X : REAL\n#ENDVAR\nM30\n").error_id == "20908");
}

// Conditional interpretation

TEST_CASE("#IF / #ELSE / #ENDIF interprets only the chosen branch") {
  auto r =
      run("%t\nP1 = 1\n#IF P1 == 1\nG00 X1\n#ELSE\nG00 X2\n#ENDIF\n"
          "#IF P1 == 2\nG00 Y1\n#ELSE\nG00 Y2\n#ENDIF\nM30\n");
  REQUIRE(r.error_id.empty());
  REQUIRE(r.lines.size() == 3);
  CHECK(r.lines[0] == "4: G00 X=1.0000 Y=0.0000 Z=0.0000");
  CHECK(r.lines[1] == "11: G00 X=1.0000 Y=2.0000 Z=0.0000");
}

TEST_CASE("nested #IF inside a skipped branch is skipped whole") {
  auto r = run("%t\n#IF 0\n#IF 1\nG00 X1\n#ENDIF\nG00 X2\n#ELSE\nG00 X3\n#ENDIF\nM30\n");
  REQUIRE(r.error_id.empty());
  REQUIRE(r.lines.size() == 2);
  CHECK(r.lines[0] == "8: G00 X=3.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("a false #IF without #ENDIF is NC4026") {
  CHECK(run("%t\n#IF 0\nG00 X1\nM30\n").error_id == "NC4026");
}

// Control-flow errors

TEST_CASE("$ENDWHILE without $WHILE is 20237; $CONTINUE outside a loop is 20244") {
  CHECK(run("%t\n$ENDWHILE\nM30\n").error_id == "20237");
  CHECK(run("%t\n$CONTINUE\nM30\n").error_id == "20244");
}

TEST_CASE("a loop without its end is NC4020, $IF without $ENDIF NC4021, $ENDFOR alone NC4025") {
  CHECK(run("%t\n$WHILE 0\nG00 X1\nM30\n").error_id == "NC4020");
  CHECK(run("%t\n$IF 0\nG00 X1\nM30\n").error_id == "NC4021");
  CHECK(run("%t\n$ENDFOR\nM30\n").error_id == "NC4025");
}

TEST_CASE("$FOR with step 0 warns NC4024") {
  Options o;
  auto c = commands(
      "%t\nP2 = 0\n$FOR P1 = 1, 2, 0\nP2 = P2 + 1\n$IF P2 > 2 $GOTO [OUT]\n"
      "$ENDFOR\n[OUT]\nM30\n");
  CHECK(c.error_id.empty());
  CHECK(std::find(c.warnings.begin(), c.warnings.end(), "NC4024") != c.warnings.end());
}

// Modal state

TEST_CASE("G93 takes F as the block time in seconds; G94 returns to mm/min") {
  auto r = run("%t\nG93 G01 X10 F2.5\nG94 G01 X20 F600\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) == "2: G01 X=10.0000 Y=0.0000 Z=0.0000 F=0.0000 TIME=2.5000");
  CHECK(r.lines.at(1) == "3: G01 X=20.0000 Y=0.0000 Z=0.0000 F=10.0000");
  auto c = commands("%t\nG93 G01 X10 F2.5\nM30\n");
  CHECK(motion(c, 0).modal.feed_mode == FeedMode::inverse_time);
}

TEST_CASE("under G93 a G01/G02/G03 block without its block time F is 20008 at the block") {
  // Not the earlier G94 feed read as mm/min (issue 34 item 29): the block time is per block.
  auto r = run("%t\nG01 X5 F600\nG93 G01 X10\nM30\n");
  CHECK(r.error_id == "20008");
  CHECK(r.error_line == 3);
  CHECK(r.error_message.find("G93") != std::string::npos);
  auto second = run("%t\nG93 G01 X10 F2\nX20\nM30\n");
  CHECK(second.error_id == "20008");
  CHECK(second.error_line == 3);
  CHECK(run("%t\nG01 X5 F600\nG93 G00 X10\nM30\n").error_id.empty());  // a rapid needs none
}

TEST_CASE("G18 and G19 select the arc plane") {
  auto r = run("%t\nG01 F600\nG18 G02 X10 Z0 I5 K0\nG19 G02 Y10 Z0 J5 K0\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) ==
        "3: G02 X=10.0000 Y=0.0000 Z=0.0000 F=10.0000 centre Z=0.0000 X=5.0000 R=5.0000");
  CHECK(r.lines.at(1) ==
        "4: G02 X=10.0000 Y=10.0000 Z=0.0000 F=10.0000 centre Y=5.0000 Z=0.0000 R=5.0000");
}

TEST_CASE("G71 returns to millimetres after G70") {
  auto r = run("%t\nG70 G00 X1\nG71 X1\nM30\n");
  CHECK(r.lines.at(1) == "3: G00 X=1.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("G09 stops at its block only; G900 and G901 are modal until G08") {
  auto r = run("%t\nG09 G00 X1\nX2\nG900 X3\nG901 X4\nG08 X5\nM30\n");
  CHECK(r.lines.at(0) == "2: G00 X=1.0000 Y=0.0000 Z=0.0000 G09");
  CHECK(r.lines.at(1) == "3: G00 X=2.0000 Y=0.0000 Z=0.0000");
  CHECK(r.lines.at(2) == "4: G00 X=3.0000 Y=0.0000 Z=0.0000 G900");
  CHECK(r.lines.at(3) == "5: G00 X=4.0000 Y=0.0000 Z=0.0000 G901");
  CHECK(r.lines.at(4) == "6: G00 X=5.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("G09 in a block leaves a modal G900/G901 in force for the next blocks") {
  auto r = run("%t\nG900 G00 X1\nG09 X2\nX3\nG901 X4\nG09 X5\nX6\nM30\n");
  CHECK(r.lines.at(0) == "2: G00 X=1.0000 Y=0.0000 Z=0.0000 G900");
  CHECK(r.lines.at(1) == "3: G00 X=2.0000 Y=0.0000 Z=0.0000 G09");
  CHECK(r.lines.at(2) == "4: G00 X=3.0000 Y=0.0000 Z=0.0000 G900");
  CHECK(r.lines.at(3) == "5: G00 X=4.0000 Y=0.0000 Z=0.0000 G901");
  CHECK(r.lines.at(4) == "6: G00 X=5.0000 Y=0.0000 Z=0.0000 G09");
  CHECK(r.lines.at(5) == "7: G00 X=6.0000 Y=0.0000 Z=0.0000 G901");
}

TEST_CASE("G60 is exact stop in its block only; G360 is modal until G359") {
  auto r = run("%t\nG60 G00 X1\nX2\nG360 X3\nX4\nG359 X5\nM30\n");
  CHECK(r.lines.at(0) == "2: G00 X=1.0000 Y=0.0000 Z=0.0000 G60");
  CHECK(r.lines.at(1) == "3: G00 X=2.0000 Y=0.0000 Z=0.0000");
  CHECK(r.lines.at(3) == "5: G00 X=4.0000 Y=0.0000 Z=0.0000 G60");
  CHECK(r.lines.at(4) == "6: G00 X=5.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("G61 contours its block only; G261 until G260; #CONTOUR MODE sets the parameters") {
  auto r = run("%t\nG61 G00 X1\nX2\nG261 X3\nG260 X4\nM30\n");
  CHECK(r.lines.at(0) == "2: G00 X=1.0000 Y=0.0000 Z=0.0000 G261");
  CHECK(r.lines.at(1) == "3: G00 X=2.0000 Y=0.0000 Z=0.0000");
  CHECK(r.lines.at(2) == "4: G00 X=3.0000 Y=0.0000 Z=0.0000 G261");
  CHECK(r.lines.at(3) == "5: G00 X=4.0000 Y=0.0000 Z=0.0000");
  auto c = commands("%t\n#CONTOUR MODE [DEV, PATH_DEV=0.5]\nG261 G00 X1\nM30\n");
  REQUIRE(c.error_id.empty());
  CHECK(motion(c, 0).modal.contour.kind == ContourKind::dev);
  CHECK(motion(c, 0).modal.contour.path_dev == doctest::Approx(0.5));
}

TEST_CASE(
    "G261 without PATH_DEV: the channel's NCSIM-CHAN-620 radius (the manual's 1 mm when the list "
    "has none); #CONTOUR MODE PATH_DEV replaces it, DEV alone keeps it") {
  const std::string program =
      "%t\nG261 G01 X1 F100\n#CONTOUR MODE [DEV]\nX2\n#CONTOUR MODE [DEV, PATH_DEV=0.5]\nX3\nM30\n";
  const Commands plain = commands(program);  // portal_3x: no ncsim.default_path_dev
  REQUIRE(plain.error_id.empty());
  CHECK(motion(plain, 0).modal.contour.path_dev == 1.0);  // isg-language.md §5.3 PROG-475164939
  CHECK(motion(plain, 1).modal.contour.path_dev == 1.0);
  CHECK(motion(plain, 2).modal.contour.path_dev == 0.5);
  machines::Machine m = test::machine("portal_3x");
  m.channel.default_path_dev = 0.25;
  const Commands channel = commands(program, m);
  REQUIRE(channel.error_id.empty());
  CHECK(motion(channel, 0).modal.contour.path_dev == 0.25);
  CHECK(motion(channel, 1).modal.contour.path_dev == 0.25);
  CHECK(motion(channel, 2).modal.contour.path_dev == 0.5);
}

TEST_CASE("#CONTOUR MODE: PATH_DEV, PRE_DIST or POST_DIST <= 0 is NC4031 at its block") {
  // A ball of radius 0 or a blend from 0 mm before the corner cannot be: before, such a value
  // reached the planner and ended the run with an unpositioned exception (session 29).
  for (const char* item : {"DEV, PATH_DEV=0", "DEV, PATH_DEV=-0.5", "DIST, PRE_DIST=0",
                           "DIST, POST_DIST=-1", "DIST, PRE_DIST=1, POST_DIST=0"}) {
    CAPTURE(item);
    const auto r =
        run(std::string("%t\nG01 X1 F100\n#CONTOUR MODE [") + item + "]\nG261 X2\nM30\n");
    CHECK(r.error_id == "NC4031");
    CHECK(r.error_line == 3);
  }
  CHECK(run("%t\n#CONTOUR MODE [DIST, PRE_DIST=0.2, POST_DIST=3]\nM30\n").error_id.empty());
}

TEST_CASE("#CONTOUR MODE CONST_VEL=1 is not supported (NC4104); CONST_VEL=0 is ncsim's way") {
  // TF5200 "Velocity curve in the contouring section" (PROG-475135755): CONST_VEL=0, the
  // default, runs the contouring section at the maximum permissible path velocity, as ncsim
  // plans its balls; CONST_VEL=1 keeps the path velocity constant in it, which ncsim does not
  // plan: it answers "not supported" instead of running the ball the other way.
  const auto bad = run("%t\nG01 X1 F100\n#CONTOUR MODE [DEV PATH_DEV=0.1 CONST_VEL=1]\nM30\n");
  CHECK(bad.error_id == "NC4104");
  CHECK(bad.error_line == 3);
  CHECK(run("%t\n#CONTOUR MODE [DEV PATH_DEV=0.1 CONST_VEL=0]\nM30\n").error_id.empty());
}

TEST_CASE("#SLOPE sets the slope type; an unknown type is NC4509") {
  auto c = commands("%t\n#SLOPE [TYPE=TRAPEZ]\nG00 X1\n#SLOPE [TYPE=SIN2]\nG00 X2\nM30\n");
  REQUIRE(c.error_id.empty());
  CHECK(motion(c, 0).modal.slope == SlopeType::trapez);
  CHECK(motion(c, 1).modal.slope == SlopeType::sin2);
  CHECK(run("%t\n#SLOPE [TYPE=WOBBLE]\nM30\n").error_id == "NC4509");
}

TEST_CASE("#TRANSVELMIN ON converts mm/min to mm/s and OFF clears it") {
  auto c = commands("%t\n#TRANSVELMIN ON [600]\nG00 X1\n#TRANSVELMIN OFF\nG00 X2\nM30\n");
  REQUIRE(c.error_id.empty());
  REQUIRE(motion(c, 0).modal.transvelmin.has_value());
  CHECK(*motion(c, 0).modal.transvelmin == doctest::Approx(10.0));
  CHECK(!motion(c, 1).modal.transvelmin.has_value());
}

TEST_CASE("E gives the end feed in mm/s; D passes through; M02 ends the program") {
  auto r = run("%t\nG01 X1 F600 E300 D2\nM02\n");
  CHECK(r.lines.at(0) == "2: TECH D=2.0000");
  CHECK(r.lines.at(1) == "2: G01 X=1.0000 Y=0.0000 Z=0.0000 F=10.0000 E=5.0000");
  CHECK(r.lines.at(2) == "3: END M02");
}

TEST_CASE("G04 with a further axis address warns 20685; with value and axis it is 20013") {
  auto c = commands("%t\nG04 X1 Y2\nM30\n");
  CHECK(c.error_id.empty());
  CHECK(c.warnings == std::vector<std::string>{"20685"});
  CHECK(run("%t\nG04 2 X1\nM30\n").error_id == "20013");
}

TEST_CASE("an unsupported G code is NC4102") {
  CHECK(run("%t\nG123\nM30\n").error_id == "NC4102");
}

TEST_CASE("R below half the chord is NC4202") {
  CHECK(run("%t\nG01 F600\nG02 X20 Y0 R5\nM30\n").error_id == "NC4202");
}

// # commands

TEST_CASE("#MACHINE DATA with AXPARAM becomes a command at its point in the stream") {
  auto r =
      run("%t\nG00 X1\n#MACHINE DATA SYN [AX=X AXPARAM=\"kenngr.swe_pos 15000000\" WAIT]\n"
          "G00 X2\nM30\n");
  REQUIRE(r.error_id.empty());
  // P-AXIS-00178 is in 0.1 um: 15000000 is 1500 mm, converted once, here.
  CHECK(r.lines.at(1) == "3: MACHINE_DATA SYN AX=X P-AXIS-00178 kenngr.swe_pos=1500.0000 WAIT");
  CHECK(starts_with(r.lines.at(2), "4: G00 X=2.0000"));
}

TEST_CASE("#CS DEF / ON / OFF become commands and mark the motions") {
  auto r = run("%t\n#CS ON [1] [10,0,0,0,0,0]\nG00 X1\n#CS OFF\nG00 X2\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(starts_with(r.lines.at(0), "2: CS ON id=1"));
  CHECK(r.lines.at(1) == "3: G00 X=1.0000 Y=0.0000 Z=0.0000 CS");
  CHECK(starts_with(r.lines.at(2), "4: CS OFF"));
  CHECK(r.lines.at(3) == "5: G00 X=2.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE(
    "#KIN ID selects a kinematic and #TRAFO ON/OFF switches it; #KIN ID under TRAFO is NC4508") {
  auto c = commands("%t\n#KIN ID[37]\n#TRAFO ON\nG00 X1\n#TRAFO OFF\nM30\n", "delta_picker");
  REQUIRE(c.error_id.empty());
  const auto& k = std::get<Kinematics>(c.items.at(0).body);
  CHECK(k.kin_id == 37);
  CHECK(std::get<Kinematics>(c.items.at(1).body).trafo_on);
  CHECK(motion(c, 2).modal.kinematics_on);
  CHECK(!std::get<Kinematics>(c.items.at(3).body).trafo_on);
  CHECK(run("%t\n#KIN ID[37]\n#TRAFO ON\n#KIN ID[37]\nM30\n", "delta_picker").error_id == "NC4508");
}

TEST_CASE("#CAXTRACK ON/OFF become commands; values out of range are 21135") {
  auto c =
      commands("%t\n#CAXTRACK ON [AX=C ANGLIMIT=90]\nG00 X1\n#CAXTRACK OFF\nM30\n", "static_saw");
  REQUIRE(c.error_id.empty());
  CHECK(std::get<CaxTrack>(c.items.at(0).body).on);
  CHECK(motion(c, 1).modal.caxtrack);
  CHECK(!std::get<CaxTrack>(c.items.at(2).body).on);
  CHECK(run("%t\n#CAXTRACK ON [AX=C ANGLIMIT=400]\nM30\n", "static_saw").error_id == "21135");
}

TEST_CASE("#CAXTRACK keeps ROTMODE, whether ANGPOS was given and the first word ncsim lacks") {
  auto c = commands(
      "%t\n#CAXTRACK ON [AX=C, ANGLIMIT 3, OFFSET 180, ROTMODE=1]\n#CAXTRACK OFF\n"
      "#CAXTRACK ON [OPTALIGN=10]\n#CAXTRACK OFF [ANGPOS=5]\nM30\n",
      "static_saw");
  REQUIRE(c.error_id.empty());
  const auto& on = std::get<CaxTrack>(c.items.at(0).body);
  CHECK(on.rotmode == 1.0);
  CHECK(on.offset == 180.0);
  CHECK(on.anglimit == 3.0);
  CHECK(on.unsupported.empty());
  CHECK_FALSE(std::get<CaxTrack>(c.items.at(1).body).angpos_given);
  CHECK(std::get<CaxTrack>(c.items.at(2).body).unsupported == "OPTALIGN");
  CHECK(std::get<CaxTrack>(c.items.at(3).body).angpos_given);
  CHECK(std::get<CaxTrack>(c.items.at(3).body).angpos == 5.0);
}

TEST_CASE("#SYNC OUT without #SYNC IN is NC4503; #SYNC IN without CONV_VEL is NC4507") {
  CHECK(run("%t\n#SYNC OUT\nM30\n", "laser_portal").error_id == "NC4503");
  CHECK(run("%t\n#SYNC IN\nM30\n", "laser_portal").error_id == "NC4507");
}

TEST_CASE("MC_TouchProbe arms the latch on the conveyor axis") {
  auto r = run("%t\nS1[MC_TouchProbe Channel=1]\nM30\n", "laser_portal");
  CHECK(r.lines.at(0) == "2: PROBE_ARM S channel=1");
}

TEST_CASE(
    "MC_TouchProbe Mode=1 arms the falling edge, Mode=2 the rising one, no Mode leaves it to "
    "P-AXIS-00518") {
  // PROG-306968203: Mode 1 falling edge, Mode 2 rising edge.
  const auto edge_of = [](const std::string& item) -> std::optional<ProbeEdge> {
    const Commands c =
        commands("%t\nS1[MC_TouchProbe Channel=1" + item + "]\nM30\n", "laser_portal");
    REQUIRE_FALSE(c.items.empty());
    const auto* arm = std::get_if<ProbeArm>(&c.items.front().body);
    REQUIRE(arm != nullptr);
    return arm->edge;
  };
  CHECK(edge_of(" Mode=1") == ProbeEdge::falling);
  CHECK(edge_of(" Mode=2") == ProbeEdge::rising);
  CHECK(edge_of("") == std::nullopt);
  CHECK(run("%t\nS1[MC_TouchProbe Channel=1 Mode=3]\nM30\n", "laser_portal").error_id == "NC4030");
}

TEST_CASE("INTERRUPTIBLE needs conveyor synchronisation [50603]; INDP without POS is NC4510") {
  CHECK(run("%t\nX[INDP_SYN G01 POS10 FEED600 INTERRUPTIBLE]\nM30\n").error_id == "50603");
  CHECK(run("%t\nX[INDP_SYN G01 FEED600]\nM30\n").error_id == "NC4510");
}

TEST_CASE("MC_MoveVelocity without Velocity is NC4511") {
  CHECK(run("%t\nS1[MC_MoveVelocity Direction=1]\nM30\n", "laser_portal").error_id == "NC4511");
}

TEST_CASE("#BCS is refused as not supported [NC4104]") {
  CHECK(run("%t\n#BCS ON [1,0,0,0,0,0]\nM30\n").error_id == "NC4104");
}

TEST_CASE("#MACHINE DATA with a parameter id and AXNR resolves the id through the table") {
  // The manual writes the id as P-AXIS-00178 (PROG-207492747); the value is in list units.
  auto r = run("%t\n#MACHINE DATA [AXNR=1 P-AXIS-00178=10000 WAIT]\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) == "2: MACHINE_DATA AX=X P-AXIS-00178 kenngr.swe_pos=1.0000 WAIT");
  CHECK(run("%t\n#MACHINE DATA [AXNR=99 P-AXIS-00178=1]\nM30\n").error_id == "NC4103");
}

TEST_CASE("#MACHINE DATA errors name the parameter id") {
  auto unknown = run("%t\n#MACHINE DATA [AX=X P-AXIS-99999=1]\nM30\n");
  CHECK(unknown.error_id == "NC4513");
  CHECK(unknown.error_message.find("P-AXIS-99999") != std::string::npos);
  auto range = run("%t\n#MACHINE DATA [AX=X P-AXIS-00178=1.5]\nM30\n");
  CHECK(range.error_id == "NC4514");
  CHECK(range.error_message.find("P-AXIS-00178") != std::string::npos);
  auto no_axis = run("%t\n#MACHINE DATA [P-AXIS-00178=1]\nM30\n");
  CHECK(no_axis.error_id == "NC4515");
  CHECK(no_axis.error_message.find("P-AXIS-00178") != std::string::npos);
  auto bad_key = run("%t\n#MACHINE DATA [AX=X AXPARAM=\"kenngr.nothing 5\"]\nM30\n");
  CHECK(bad_key.error_id == "NC4513");
}

TEST_CASE("PP parameters are NC4004, @P outside a cycle 21382; an undefined macro is NC4005") {
  CHECK(run("%t\nPP1 = 2\nM30\n").error_id == "NC4004");
  CHECK(run("%t\n@P1 = 2\nM30\n").error_id == "21382");
  CHECK(run("%t\nLL \"NOPE\"\nM30\n").error_id == "NC4005");
  CHECK(run("%t\nP1 = \"NOPE\" + 1\nM30\n").error_id == "NC4005");
}

TEST_CASE("SIZEOF of a number is NC4003; a one-argument function given two is NC4002") {
  CHECK(run("%t\nP1 = SIZEOF[3]\nM30\n").error_id == "NC4003");
  CHECK(run("%t\nP1 = SIN[1, 2]\nM30\n").error_id == "NC4002");
  CHECK(run("%t\nP1 = ATAN2[1]\nM30\n").error_id == "NC4002");
}

TEST_CASE("CONV_VEL above the conveying axis' maximum velocity is error 50587") {
  CHECK(run("%t\n#SYNC IN [CONV_VEL=6000000]\nM30\n", "laser_portal").error_id == "50587");
}

TEST_CASE("#TRAFO ON / OFF with kinematic 45 re-bases all six axes X, Y, Z, A, B, C") {
  const auto r =
      run("%t\n#KIN ID[45]\nG01 X0 Y0 Z0 A0 B90 C0 F20000\n#TRAFO ON\nG01 X700 C30 F1000\n"
          "#TRAFO OFF\nG01 X0 F1000\nM30\n",
          "arm6_belt");
  REQUIRE(r.error_id.empty());
  std::string on, off;
  for (const std::string& l : r.lines) {
    if (starts_with(l, "5: G01")) on = l;
    if (starts_with(l, "7: G01")) off = l;
  }
  INFO(on);
  INFO(off);
  // ON: the TCP of the start pose: wrist centre (a1 + d4, 0, d1 + a2 + a3) = (790, 0, 1170),
  // the tool (d6 + tool = 250 mm) pointing down (A = B = 0); X and C as programmed.
  CHECK(on.find("X=700.0000 Y=0.0000 Z=920.0000 A=0.0000 B=0.0000 C=30.0000") != std::string::npos);
  // OFF: the joints of that TCP (X programmed again, the others as re-based).
  const auto kin =
      machines::make_kinematics(45, test::machine("arm6_belt").channel.trafos[0].param);
  REQUIRE(kin.kinematics);
  const machines::KinAxesResult q = kin.kinematics->inverse_axes({700, 0, 920, 0, 0, 30});
  REQUIRE(q.ok());
  char want[160];
  std::snprintf(want, sizeof want, "Y=%.4f Z=%.4f A=%.4f B=%.4f C=%.4f", q.value[1], q.value[2],
                q.value[3], q.value[4], q.value[5]);
  CHECK(off.find(want) != std::string::npos);
  // Joint 6's axis points down: a turn of +30 deg about +Z is -30 deg about it.
  CHECK(q.value[5] == doctest::Approx(-30.0));
}

TEST_CASE("V.G.KIN[id].PARAM[k] reads the channel list's trafo parameter; a write is NC1002") {
  // arm6_belt: trafo[0].id 45, param[5] 6000000 (the upper arm, 0.1 um), param[10] 0.
  const auto r =
      run("%t\nP1 = V.G.KIN[45].PARAM[5]\n$IF ABS[P1 - 6000000] > 0.001\nP2 = V.G.NONE\n$ENDIF\n"
          "P3 = V.G.KIN[45].PARAM[10]\nM30\n",
          "arm6_belt");
  CHECK(r.error_id.empty());
  CHECK(run("%t\nV.G.KIN[45].PARAM[5] = 1\nM30\n", "arm6_belt").error_id == "NC1002");
  // Beyond the configured ids, or on a machine without a kinematic: no such element.
  CHECK_FALSE(run("%t\nP1 = V.G.KIN[46].PARAM[5]\nM30\n", "arm6_belt").error_id.empty());
  CHECK(run("%t\nP1 = V.G.KIN[45].PARAM[5]\nM30\n").error_id == "NC4011");
}

TEST_CASE("under #TRAFO ON CONV_VEL is not compared with joint X's V (no 50587)") {
  // arm6_belt's joint 1 (axis X) turns at most 180 deg/s; the belt runs at 200 mm/s.
  const char* arm =
      "%t\n#KIN ID[45]\nG01 X0 Y0 Z0 A0 B90 C0 F20000\n#TRAFO ON\n"
      "#SYNC IN [CONVEYOR=S1, CONV_VEL=12000]\nM30\n";
  CHECK(run(arm, "arm6_belt").error_id.empty());
  // Without the transform X is the conveying axis itself: the same belt is 50587.
  CHECK(run("%t\n#SYNC IN [CONVEYOR=S1, CONV_VEL=12000]\nM30\n", "arm6_belt").error_id == "50587");
}

TEST_CASE("#FLUSH CONTINUE and #WAIT INDP with an axis list become commands") {
  auto r = run("%t\n#FLUSH CONTINUE\n#WAIT INDP [X Y]\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) == "2: FLUSH CONTINUE");
  CHECK(starts_with(r.lines.at(1), "3: WAIT_INDP X"));
}

TEST_CASE("$GOTO to a V.E. variable is NC4022") {
  CHECK(run("%t\n$GOTO V.E.TARGET\nM30\n").error_id == "NC4022");
}

}  // namespace
}  // namespace ncsim::interp
