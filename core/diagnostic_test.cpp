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
