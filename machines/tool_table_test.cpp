#include "machines/tool_table.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "machines/loader.hpp"

namespace ncsim::machines {
namespace {

struct Read {
  ToolTable table;
  core::DiagnosticList diagnostics;
};

Read read(std::string text) {
  Read r;
  r.table = read_tool_list(core::SourceFile("tools.lis", std::move(text)), r.diagnostics);
  return r;
}

TEST_CASE("the tool list gives radius and length in mm from 0.1 um (P-TOOL-00003/00004)") {
  const Read r = read(
      "# tool 1: 3 mm cutter\n"
      "wz[1].gueltig 1\n"
      "wz[1].radius 30000   # 3 mm\n"
      "wz[1].laenge 600000\n"
      "wz[2].gueltig 1\n"
      "wz[2].radius -5000\n"
      "wz[3].radius 1000\n"
      "wz[3].mass_einheit 1\n");
  CHECK(r.diagnostics.items().empty());
  REQUIRE(r.table.find(1) != nullptr);
  CHECK(r.table.find(1)->radius == doctest::Approx(3.0));
  CHECK(r.table.find(1)->length == doctest::Approx(60.0));
  CHECK(r.table.find(1)->valid);
  CHECK(r.table.find(2)->radius == doctest::Approx(-0.5));
  // P-TOOL-00008 = 1: 0.0001 inch; validity defaults to 0 (P-TOOL-00005)
  CHECK(r.table.find(3)->radius == doctest::Approx(2.54));
  CHECK_FALSE(r.table.find(3)->valid);
  CHECK(r.table.find(4) == nullptr);
  CHECK(r.table.find(0) == nullptr);
}

TEST_CASE("bad tool list lines give one positioned error each [NC3030..NC3033, NC3001]") {
  const Read r = read(
      "wz[1].durchmesser 5\n"    // 1: unknown key
      "wz[1].radius 2.5\n"       // 2: not an integer
      "wz[1].gueltig 2\n"        // 3: out of range
      "wz[256].radius 10\n"      // 4: tool number out of range
      "wz[0].radius 10\n"        // 5: tool number out of range
      "wz[4].radius 10\n"        // 6: fine
      "wz[4].radius 20\n"        // 7: twice
      "wz[5].radius 1 junk\n");  // 8: syntax
  const auto& items = r.diagnostics.items();
  std::string all;
  for (const auto& d : items)
    all += core::format(d) + "\n";
  INFO(all);
  REQUIRE(items.size() == 7);
  CHECK(items[0].id == "NC3001");  // syntax errors come first (parse_list)
  CHECK(items[0].loc.line == 8);
  CHECK(items[1].id == "NC3030");
  CHECK(items[1].loc == core::SourceLoc{1, 1});
  CHECK(items[2].id == "NC3031");
  CHECK(items[2].loc == core::SourceLoc{2, 14});
  CHECK(items[2].message.find("wz[1].radius (P-TOOL-00004)") != std::string::npos);
  CHECK(items[3].id == "NC3031");
  CHECK(items[4].id == "NC3032");
  CHECK(items[4].loc.line == 4);
  CHECK(items[5].id == "NC3032");
  CHECK(items[6].id == "NC3033");
  CHECK(items[6].loc.line == 7);
  REQUIRE(r.table.find(4) != nullptr);
  CHECK(r.table.find(4)->radius == doctest::Approx(0.001));
}

TEST_CASE("machine.lis names the tool list with a 'tools' line; a missing file is NC3010") {
  const char* root = std::getenv("NCSIM_SOURCE_DIR");
  REQUIRE(root != nullptr);
  const auto dir = std::filesystem::temp_directory_path() / "ncsim_tool_table_test";
  std::filesystem::remove_all(dir);
  std::filesystem::copy(std::filesystem::path(root) / "machines" / "portal_3x", dir);
  {
    std::ofstream index(dir / "machine.lis", std::ios::app);
    index << "tools tools.lis\n";
  }
  LoadResult missing = load_machine(dir);
  REQUIRE_FALSE(missing.diagnostics.items().empty());
  CHECK(missing.diagnostics.items()[0].id == "NC3010");
  {
    std::ofstream tools(dir / "tools.lis");
    tools << "wz[1].gueltig 1\nwz[1].radius 15000\n";
  }
  LoadResult ok = load_machine(dir);
  REQUIRE(ok.machine.has_value());
  REQUIRE(ok.machine->tools.find(1) != nullptr);
  CHECK(ok.machine->tools.find(1)->radius == doctest::Approx(1.5));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ncsim::machines
