// The trace driver: exact numbers of any magnitude, an honest end when it is cut short.
#include <doctest/doctest.h>

#include <sstream>

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

}  // namespace
}  // namespace ncsim::interp
