// scenario/line_file: the line file validated like a scenario (docs/lines.md "The line file"):
// every error at file:line:col with its key, all of them in one pass.
#include "scenario/line_file.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace {

using namespace ncsim;

// "line:col id" of every diagnostic.
std::vector<std::string> diagnostics(const std::string& text) {
  const scenario::LineLoad r = scenario::parse_line(core::SourceFile("l.toml", text));
  std::vector<std::string> out;
  for (const core::Diagnostic& d : r.diagnostics.items())
    out.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " + d.id);
  return out;
}

const char* kChannel = "[[channel]]\nnumber = 1\nprogram = \"a.nc\"\nmachine = \"portal_3x\"\n";

}  // namespace

TEST_CASE("a line file gives its channels in file order, names defaulted, and the conveyor") {
  const std::string text = std::string("description = \"two\"\ncycle_us = 500\n") + kChannel +
                           "[[channel]]\nnumber = 3\nname = \"sorter\"\nprogram = \"b.nc\"\n"
                           "machine = \"m\"\nscenario = \"s.toml\"\n"
                           "[conveyor]\nmode = \"encoder\"\nvelocity = 100\n";
  const scenario::LineLoad r = scenario::parse_line(core::SourceFile("dir/l.toml", text));
  REQUIRE(r.line);
  const scenario::LineFile& l = *r.line;
  CHECK(l.description == "two");
  CHECK(l.cycle_us == 500u);
  REQUIRE(l.channels.size() == 2);
  CHECK(l.channels[0].name == "channel 1");
  CHECK(l.channels[1].number == 3);
  CHECK(l.channels[1].name == "sorter");
  CHECK(l.channels[1].scenario->text == "s.toml");
  CHECK(l.channels[1].program.loc.line == 10);
  CHECK(l.resolved(l.channels[1].program) == "dir/b.nc");
  REQUIRE(l.conveyor);
  CHECK(l.conveyor->velocity == 100.0);
}

TEST_CASE("every error of a line file is positioned, all in one pass") {
  CHECK(diagnostics("[[channel]]\nnumbr = 1\nprogram = \"a.nc\"\n") ==
        std::vector<std::string>{"1:1 NC7102", "1:1 NC7102", "2:1 NC7101"});
  CHECK(diagnostics(std::string(kChannel) + kChannel) == std::vector<std::string>{"6:10 NC7103"});
  CHECK(diagnostics("cycle_us = 0\n") == std::vector<std::string>{"1:1 NC7104", "1:12 NC7004"});
  CHECK(diagnostics(std::string(kChannel) + "belt = 3\n") ==
        std::vector<std::string>{"5:1 NC7101"});
  CHECK(diagnostics("[[channel]]\nnumber = 13\nprogram = 4\nmachine = \"\"\n") ==
        std::vector<std::string>{"2:10 NC7004", "3:11 NC7003", "4:11 NC7004"});
  CHECK_FALSE(diagnostics(std::string(kChannel) + "[conveyor]\nmode = \"belt\"\n").empty());
  const std::vector<std::string> syntax = diagnostics("[[channel]\n");
  REQUIRE(syntax.size() == 1);
  CHECK(syntax[0].rfind("1:", 0) == 0);
  CHECK(syntax[0].find("NC7001") != std::string::npos);
}

TEST_CASE("an unknown key suggests the one meant") {
  const scenario::LineLoad r =
      scenario::parse_line(core::SourceFile("l.toml", std::string(kChannel) + "machne = 1\n"));
  REQUIRE(r.diagnostics.items().size() == 1);
  CHECK(r.diagnostics.items()[0].message.find("did you mean `machine`?") != std::string::npos);
}

TEST_CASE("a channel's sensor along the belt and the belt's end (docs/lines.md)") {
  const std::string text = std::string("belt_end = 1500\n") + kChannel + "sensor_at = 700\n";
  const scenario::LineLoad r = scenario::parse_line(core::SourceFile("l.toml", text));
  REQUIRE(r.line);
  CHECK(r.line->channels[0].sensor_at == 700.0);
  CHECK(r.line->belt_end == 1500.0);
  // The belt ends after the last sensor; both within 0 .. 1e6 mm.
  CHECK(diagnostics(std::string("belt_end = 500\n") + kChannel + "sensor_at = 700\n") ==
        std::vector<std::string>{"1:12 NC7004"});
  CHECK(diagnostics(std::string(kChannel) + "sensor_at = -1\n") ==
        std::vector<std::string>{"5:13 NC7004"});
  CHECK(diagnostics(std::string(kChannel) + "sensor_at = \"near\"\n") ==
        std::vector<std::string>{"5:13 NC7003"});
  // The line's sensor is where the stream arrives; each channel's own is at its T0.
  CHECK(diagnostics(std::string(kChannel) +
                    "[conveyor]\nmode = \"spindle\"\n[conveyor.sensor]\nposition = 5\n") ==
        std::vector<std::string>{"5:1 NC7110"});
}
