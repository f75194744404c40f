// The trace driver: exact numbers of any magnitude, an honest end when it is cut short.
#include <doctest/doctest.h>

#include <sstream>

#include "grammar/check.hpp"
#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

std::string trace(const std::string& text, std::uint64_t max_commands = 0) {
  core::SourceFile file("test.nc", text);
  TraceOptions options;
  options.max_commands = max_commands;
  std::ostringstream out;
  core::DiagnosticList diags;
  write_trace(file, test::machine(), options, out, diags);
  return out.str();
}

TEST_CASE("issue 9 defect 2: a coordinate of 1e80 is printed in full, the same every time") {
  // (a dwell of 1e80 s, the first form of this test, is 20752 since issue 34: beyond a day)
  const std::string text = "%t\nP1 = 1" + std::string(80, '0') + "\nG00 X[P1]\nM30\n";
  const std::string first = trace(text);
  CHECK(first == trace(text));
  // The double nearest 1e80, every digit of it.
  CHECK(
      first.starts_with("3: G00 X=10000000000000000002660986470836727653740240118120080909813"
                        "1977453489758916313088.0000 "));
}

TEST_CASE("the largest double is printed in fixed notation without truncation") {
  Command c{2, 0, Dwell{1.7976931348623157e308}};
  const std::string line = to_trace_line(c, test::machine());
  CHECK(line.size() == std::string("2: DWELL t=").size() + 309 + 5);
  CHECK(line.ends_with(".0000"));
}

TEST_CASE("issue 9 defect 7: a trace cut at --max-commands ends with a marker line") {
  const std::string text = "%t\n$WHILE [TRUE]\nG00 X1\nG00 X2\n$ENDWHILE\nM30\n";
  const std::string out = trace(text, 3);
  CHECK(out.ends_with("# truncated after 3 commands (--max-commands)\n"));
  // A program that ends within the cap has no marker.
  CHECK(trace("%t\nG00 X1\nM30\n", 2).find("truncated") == std::string::npos);
}

/// Every diagnostic of `list`, formatted, one a line, and the dropped count.
std::string listed(const core::DiagnosticList& list) {
  std::string out;
  for (const core::Diagnostic& d : list.items())
    out += core::format(d);
  return out + "dropped " + std::to_string(list.dropped()) + '\n';
}

/// The syntax check fed by check_semantics' parse of `text`, and check_program's.
std::pair<std::string, std::string> shared_and_own_check(const std::string& text) {
  const core::SourceFile file("test.nc", text);
  grammar::ProgramCheck shared(file);
  check_semantics(file, test::machine(), {}, &shared);
  return {listed(shared.finish()), listed(grammar::check_program(file))};
}

TEST_CASE("the syntax check fed by the semantic check's parse equals check_program") {
  // clean; an error after M30; after a run-time error; structure errors found at the end;
  // a loop whose body is read twice; an error inside the loop the interpreter stops at
  const char* const programs[] = {
      "%t\nG01 X1 F100\nM30\n",
      "%t\nG01 X1 F100\nM30\nG01 X[1+*2]\n$ENDIF\nN10 G01 Y]\n",
      "%t\nG01 X1\nG01 X[1+*2]\n$IF 1\n",
      "%t\n$WHILE P1 < 3\nP1 = P1 + 1\nG01 X[P1] F100\n$GOTO N99\nM30\n",
      "%t\n$FOR P1 = 1, 3, 1\nG01 X[P1] F100\n$ENDFOR\nG04 X\nM30\n",
      "%t\n$FOR P1 = 1, 3, 1\nG01 X[P1] F100\nG01 Y[*]\n$ENDFOR\nM30\n",
  };
  for (const char* text : programs) {
    CAPTURE(text);
    const auto [shared, own] = shared_and_own_check(text);
    CHECK(shared == own);
  }
  // A loop body longer than the block cache is read again by the second parser: its blocks
  // reach the syntax check once (a $ENDFOR fed twice would be an error of its own).
  std::string long_loop = "%t\n$FOR P1 = 1, 2, 1\n";
  for (int i = 0; i < 3000; ++i)
    long_loop += "G01 X" + std::to_string(i % 7) + " F100\n";
  long_loop += "$ENDFOR\nM30\nG01 X[*]\n";
  const auto [shared, own] = shared_and_own_check(long_loop);
  CHECK(shared == own);
  // and the errors are there to compare
  CHECK(shared_and_own_check(programs[1]).first.find("NC1001") != std::string::npos);
}

}  // namespace
}  // namespace ncsim::interp
