#include "core/diagnostic.hpp"

#include <doctest/doctest.h>

using namespace ncsim::core;

TEST_CASE("a diagnostic prints as file:line:col: error: text [id] with source line and caret") {
  const Diagnostic d{Severity::error, "prog.nc", {3, 5}, "20218", "unexpected $ENDIF"};
  CHECK(format(d, "N30 $ENDIF") ==
        "prog.nc:3:5: error: unexpected $ENDIF [20218]\n"
        "N30 $ENDIF\n"
        "    ^\n");
}

TEST_CASE("the caret keeps tabs of the source line") {
  const Diagnostic d{Severity::warning, "p.nc", {1, 3}, "NC1000", "w"};
  CHECK(format(d, "\tX?") == "p.nc:1:3: warning: w [NC1000]\n\tX?\n\t ^\n");
}

TEST_CASE("a diagnostic without position or file prints the message alone") {
  CHECK(format(Diagnostic{Severity::error, "", {}, "", "no program given"}) ==
        "error: no program given\n");
  CHECK(format(Diagnostic{Severity::error, "m.txt", {}, "NC3001", "bad"}) ==
        "m.txt: error: bad [NC3001]\n");
}

TEST_CASE("the list counts errors, not warnings") {
  DiagnosticList list;
  list.add({Severity::warning, "a", {1, 1}, "21483", "limited"});
  CHECK_FALSE(list.has_errors());
  list.add({Severity::error, "a", {2, 1}, "20218", "x"});
  CHECK(list.error_count() == 1);
  CHECK(list.items().size() == 2);
}

TEST_CASE("raw bytes in the echo and the message print as \\xHH, valid UTF-8 stays") {
  const Diagnostic d{Severity::error, "p.nc", {1, 5}, "NC1001", "found '\x1b'"};
  const std::string line = std::string("X1\x1b[2J") + "\xC3\xA4" + std::string("\0\xFF", 2);
  CHECK(format(d, line) ==
        "p.nc:1:5: error: found '\\x1B' [NC1001]\n"
        "X1\\x1B[2J\xC3\xA4\\x00\\xFF\n"
        "       ^\n");
  CHECK(printable("a\x7f\xE2\x82") == "a\\x7F\\xE2\\x82");  // DEL, a cut-off sequence
  CHECK(printable("\xE2\x82\xAC") == "\xE2\x82\xAC");       // the euro sign
}

TEST_CASE("a long source line is echoed as a window around the column") {
  const std::string line = std::string(100000, 'A') + "?" + std::string(100000, 'B');
  const Diagnostic d{Severity::error, "p.nc", {1, 100001}, "NC1001", "x"};
  const std::string text = format(d, line);
  CHECK(text.size() < 2 * kEchoWidth + 100);
  const auto echo_begin = text.find('\n') + 1;
  const auto echo_end = text.find('\n', echo_begin);
  const std::string echo = text.substr(echo_begin, echo_end - echo_begin);
  const std::string caret = text.substr(echo_end + 1, text.size() - echo_end - 2);
  CHECK(echo.rfind("...", 0) == 0);
  CHECK(echo.ends_with("..."));
  REQUIRE(caret.size() <= echo.size());
  CHECK(echo[caret.size() - 1] == '?');  // the caret stands under the offending byte
}

TEST_CASE("a list keeps the first diagnostics up to its limit and counts the rest") {
  DiagnosticList list(3);
  for (int i = 0; i < 10; ++i)
    list.add({i % 2 == 0 ? Severity::error : Severity::warning, "a", {1, 1}, "X", "m"});
  CHECK(list.items().size() == 3);
  CHECK(list.dropped() == 7);
  CHECK(list.error_count() == 5);
}

TEST_CASE("edit distance counts insertions, deletions and substitutions") {
  CHECK(edit_distance("", "") == 0);
  CHECK(edit_distance("swe_poss", "swe_pos") == 1);
  CHECK(edit_distance("vb_eilgng", "vb_eilgang") == 1);
  CHECK(edit_distance("kitten", "sitting") == 3);
  CHECK(edit_distance("abc", "") == 3);
}
