// The constructs shipped NC programs use (issue 33): M/H functions with an additional value,
// implicit cycle calls with parameter lists, L CYCLE, #FILE NAME, zero offsets, #SCALE, #MCS,
// #HSC, #VECTOR LIMIT, accepted # commands, blanks in program names.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

namespace fs = std::filesystem;
using test::run;

/// A scratch folder with files for cycle tests, removed at the end of the test.
struct Folder {
  fs::path dir;
  explicit Folder(const std::string& name) {
    dir = fs::temp_directory_path() / ("ncsim_real_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
  }
};

/// A machine like portal_3x whose channel configures G80 and G805 (P-CHAN-00160, 00187).
machines::Machine cycle_machine() {
  machines::Machine m = test::machine("portal_3x");
  m.channel.implicit_call_files[80] = "drill.nc";
  m.channel.implicit_call_files[805] = "dispense.nc";
  return m;
}

/// Interprets `file` on `m`, each warning as a line "warning <id>" after the commands.
test::Run run_source(const machines::Machine& m, const core::SourceFile& file,
                     Options options = {}) {
  return test::run_on_machine(file, m, std::move(options), 1000, true);
}

test::Run run_on(const machines::Machine& m, const fs::path& program, Options options = {}) {
  return run_source(m, core::SourceFile::load(program), std::move(options));
}

/// A program given as text on portal_3x, warnings included.
test::Run run_warn(const std::string& text) {
  return run_source(test::machine("portal_3x"), core::SourceFile("test.nc", text));
}

/// The value of field `name` (X, F, ...) of a trace line's motion, before its ` frame=` part;
/// NaN when the line has none.
double field(const std::string& line, const std::string& name) {
  const std::string head = line.substr(0, line.find(" frame="));
  const std::size_t k = head.find(" " + name + "=");
  if (k == std::string::npos) return std::nan("");
  return std::strtod(head.c_str() + k + name.size() + 2, nullptr);
}

bool has_line(const test::Run& r, const std::string& text) {
  for (const auto& l : r.lines)
    if (l.find(text) != std::string::npos) return true;
  return false;
}

TEST_CASE("M and H functions carry an additional value to the PLC (M200=1200, H5=-345)") {
  const test::Run r = run("%t\nM200=1200 H5=-345 M52=-P1\nM30\n");
  CHECK(r.error_id == "NC4010");  // P1 was never written: the value is evaluated
  const test::Run ok = run("%t\nP2=17\nM200=1200 H5=-345 M52=-P2 M8\nM30\n");
  REQUIRE(ok.error_id.empty());
  CHECK(has_line(ok, "TECH M=200.0000 value=1200.0000"));
  CHECK(has_line(ok, "TECH H=5.0000 value=-345.0000"));
  CHECK(has_line(ok, "TECH M=52.0000 value=-17.0000"));
  CHECK(has_line(ok, "TECH M=8.0000"));
}

TEST_CASE("an additional value must be a whole number, and spindle M functions take none") {
  CHECK(run("%t\nM200=1.5\nM30\n").error_id == "NC4033");
  CHECK(run("%t\nM3=100\nM30\n").error_id == "NC4033");
  CHECK(run("%t\nM42=1\nM30\n").error_id == "NC4033");
}

TEST_CASE("an implicit call without a configured subroutine is 20131 naming the parameter") {
  const test::Run r = run("%t\nG00 X0\nG805 [1, 2]\nM30\n");
  CHECK(r.error_id == "20131");
  CHECK(r.error_line == 3);
  CHECK(r.error_message.find("g800_prog_file[5] (P-CHAN-00187)") != std::string::npos);
  CHECK(run("%t\nG81\nM30\n").error_message.find("g81_prog_file (P-CHAN-00161)") !=
        std::string::npos);
}

TEST_CASE("G805 [v1, v2,, v4] runs the configured subroutine with @P1..@P4, gaps unprogrammed") {
  Folder f("g805");
  f.write("dispense.nc",
          "%dispense\nG01 X[@P1] Y[@P2] F600\n$IF EXIST[@P3] == 0\nG01 Z[@P4]\n$ENDIF\nM17\n");
  f.write("main.nc", "%main\nG00 X0 Y0 Z0\nG805 [ 10.5, -2 ,, 3 ]\nG00 X1\nM30\n");
  const test::Run r = run_on(cycle_machine(), f.dir / "main.nc");
  REQUIRE(r.error_id.empty());
  REQUIRE(r.lines.size() >= 5);
  CHECK(r.full[1].find("G01") != std::string::npos);
  CHECK(field(r.full[1], "X") == doctest::Approx(10.5));
  CHECK(field(r.full[1], "Y") == doctest::Approx(-2));
  CHECK(field(r.full[2], "Z") == doctest::Approx(3));  // @P3 was a gap: EXIST is 0
  CHECK(field(r.full[3], "X") == doctest::Approx(1));  // back in the main program
}

TEST_CASE("@P outside a cycle is 21382; a @P the call did not program reads 0 (P-CHAN-00463)") {
  CHECK(run("%t\nP1 = @P1\nM30\n").error_id == "21382");
  Folder f("atp");
  f.write("drill.nc", "%drill\nG01 X[@P7] F100\nM17\n");
  f.write("main.nc", "%main\nG80\nM30\n");
  machines::Machine m = cycle_machine();
  const test::Run r = run_on(m, f.dir / "main.nc");
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "X") == doctest::Approx(0));
  m.channel.create_cycle_param_on_read = false;
  CHECK(run_on(m, f.dir / "main.nc").error_id == "20394");
}

TEST_CASE("#FILE NAME overrides the channel's subroutine of an implicit call until the end") {
  Folder f("filename");
  f.write("other.nc", "%other\nG01 X[@P1*2] F100\nM17\n");
  f.write("main.nc", "%main\n#FILE NAME [G805=\"other.nc\"]\nG805 [4]\nM30\n");
  const test::Run r = run_on(cycle_machine(), f.dir / "main.nc");
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "X") == doctest::Approx(8));
}

TEST_CASE("a cycle file that is not found names where ncsim looked; --missing-cycles skips") {
  Folder f("missing");
  f.write("main.nc", "%main\nG805 [1]\nG805 [2]\nG81\nG00 X5\nM30\n");
  const test::Run r = run_on(cycle_machine(), f.dir / "main.nc");
  CHECK(r.error_id == "NC4301");
  CHECK(r.error_message.find("dispense.nc") != std::string::npos);
  CHECK(r.error_message.find("--cycles") != std::string::npos);
  Options skip;
  skip.skip_missing_cycles = true;
  const test::Run s = run_on(cycle_machine(), f.dir / "main.nc", skip);
  CHECK(s.error_id.empty());
  CHECK(has_line(s, "X=5"));
  int warnings = 0;
  for (const auto& l : s.lines)
    if (l == "warning NC4307") ++warnings;
  CHECK(warnings == 2);  // once per G code: G805 and G81
}

TEST_CASE("--cycles folders come before the machine's cycles/ and the program's folder") {
  Folder f("dirs");
  fs::create_directories(f.dir / "builder");
  f.write("dispense.nc", "%d\nG01 X1 F100\nM17\n");
  f.write("builder/dispense.nc", "%d\nG01 X2 F100\nM17\n");
  f.write("main.nc", "%main\nG805\nM30\n");
  Options o;
  o.cycle_dirs = {f.dir / "builder"};
  CHECK(field(run_on(cycle_machine(), f.dir / "main.nc", o).full[0], "X") == doctest::Approx(2));
  CHECK(field(run_on(cycle_machine(), f.dir / "main.nc").full[0], "X") == doctest::Approx(1));
}

TEST_CASE("L CYCLE [NAME=.. @P1=..] calls a cycle file with its parameters") {
  Folder f("lcycle");
  f.write("pocket.cyc", "%pocket\nG01 X[@P1] Y[@P2] F100\nM17\n");
  f.write("main.nc", "%main\nL CYCLE [NAME=pocket.cyc @P1=3 @P2=4]\nM30\n");
  const test::Run r = run_on(cycle_machine(), f.dir / "main.nc");
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "X") == doctest::Approx(3));
  CHECK(field(r.full[0], "Y") == doctest::Approx(4));
}

TEST_CASE("a text as a cycle parameter is 'not supported', not a missing value") {
  Folder f("lcycle_text");
  f.write("pocket.cyc", "%pocket\nG01 X1 F100\nM17\n");
  f.write("main.nc", "%main\nL CYCLE [NAME=pocket.cyc @P1=\"left\" @P2=4]\nM30\n");
  const test::Run r = run_on(cycle_machine(), f.dir / "main.nc");
  CHECK(r.error_id == "NC4304");
  CHECK(r.error_message.find("not supported: a text as cycle parameter @P1") != std::string::npos);
  f.write("flag.nc", "%flag\nL CYCLE [NAME=pocket.cyc @P1]\nM30\n");
  CHECK(run_on(cycle_machine(), f.dir / "flag.nc").error_message.find("needs a value") !=
        std::string::npos);
}

/// The trace lines of `r` that are motions (G00 / G01 ...), in order.
std::vector<std::string> motions(const test::Run& r) {
  std::vector<std::string> out;
  for (const std::string& line : r.full)
    if (line.find(": G0") != std::string::npos) out.push_back(line);
  return out;
}

TEST_CASE("M6 calls m6_prog_file instead of being an M function; #FILE NAME [M6=..] overrides") {
  // P-CHAN-00118: "M6 is not treated as a normal M function but becomes a global subroutine
  // call analogous to 'L ...'", executed as the last action at block end.
  Folder f("m6call");
  f.write("change.nc", "%change\nG00 Z50\nM17\n");
  f.write("other.nc", "%other\nG00 Z70\nM17\n");
  f.write("main.nc",
          "%main\nG00 X1 M6\nG00 X2\n#FILE NAME [M6=\"other.nc\" MSG=\"log.txt\"]\nM6\nM30\n");
  machines::Machine m = cycle_machine();
  m.channel.m6_prog_file = "change.nc";
  const test::Run r = run_on(m, f.dir / "main.nc");
  REQUIRE(r.error_id.empty());
  const std::vector<std::string> mv = motions(r);
  REQUIRE(mv.size() == 4);
  CHECK(field(mv[0], "X") == doctest::Approx(1));   // the block's motion first
  CHECK(field(mv[1], "Z") == doctest::Approx(50));  // then the subroutine
  CHECK(field(mv[2], "X") == doctest::Approx(2));
  CHECK(field(mv[3], "Z") == doctest::Approx(70));  // #FILE NAME's subroutine
  CHECK_FALSE(has_line(r, "TECH M=6"));             // no M function
  // Not configured, the first M6 is an M function; after #FILE NAME the second one calls.
  const test::Run plain = run_on(cycle_machine(), f.dir / "main.nc");
  REQUIRE(plain.error_id.empty());
  CHECK(has_line(plain, "TECH M=6"));
  CHECK(motions(plain).size() == 3);
}

TEST_CASE("#FILE NAME [M6=\"\"] gives M6 the channel's m6_prog_file (P-CHAN-00118) again") {
  Folder f("m6reset");
  f.write("change.nc", "%change\nG00 Z50\nM17\n");
  f.write("other.nc", "%other\nG00 Z70\nM17\n");
  f.write("main.nc", "%main\n#FILE NAME [M6=\"other.nc\"]\nM6\n#FILE NAME [M6=\"\"]\nM6\nM30\n");
  machines::Machine m = cycle_machine();
  m.channel.m6_prog_file = "change.nc";
  const test::Run r = run_on(m, f.dir / "main.nc");
  REQUIRE(r.error_id.empty());
  const std::vector<std::string> mv = motions(r);
  REQUIRE(mv.size() == 2);
  CHECK(field(mv[0], "Z") == doctest::Approx(70));
  CHECK(field(mv[1], "Z") == doctest::Approx(50));
}

TEST_CASE("a D word also calls d_prog_file (P-CHAN-00429); with G80 in the block it is NC4308") {
  Folder f("dcall");
  f.write("tooldata.nc", "%tooldata\nG00 Y9\nM17\n");
  f.write("main.nc", "%main\nG00 X1 D0\nM30\n");
  f.write("two.nc", "%two\nG80 D0\nM30\n");
  machines::Machine m = cycle_machine();
  m.channel.d_prog_file = "tooldata.nc";
  const test::Run r = run_on(m, f.dir / "main.nc");
  REQUIRE(r.error_id.empty());
  const std::vector<std::string> mv = motions(r);
  REQUIRE(mv.size() == 2);
  CHECK(field(mv[0], "X") == doctest::Approx(1));
  CHECK(field(mv[1], "Y") == doctest::Approx(9));
  CHECK(has_line(r, "TECH D=0"));  // the D word itself still acts
  CHECK(run_on(m, f.dir / "two.nc").error_id == "NC4308");
}

TEST_CASE("two implicit calls in one block are NC4308; #FILE NAME of another G code is NC4309") {
  CHECK(run("%t\nG80 G81\nM30\n").error_id == "NC4308");
  CHECK(run("%t\n#FILE NAME [G01=\"x.nc\"]\nM30\n").error_id == "NC4309");
  CHECK(run("%t\n#FILE NAME [G805=5]\nM30\n").error_id == "NC4309");
}

TEST_CASE(
    "#VECTOR LIMIT ON [VEL] without a value takes the channel's vector.velocity "
    "(P-CHAN-00090)") {
  machines::Machine m = test::machine("portal_3x");
  m.channel.vector_velocity = 20.0;  // [mm/s] = 1200 mm/min
  const test::Run r =
      run_source(m, core::SourceFile("t.nc", "%t\n#VECTOR LIMIT ON [VEL]\nG01 X5 F6000\nM30\n"));
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "F") == doctest::Approx(20.0));
}

TEST_CASE("a bad character in an implicit call's list is 22151; more than 50 values too") {
  CHECK(run("%t\nG80 [12 !]\nM30\n").error_id == "22151");
  std::string many = "%t\nG80 [";
  for (int k = 0; k < 51; ++k)
    many += (k == 0 ? "" : ",") + std::to_string(k);
  CHECK(run(many + "]\nM30\n").error_id == "22151");
}

TEST_CASE("G54 shifts the next absolute position by V.G.NP[1]; G91 does not move by it") {
  const test::Run r =
      run("%t\nV.G.NP[1].V.X = 10\nV.G.NP[1].V.Y = -5\nG00 X0 Y0\nG54\nG00 X1\nG91 X1\nG90 Y0\n"
          "G53 X1\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[1], "X") == doctest::Approx(11));  // absolute: shifted
  CHECK(field(r.full[1], "Y") == doctest::Approx(0));   // Y not programmed: does not move
  CHECK(field(r.full[2], "X") == doctest::Approx(12));  // incremental: +1
  CHECK(field(r.full[3], "Y") == doctest::Approx(-5));
  CHECK(field(r.full[4], "X") == doctest::Approx(1));  // G53: deselected
}

TEST_CASE("G159=n selects group n; outside 0..96 is NC4311") {
  const test::Run r = run("%t\nV.G.NP[12].V.Z = 2.5\nG159=12\nG00 Z1\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "Z") == doctest::Approx(3.5));
  CHECK(run("%t\nG159=97\nM30\n").error_id == "NC4311");
}

TEST_CASE("#MCS ON moves in machine coordinates: the zero offset is off until #MCS OFF") {
  const test::Run r =
      run("%t\nV.G.NP[2].V.X = 100\nG55 G00 X1\n#MCS ON\nG00 X1\n#MCS OFF\nG00 X2\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "X") == doctest::Approx(101));
  CHECK(field(r.full[1], "X") == doctest::Approx(1));
  CHECK(field(r.full[2], "X") == doctest::Approx(102));
}

TEST_CASE("#SCALE scales programmed values about the zero point; a factor <= 0 is NC4312") {
  const test::Run r = run("%t\n#SCALE ON X2 Y0.5\nG01 X10 Y10 F100\n#SCALE OFF\nG01 X10\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "X") == doctest::Approx(20));
  CHECK(field(r.full[0], "Y") == doctest::Approx(5));
  CHECK(field(r.full[1], "X") == doctest::Approx(10));
  CHECK(run("%t\n#SCALE X0\nM30\n").error_id == "NC4312");
  CHECK(run("%t\n#SCALE X2 Y3\nG02 X1 Y1 I1 F100\nM30\n").error_id == "NC4312");
}

TEST_CASE("#VECTOR LIMIT ON [VEL=..] caps the feed; ACC is a warning, not silence") {
  const test::Run r = run_warn(
      "%t\n#VECTOR LIMIT ON [VEL=600 ACC=1000]\nG01 X10 F6000\n#VECTOR LIMIT OFF\nG01 X20\n"
      "M30\n");
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "F") == doctest::Approx(10));   // 600 mm/min
  CHECK(field(r.full[1], "F") == doctest::Approx(100));  // 6000 mm/min again
  CHECK(has_line(r, "warning NC4310"));
}

TEST_CASE("#HSC ON blends within PATH_DEV like G261; #HSC OFF restores G260") {
  const test::Run r = run("%t\n#HSC ON [PATH_DEV=0.02]\nG01 X10 F100\n#HSC OFF\nG01 X20\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.full[0].find("G261") != std::string::npos);
  CHECK(r.full[1].find("G261") == std::string::npos);
}

TEST_CASE("#CHANNEL INIT, #IDENT, #ORI MODE, #TOOL are accepted and shown in trace") {
  const test::Run r =
      run("% my first program\n#CHANNEL INIT [CONFIG]\n#IDENT [ID=7]\n#ORI MODE [A]\n#TOOL DATA "
          "[1]\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(has_line(r, "ACCEPTED \"#CHANNEL INIT [CONFIG]\""));
  CHECK(has_line(r, "ACCEPTED \"#IDENT [ID=7]\""));
  CHECK(has_line(r, "ACCEPTED \"#ORI MODE [A]\""));
}

TEST_CASE("#PSET makes the current position read as the value, without motion") {
  const test::Run r = run("%t\nG00 X50\n#PSET X0\nG00 X10\nG91 X5\nM30\n");
  REQUIRE(r.error_id.empty());
  REQUIRE(r.full.size() >= 3);
  CHECK(field(r.full[1], "X") == doctest::Approx(60));  // X0 is where X50 was
  CHECK(field(r.full[2], "X") == doctest::Approx(65));
  CHECK(run("%t\n#PSET Q1\nM30\n").error_id == "NC4103");
}

TEST_CASE("the channel's feed unit (P-CHAN-00108) and default feed (P-CHAN-00099) apply to F") {
  machines::Machine m = test::machine("portal_3x");
  m.channel.feedrate_factor = 0.1;  // F in m/min
  m.channel.default_feed = 500.0 / 60.0;
  const test::Run r = run_source(m, core::SourceFile("t.nc", "%t\nG01 X1\nG01 X2 F3\nM30\n"));
  REQUIRE(r.error_id.empty());
  CHECK(field(r.full[0], "F") == doctest::Approx(500.0 / 60.0));  // before any F: the default
  CHECK(field(r.full[1], "F") == doctest::Approx(50.0));          // 3 m/min = 50 mm/s
}

TEST_CASE("G134 is warning NC4313 (P-AXIS-00199 unmodelled); G130 X70 weights X") {
  const test::Run r =
      run_warn("%t\nG00 X1\nG130 X70 Y50\nG231=80 G00 X5\nG131=50\nG134=70\nG134=60\nM30\n");
  REQUIRE(r.error_id.empty());
  int unmodelled = 0;
  for (const auto& l : r.lines)
    unmodelled += l.find("warning NC4313") != std::string::npos;
  CHECK(unmodelled == 1);  // G134, once; G130, G231 and G131 are applied
  REQUIRE(r.full.size() >= 2);
  CHECK(field(r.full[1], "X") == doctest::Approx(5));  // the next motion is the G231 block's
}

TEST_CASE(
    "feed-hold weightings G333/G334/G338/G339 change nothing with P-CHAN-00097 = 0 [NC4315]") {
  // PROG-206590731 / PROG-206596619: they weight the feed-hold ramps P-AXIS-00053 / 00081, which
  // a feed hold uses only with P-CHAN-00097 = 1; ncsim's channel decelerates at the currently
  // valid deceleration (P-CHAN-00097 = 0), so the motions are the same as without them.
  const std::string plain = "%t\nG01 X10 Y5 F600\nG01 X20\nM30\n";
  const std::string weighted =
      "%t\nG333 X50 Y40\nG334=30\nG01 X10 Y5 F600\nG338 X300\nG339=200 G01 X20\nG334=20\nM30\n";
  const test::Run a = run_warn(plain);
  const machines::Machine& m = test::machine("portal_3x");
  const core::SourceFile file("test.nc", weighted);
  Interpreter interp(file, m, {});
  std::vector<std::string> motions;
  while (auto c = interp.next_decode_only()) {
    if (std::holds_alternative<Motion>(c->body)) {
      const std::string l = to_trace_line(*c, m);
      motions.push_back(l.substr(l.find(':')));  // without the line number
    }
  }
  REQUIRE(interp.error() == nullptr);
  std::vector<std::string> plain_motions;
  for (const auto& l : a.full)
    if (l.find(" G01 ") != std::string::npos) plain_motions.push_back(l.substr(l.find(':')));
  CHECK(motions == plain_motions);  // G333 X50 Y40 and G338 X300 are weights, not positions
  int notes = 0;
  for (const auto& d : interp.diagnostics().items()) {
    CHECK(d.id != "NC4313");
    if (d.id == "NC4315") {
      ++notes;
      CHECK(d.severity == core::Severity::note);
      CHECK(d.message.find("P-CHAN-00097") != std::string::npos);
    }
  }
  CHECK(notes == 4);  // once per code
}

}  // namespace
}  // namespace ncsim::interp
