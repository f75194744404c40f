#include "machines/list_file.hpp"

#include <doctest/doctest.h>

namespace ncsim::machines {
namespace {

ListParse parse(std::string text) {
  return parse_list(core::SourceFile("t.lis", std::move(text)));
}

TEST_CASE("a list line gives key, value and position; comments are skipped") {
  const ListParse p = parse(
      "# header comment\n"
      "\n"
      "kenngr.swe_pos   40000000   (P-AXIS-00178\n"
      "  conveyor_sync.log_number_master 3 #spindle\n");
  REQUIRE(p.diagnostics.empty());
  REQUIRE(p.entries.size() == 2);
  CHECK(p.entries[0].key == "kenngr.swe_pos");
  CHECK(p.entries[0].value == "40000000");
  CHECK(p.entries[0].key_loc == core::SourceLoc{3, 1});
  CHECK(p.entries[0].value_loc == core::SourceLoc{3, 18});
  CHECK(p.entries[1].value == "3");
  CHECK(p.entries[1].key_loc.line == 4);
}

TEST_CASE("indexed keys give a pattern and their indices") {
  const ListParse p = parse("trafo[0].param[12] -1800000\ngetriebe[1].window 500\n");
  REQUIRE(p.entries.size() == 2);
  CHECK(p.entries[0].pattern == "trafo[].param[]");
  CHECK(p.entries[0].indices == std::vector<int>{0, 12});
  CHECK(p.entries[0].value == "-1800000");
  CHECK(p.entries[1].pattern == "getriebe[].window");
}

TEST_CASE("flag combinations with blanks around | are joined") {
  const ListParse p = parse("configuration.interpolator.function FCT_IPO_DEFAULT | FCT_SYNC\n");
  REQUIRE(p.entries.size() == 1);
  CHECK(p.entries[0].value == "FCT_IPO_DEFAULT|FCT_SYNC");
}

TEST_CASE("exponent and hex values are kept as written") {
  const ListParse p = parse("a.b 5.000e+004\nkenngr.achs_mode 0x00100001\n");
  REQUIRE(p.entries.size() == 2);
  CHECK(p.entries[0].value == "5.000e+004");
  CHECK(p.entries[1].value == "0x00100001");
}

TEST_CASE("a key without a value is reported at its line") {
  const ListParse p = parse("kopf.achs_nr 1\nkenngr.swe_pos   # nothing\n");
  REQUIRE(p.diagnostics.size() == 1);
  CHECK(p.diagnostics[0].id == "NC3001");
  CHECK(p.diagnostics[0].loc.line == 2);
  CHECK(p.entries.size() == 1);
}

TEST_CASE("text after a value that is not a comment is an error") {
  const ListParse p = parse("kenngr.swe_pos 100 200\n");
  REQUIRE(p.diagnostics.size() == 1);
  CHECK(p.diagnostics[0].loc == core::SourceLoc{1, 20});
  CHECK(p.diagnostics[0].message.find("kenngr.swe_pos (P-AXIS-00178)") != std::string::npos);
}

TEST_CASE("NC3001 messages name the parameter id of a known key, of either list") {
  const ListParse axis = parse("kenngr.swe_neg\n");
  REQUIRE(axis.diagnostics.size() == 1);
  CHECK(axis.diagnostics[0].message == "missing value after key kenngr.swe_neg (P-AXIS-00177)");
  const ListParse channel = parse("conveyor_sync.move_direction 1 2\n");
  REQUIRE(channel.diagnostics.size() == 1);
  CHECK(channel.diagnostics[0].message.find("conveyor_sync.move_direction (P-CHAN-00363)") !=
        std::string::npos);
  const ListParse unknown = parse("no.such.key 1 2\n");
  REQUIRE(unknown.diagnostics.size() == 1);
  CHECK(unknown.diagnostics[0].message.find("'no.such.key'") != std::string::npos);
}

TEST_CASE("a line whose value is malformed is kept as rejected, so its key is not missing") {
  const ListParse p = parse("kopf.achs_nr 1 2\ntrafo[0].param[3] $\n");
  CHECK(p.entries.empty());
  REQUIRE(p.rejected.size() == 2);
  CHECK(p.rejected[0].key == "kopf.achs_nr");
  CHECK(p.rejected[1].pattern == "trafo[].param[]");
  CHECK(p.rejected[1].indices == std::vector<int>{0, 3});
}

TEST_CASE("a UTF-8 byte order mark at the start of a list is skipped with note NC3021") {
  const ListParse p = parse("\xEF\xBB\xBFkopf.achs_nr 1\n");
  REQUIRE(p.diagnostics.size() == 1);
  CHECK(p.diagnostics[0].id == "NC3021");
  CHECK(p.diagnostics[0].severity == core::Severity::note);
  CHECK(p.diagnostics[0].loc == core::SourceLoc{1, 1});
  REQUIRE(p.entries.size() == 1);
  CHECK(p.entries[0].key == "kopf.achs_nr");
  CHECK(p.entries[0].key_loc == core::SourceLoc{1, 4});
}

TEST_CASE("a byte order mark after the start is a stray byte, shown escaped") {
  const ListParse p = parse("kopf.achs_nr 1\n\xEF\xBB\xBFkenngr.swe_pos 1\n");
  REQUIRE(p.diagnostics.size() == 1);
  CHECK(p.diagnostics[0].id == "NC3001");
  CHECK(p.diagnostics[0].loc.line == 2);
  CHECK(p.diagnostics[0].message.find("'\\xEF'") != std::string::npos);
  CHECK(p.diagnostics[0].message.find('\xEF') == std::string::npos);
}

TEST_CASE("malformed indices are errors") {
  CHECK(parse("trafo[x].id 1\n").diagnostics.size() == 1);
  CHECK(parse("trafo[].id 1\n").diagnostics.size() == 1);
  CHECK(parse("trafo]0[.id 1\n").diagnostics.size() == 1);
  CHECK(parse("kenngr.swe=pos 1\n").diagnostics.size() == 1);
}

TEST_CASE("a dangling | in a flag value is an error") {
  const ListParse p = parse("configuration.interpolator.function FCT_DLM |\n");
  REQUIRE(p.diagnostics.size() == 1);
  CHECK(p.diagnostics[0].id == "NC3001");
}

}  // namespace
}  // namespace ncsim::machines
