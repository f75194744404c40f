#include <doctest/doctest.h>

#include "grammar/test_support.hpp"

namespace ncsim::grammar::test {

using V = std::vector<std::string>;

TEST_CASE("an unclosed $IF is reported at its line") {
  CHECK(check("%main\nG01 X1\n$IF P1\nG01 X2\nM30\n") == V{"3:1 NC2001"});
}

TEST_CASE("balanced control flow checks clean") {
  CHECK(check("$IF 1\n$ELSEIF 2\n$ELSE\n$ENDIF\n$SWITCH P1\n$CASE 1\n$BREAK\n$DEFAULT\n"
              "$ENDSWITCH\n$FOR P1 = 1, 3, 1\n$CONTINUE\n$ENDFOR\n$WHILE 1\n$BREAK\n$ENDWHILE\n"
              "$DO\n$ENDDO 0\n$REPEAT\n$UNTIL 1\nM30\n")
            .empty());
}

TEST_CASE("misplaced $ELSE, $ELSEIF, $ENDIF carry the manual's ids") {
  CHECK(check("$ELSE\n") == V{"1:1 20214"});
  CHECK(check("$IF 1\n$ELSE\n$ELSEIF 1\n$ENDIF\n") == V{"3:1 20216"});
  CHECK(check("$IF 1\n$ELSE\n$ELSE\n$ENDIF\n") == V{"3:1 20214"});
  CHECK(check("$ENDIF\n") == V{"1:1 20218"});
  CHECK(check("$IF 1\n$ENDIF X1\n") == V{"2:8 20219"});
  CHECK(check("$ENDWHILE\n") == V{"1:1 20237"});
}

TEST_CASE("$BREAK needs a loop or switch, $CONTINUE a loop") {
  CHECK(check("$BREAK\n") == V{"1:1 20243"});
  CHECK(check("$SWITCH 1\n$CASE 1\n$CONTINUE\n$ENDSWITCH\n") == V{"3:1 20244"});
  CHECK(check("$WHILE 1\n$IF 1\n$BREAK\n$ENDIF\n$ENDWHILE\n").empty());
}

TEST_CASE("labels are per program level; $GOTO into a loop is 21480") {
  CHECK(check("%L SUB\nN10: X1\nM17\n%main\n$GOTO N10\nM30\n") == V{"5:7 NC2012"});
  CHECK(check("$GOTO N10\n$WHILE 1\nN10: X1\n$ENDWHILE\n") == V{"1:7 21480"});
  CHECK(check("$WHILE 1\n$GOTO [OUT]\n$ENDWHILE\n[OUT]\nM30\n").empty());
  CHECK(check("N10: X1\nN10: X2\n") == V{"2:1 NC2011"});
  CHECK(check("$GOTO [end]\n[END]\n").empty());  // labels are case-insensitive
}

TEST_CASE("subroutines: local after main, LL without %L, call not last") {
  CHECK(check("G01 X1\n%L SUB\nM17\n") == V{"2:1 NC2013"});
  CHECK(check("%main\nLL NOPE\nM30\n") == V{"2:1 NC2014"});
  CHECK(check("%L SUB\nM17\n%main\nLL sub\nM30\n").empty());
  CHECK(check("%L SUB\nM17\n%main\nLL SUB X1\nM30\n") == V{"4:8 21542"});
}

TEST_CASE("#IF: a block number before it is 20593; the #ELSE branch is syntax-only") {
  CHECK(check("N10 #IF 1\n#ENDIF\n") == V{"1:1 20593"});
  CHECK(check("#IF 1\n$IF 1\n#ELSE\n$IF 2\n#ENDIF\n$ENDIF\n").empty());
  CHECK(check("#IF 1\n#ELSE\nG01 X[\n#ENDIF\n") == V{"3:7 NC1001"});
  CHECK(check("#IF 1\n") == V{"1:1 NC2015"});
}

TEST_CASE("unknown G and M codes, unknown bracket keywords") {
  CHECK(check("G123\n") == V{"1:1 20131"});
  CHECK(check("G81\n").empty());  // an implicit call: the interpreter knows its subroutine
  CHECK(check("G805 [ -27.120, 28.955,, 2.870 ]\n").empty());
  CHECK(check("G840\n") == V{"1:1 20131"});
  CHECK(check("M200=1200 H5=-345\n").empty());  // M/H with an additional value
  CHECK(check("% 1x10 dots right\nM30\n").empty());
  CHECK(check("M1000\n") == V{"1:1 NC2009"});
  CHECK(check("M2.5\n") == V{"1:1 NC2009"});
  CHECK(check("M10 M11 M50 M3 M999\n").empty());  // technology functions for the PLC
  CHECK(check("#SYNC IN [CONV_VEL=1 BOGUS=2]\n") == V{"1:22 NC2010"});
}

TEST_CASE("a main program without M02/M30 is warning NC2019 at its last block") {
  const auto ids = [](const std::string& text) {
    const core::SourceFile file("t.nc", text);
    std::vector<std::string> out;
    const core::DiagnosticList diags = check_program(file);
    for (const auto& d : diags.items()) {
      out.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " + d.id +
                    (d.severity == core::Severity::warning ? " warning" : ""));
    }
    return out;
  };
  CHECK(ids("%p\nG01 X1 F100\nG01 X2\n") == V{"3:1 NC2019 warning"});
  CHECK(ids("%p\nG01 X1 F100\nM30\n").empty());
  CHECK(ids("%p\nG01 X1 F100\n$IF P1 > 0\nM02\n$ENDIF\nX0\n").empty());
  // an M30 in a local subroutine does not end the main program
  CHECK(ids("%L sub\nM30\nM17\n%main\nLL sub\n") == V{"5:1 NC2019 warning"});
  // a global subroutine file returns with M17 / M29
  CHECK(ids("%sub\nG91 X1\nM17\n").empty());
  // issue 9: an empty program has no M02/M30 either
  CHECK(ids("") == V{"0:0 NC2019 warning"});
  CHECK(ids("%\n") == V{"1:1 NC2019 warning"});
  CHECK(ids("%p\n; nothing\n(at all)\n") == V{"1:1 NC2019 warning"});
  CHECK(ids("%L sub\nM17\n") == V{"0:0 NC2019 warning"});
}

TEST_CASE("a UTF-8 byte order mark is skipped with note NC1006") {
  const core::SourceFile file("t.nc", "\xEF\xBB\xBF%p\nG01 X1 F100\nM30\n");
  const core::DiagnosticList diags = check_program(file);
  REQUIRE(diags.items().size() == 1);
  CHECK(diags.items()[0].id == "NC1006");
  CHECK(diags.items()[0].severity == core::Severity::note);
  CHECK(!diags.has_errors());
}

TEST_CASE("a comment-only line is no block whatever its length, ( ) as ;") {
  const std::string paren = "(" + std::string(5000, 'a') + " (nested) )  ; and more\n";
  const std::string semi = ";" + std::string(5000, 'b') + "\n";
  const core::SourceFile file("t.nc", "%p\n" + paren + semi + "G01 X1 F100\nM30\n");
  CHECK(check_program(file).items().empty());
  // A long line with a word after its comment is still a block, and too long (NC1003).
  const core::SourceFile word("t.nc", "%p\n(" + std::string(5000, 'a') + ") X1\nM30\n");
  const auto d = check_program(word);
  REQUIRE(d.items().size() == 1);
  CHECK(d.items()[0].id == "NC1003");
}

}  // namespace ncsim::grammar::test
