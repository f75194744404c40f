// Expression evaluation (isg-language.md §3.1-3.3), through P1 = <expr> and G00 X[P1].
#include <doctest/doctest.h>

#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

using test::value_line;

std::string x(const char* v) {
  return std::string("3: G00 X=") + v + " Y=0.0000 Z=0.0000";
}

TEST_CASE("multiplication binds tighter than addition and brackets group") {
  CHECK(value_line("2 + 3 * 4") == x("14.0000"));
  CHECK(value_line("[2 + 3] * 4") == x("20.0000"));
}

TEST_CASE("power, MOD and unary minus follow the documented examples") {
  CHECK(value_line("2 ** 3") == x("8.0000"));
  CHECK(value_line("11 MOD 3") == x("2.0000"));
  CHECK(value_line("-2 + 5") == x("3.0000"));
}

TEST_CASE("trigonometric functions take and return degrees") {
  CHECK(value_line("SIN[30]") == x("0.5000"));
  CHECK(value_line("COS[60]") == x("0.5000"));
  CHECK(value_line("ATAN[1]") == x("45.0000"));
  CHECK(value_line("ACOS[0]") == x("90.0000"));
}

TEST_CASE("rounding functions and square root") {
  CHECK(value_line("INT[-2.7]") == x("-2.0000"));
  CHECK(value_line("ROUND[2.5]") == x("3.0000"));
  CHECK(value_line("FRACT[1.25]") == x("0.2500"));
  CHECK(value_line("SQRT[16] + SQR[3]") == x("13.0000"));
  CHECK(value_line("FLOOR[-1.5] + CEIL[1.2]") == x("0.0000"));
}

TEST_CASE("a value counts as TRUE from 0.5 on") {
  CHECK(value_line("[0.5 && 1]") == x("1.0000"));
  CHECK(value_line("[0.49 || 0]") == x("0.0000"));
  CHECK(value_line("NOT 0.4") == x("1.0000"));
}

TEST_CASE("comparisons and bit operations give numbers") {
  CHECK(value_line("[3 > 2] + [2 == 2] + [1 != 1]") == x("2.0000"));
  CHECK(value_line("[6 & 3] + [4 | 1] + [3 ^ 1]") == x("9.0000"));
}

TEST_CASE("hexadecimal literals are numbers") {
  CHECK(value_line("'16#10'") == x("16.0000"));
}

TEST_CASE("division by zero is error 20396 at its line") {
  auto r = test::run("%t\nP1 = 10 / COS[90]\nM30\n");
  CHECK(r.error_id == "20396");
  CHECK(r.error_line == 2);
  CHECK(test::run("%t\nP1 = 5 MOD 0\nM30\n").error_id == "20396");
}

TEST_CASE("domain errors are NC4101") {
  CHECK(value_line("SQRT[-1]") == "error NC4101");
  CHECK(value_line("LN[0]") == "error NC4101");
  CHECK(value_line("ASIN[2]") == "error NC4101");
}

TEST_CASE("a result that is not a finite number is NC4101, never a motion to inf or NaN") {
  CHECK(value_line("DEXP[400]") == "error NC4101");
  CHECK(value_line("EXP[1000]") == "error NC4101");
  CHECK(value_line("2 ** 5000") == "error NC4101");
  // reported at the operation that overflowed, here the product inside the addition
  auto r = test::run("%t\nP1 = 1 + 1000000 * DEXP[303]\nM30\n");
  CHECK(r.error_id == "NC4101");
  CHECK(r.error_line == 2);
  auto in_motion = test::run("%t\nG01 X[DEXP[400]] F100\nM30\n");
  CHECK(in_motion.error_id == "NC4101");
  CHECK(in_motion.lines.empty());
}

TEST_CASE("P0 and a negative P index are error 20400") {
  CHECK(test::run("%t\nP0 = 1\nM30\n").error_id == "20400");
  CHECK(test::run("%t\nP5[-1] = 1\nM30\n").error_id == "20400");
}

TEST_CASE("reading a P parameter never written is NC4010") {
  CHECK(value_line("P77 + 1") == "error NC4010");
}

TEST_CASE("P arrays are created on write") {
  auto r = test::run("%t\nP100[3] = 7\nG00 X[P100[3]]\nM30\n");
  CHECK(r.error_id.empty());
  CHECK(r.lines.at(0) == "3: G00 X=7.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("implicit P arrays hold at most 1,000,000 elements in all (20400 beyond)") {
  // ten arrays of 100,001 elements would be 1,000,010: the tenth write is refused
  std::string text = "%t\n";
  for (int n = 1; n <= 10; ++n)
    text += "P" + std::to_string(n) + "[100000] = 1\n";
  const auto r = test::run(text + "M30\n");
  CHECK(r.error_id == "20400");
  CHECK(r.error_line == 11);
  // rewriting existing elements costs nothing more
  std::string again = "%t\n";
  for (int k = 0; k < 30; ++k)
    again += "P1[99999] = " + std::to_string(k) + "\n";
  CHECK(test::run(again + "M30\n").error_id.empty());
}

TEST_CASE("V.E. values come from the caller and a read flushes the channel") {
  Options o;
  o.external["WIDTH"] = 12.5;
  auto r = test::run("%t\nG00 X[V.E.WIDTH]\nM30\n", "portal_3x", o);
  REQUIRE(r.lines.size() >= 2);
  CHECK(r.lines[0] == "2: BARRIER FLUSH V.E.READ V.E.WIDTH");
  CHECK(r.lines[1] == "2: G00 X=12.5000 Y=0.0000 Z=0.0000");
}

TEST_CASE("V.S. variables persist across runs sharing a store") {
  PersistentVariables store;
  Options o;
  o.persistent = &store;
  test::run("%t\nV.S.COUNT = 3\nM30\n", "portal_3x", o);
  auto r = test::run("%t\nG00 X[V.S.COUNT]\nM30\n", "portal_3x", o);
  CHECK(r.lines.at(0) == "2: G00 X=3.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("string macros are replaced textually, also inside macros") {
  auto r = test::run("%t\n\"A\" = \"2 * 3\"\n\"B\" = \"[\\\"A\\\" + 1]\"\nG00 X[\"B\"]\nM30\n");
  CHECK(r.error_id.empty());
  CHECK(r.lines.at(0) == "4: G00 X=7.0000 Y=0.0000 Z=0.0000");
}

TEST_CASE("a macro that contains itself stops at the recursion limit") {
  auto r = test::run("%t\n\"A\" = \"[\\\"A\\\" + 1]\"\nG00 X[\"A\"]\nM30\n");
  CHECK(r.error_id == "NC4006");
}

}  // namespace
}  // namespace ncsim::interp
