// Regression tests for what the interpreter fuzz target (tests/fuzz/fuzz_interp.cpp) found,
// one test per root cause; the crashing inputs themselves are in tests/fuzz/regressions/.
#include <doctest/doctest.h>

#include <string>

#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

/// Runs `text` as a program file placed in interp/testdata/ (next to sub_move.nc).
test::Run run_in_testdata(const std::string& text, Options options) {
  const std::string name = (test::source_root() / "interp/testdata/virtual.nc").string();
  return test::run_file(core::SourceFile(name, text), "portal_3x", std::move(options), 100);
}

TEST_CASE("with confined subroutine files, L opens a plain name next to the program") {
  Options options;
  options.confine_subroutine_files = true;
  const auto r = run_in_testdata("%v\nP1 = 2\nV.P.LEN = 0\nL sub_move.nc\nM30\n", options);
  CHECK(r.error_id.empty());
  REQUIRE(r.lines.size() == 2);
  CHECK(r.lines[0] == "2: G00 X=2.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("with confined subroutine files, L with an absolute path or .. is NC4301") {
  Options options;
  options.confine_subroutine_files = true;
  const std::string absolute = (test::source_root() / "interp/testdata/sub_move.nc").string();
  for (const std::string& name : {absolute, std::string("../testdata/sub_move.nc"),
                                  std::string("./../testdata/sub_move.nc")}) {
    CAPTURE(name);
    const auto r = run_in_testdata("%v\nP1 = 2\nV.P.LEN = 0\nL " + name + "\nM30\n", options);
    CHECK(r.error_id == "NC4301");
    CHECK(r.error_line == 4);
    CHECK(r.lines.empty());
  }
  // Without the option the same paths are opened (the manual allows a path, PROG-206834699).
  const auto open =
      run_in_testdata("%v\nP1 = 2\nV.P.LEN = 0\nL " + absolute + "\nM30\n", Options{});
  CHECK(open.error_id.empty());
}

TEST_CASE("a macro that grows the block beyond 4000 characters is NC4007 at its line") {
  // Each pass triples the text: before the fix 16 passes built a 3^16-fold block (many GB).
  const auto r = test::run("%t\n\"A\" = \"\\\"A\\\"\\\"A\\\"\\\"A\\\"\"\nX[\"A\"]\nM30\n");
  CHECK(r.error_id == "NC4007");
  CHECK(r.error_line == 3);
  CHECK(r.error_message.find("4000") != std::string::npos);
  CHECK(r.lines.empty());
  // A macro text that is long but fits stays valid.
  const std::string sum = "1" + std::string(60, ' ') + "+1";
  const auto ok = test::run("%t\n\"B\" = \"" + sum + "\"\nX[\"B\" + \"B\" + \"B\"]\nM30\n");
  CHECK(ok.error_id.empty());
  REQUIRE(ok.lines.size() == 2);
  CHECK(ok.lines[0] == "3: G00 X=6.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("an array declared with more than 1,000,000 elements is NC4015, not an allocation") {
  // 100000 x 100000 REAL64 asked for 80 GB and ended in std::bad_alloc.
  const auto big = test::run("%t\n#VAR\n  V.P.A[100000][100000] : REAL\n#ENDVAR\nG00 X1\nM30\n");
  CHECK(big.error_id == "NC4015");
  CHECK(big.error_line == 3);
  CHECK(big.error_message.find("1000000") != std::string::npos);
  CHECK(big.lines.empty());
  // A dimension far beyond uint32 (was an undefined float-to-integer conversion).
  const auto huge = test::run(
      "%L SUB\n#VAR\n  V.L.A[P1] : REAL\n#ENDVAR\nM17\n%main\nP1 = 10 ** 30\nLL SUB\nM30\n");
  CHECK(huge.error_id == "NC4015");
  CHECK(huge.error_line == 3);
  // The largest array allowed is declared and usable.
  const auto fits = test::run(
      "%t\n#VAR\n  V.P.A[1000][1000] : REAL\n#ENDVAR\nV.P.A[999][999] = 4\n"
      "G00 X[V.P.A[999][999]]\nM30\n");
  CHECK(fits.error_id.empty());
  REQUIRE(!fits.lines.empty());
  CHECK(fits.lines[0] == "6: G00 X=4.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("a coordinate that overflows in inch conversion or G91 addition is NC4101") {
  // G70 multiplied 1e307 inch by 25.4 into an infinite X that reached the planner.
  const auto inch = test::run("%t\nG70 G01 X[10 ** 307] F100\nM30\n");
  CHECK(inch.error_id == "NC4101");
  CHECK(inch.error_line == 2);
  CHECK(inch.lines.empty());
  const auto centre = test::run("%t\nG70 G02 X0 Y0 I[10 ** 307] J0 F100\nM30\n");
  CHECK(centre.error_id == "NC4101");
  // (G00: a G01 that far at F100 is NC4032 first, longer than a day)
  const auto incremental = test::run("%t\nG00 X[10 ** 308]\nG91 G00 X[10 ** 308]\nM30\n");
  CHECK(incremental.error_id == "NC4101");
  CHECK(incremental.error_line == 3);
  REQUIRE(incremental.lines.size() == 1);
  const auto arc =
      test::run("%t\nG00 X[10 ** 308]\nG02 X[-10 ** 308] Y0 I[-10 ** 308] J0 F100\nM30\n");
  CHECK(arc.error_id == "NC4101");
  CHECK(arc.error_line == 3);
  // Large but representable values stay motions.
  const auto large = test::run("%t\nG70 G00 X[10 ** 300]\nM30\n");
  CHECK(large.error_id.empty());
}

}  // namespace
}  // namespace ncsim::interp
