#include <doctest/doctest.h>

#include <string>

#include "scenario/loader.hpp"

namespace ncsim::scenario {
namespace {

LoadResult wired(std::string text) {
  const core::SourceFile file("c.toml", std::move(text));
  Context c;
  c.conveyor_wired = true;
  return parse_scenario(file, c);
}

// The first error's id and line ("" when none).
std::string first(const LoadResult& r) {
  for (const core::Diagnostic& d : r.diagnostics.items()) {
    if (d.severity == core::Severity::error)
      return d.id + "@" + std::to_string(d.loc.line) + " " + d.message;
  }
  return "";
}

// Every message of r, one per line.
std::string all(const LoadResult& r) {
  std::string out;
  for (const core::Diagnostic& d : r.diagnostics.items())
    out += d.id + " " + d.message + "\n";
  return out;
}

}  // namespace

TEST_CASE("[conveyor] spindle mode with a sensor and workpieces by travel and by time") {
  const LoadResult r = wired(R"([conveyor]
mode = "spindle"
dead_time = 0.002
noise = { sigma = 0.01, seed = 42 }
sensor = { kind = "camera", position = -100, queue = 4 }
[[conveyor.workpiece]]
travel = 150
length = 80
ve = { part = 2 }
[[conveyor.workpiece]]
at = 3.5
)");
  REQUIRE(r.scenario);
  const Conveyor& c = *r.scenario->conveyor;
  CHECK(c.mode == ConveyorMode::spindle);
  CHECK(c.noise->seed == 42u);
  CHECK(c.sensor.kind == SensorKind::camera);
  CHECK(*c.sensor.position == -100.0);
  CHECK(c.sensor.queue == 4u);
  REQUIRE(c.workpieces.size() == 2);
  CHECK(*c.workpieces[0].travel == 150.0);
  CHECK(c.workpieces[0].ve[0].name == "PART");
  CHECK(*c.workpieces[1].t == 3.5);
  CHECK(c.workpieces[1].length == 100.0);  // the default
}

TEST_CASE("[conveyor] errors name file, line and key: NC7014..NC7018") {
  CHECK(first(wired("[conveyor]\nmode = \"belt\"\n")).rfind("NC7014@2", 0) == 0);
  CHECK(first(wired("[conveyor]\nvelocity = 3\n")).rfind("NC7015@1", 0) == 0);  // no mode
  CHECK(first(wired("[conveyor]\nmode = \"spindle\"\nvelocity = 3\n")).rfind("NC7015@3", 0) == 0);
  CHECK(first(wired("[conveyor]\nmode = \"encoder\"\nprofile = [{at = 2, velocity = 0, ramp = "
                    "1},\n {at = 2.5, velocity = 100}]\n"))
            .rfind("NC7016@4", 0) == 0);  // starts before the previous ramp ends
  CHECK(first(wired("[conveyor]\nmode = \"encoder\"\n[[conveyor.workpiece]]\nlength = 5\n"))
            .rfind("NC7017@3", 0) == 0);
  CHECK(first(wired("[conveyor]\nmode = \"encoder\"\n[[conveyor.workpiece]]\ntravel = 100\n"
                    "[[conveyor.workpiece]]\ntravel = 150\n"))
            .rfind("NC7018@6", 0) == 0);  // 150 < 100 + 100 (default length)
  CHECK(first(wired("[conveyor]\nmode = \"encoder\"\n[conveyor.workpieces]\nfirst = 10\npitch "
                    "= 50\ncount = 3\nlength = 60\n"))
            .rfind("NC7018@5", 0) == 0);
  CHECK(first(wired("[conveyor]\nmode = \"encoder\"\n[conveyor.workpieces]\nfirst = 10\nperiod "
                    "= 2\ncount = 3\n"))
            .rfind("NC7017@3", 0) == 0);
  CHECK(first(wired("[conveyor]\nmode = \"encoder\"\n[[conveyor.workpiece]]\ntravel = 0\n"))
            .rfind("NC7004@4", 0) == 0);
  CHECK(first(wired("[conveyor]\nmode = \"encoder\"\ndead_time = -1\n")).rfind("NC7004@3", 0) == 0);
  CHECK(all(wired("[conveyor]\nmode = \"encoder\"\nnoise = { sgima = 1 }\n"))
            .find("did you mean `sigma`") != std::string::npos);
  CHECK(first(wired("[conveyor]\nmode = \"encoder\"\nsensor = { kind = \"camera\", front_edge "
                    "= \"rising\" }\n"))
            .rfind("NC7014@3", 0) == 0);
}

TEST_CASE("[conveyor] for a machine without a conveyor axis is warning NC7019 at its header") {
  const core::SourceFile file("c.toml", "description = \"x\"\n[conveyor]\nmode = \"spindle\"\n");
  Context c;
  c.conveyor_wired = true;
  c.conveyor_axis = false;
  const LoadResult r = parse_scenario(file, c);
  REQUIRE(r.scenario);  // a warning: the scenario still loads
  REQUIRE(r.diagnostics.items().size() == 1);
  const core::Diagnostic& d = r.diagnostics.items().front();
  CHECK(d.severity == core::Severity::warning);
  CHECK(d.id == "NC7019");
  CHECK(d.loc.line == 2);
  CHECK(d.loc.column == 2);
  CHECK(d.message.find("has no conveyor axis") != std::string::npos);
  CHECK_FALSE(r.scenario->conveyor);  // not played
  c.conveyor_axis = true;
  CHECK(parse_scenario(file, c).diagnostics.items().empty());
}

TEST_CASE("conveyor.noise.seed takes its documented maximum 2^63-1") {
  const LoadResult r = wired(
      "[conveyor]\nmode = \"spindle\"\nnoise = { sigma = 0.01, seed = 9223372036854775807 }\n");
  REQUIRE(r.scenario);
  CHECK(r.scenario->conveyor->noise->seed == 9223372036854775807u);
  CHECK(first(wired("[conveyor]\nmode = \"spindle\"\nnoise = { sigma = 0.01, seed = -1 }\n"))
            .find("conveyor.noise.seed = -1 is out of range 0 .. 9223372036854775807") !=
        std::string::npos);
}

}  // namespace ncsim::scenario

namespace ncsim::scenario {

TEST_CASE("[conveyor.workpieces] a seeded random stream: scatter and seed") {
  const LoadResult r = wired(R"([conveyor]
mode = "spindle"
[conveyor.workpieces]
first = 100
pitch = 150
scatter = 60
seed = 37
count = 5
)");
  REQUIRE(r.scenario);
  const WorkpieceSeries& s = *r.scenario->conveyor->series;
  CHECK(s.scatter == 60.0);
  CHECK(s.seed == 37u);
  CHECK(first(wired("[conveyor]\nmode = \"spindle\"\n[conveyor.workpieces]\nfirst = 100\n"
                    "pitch = 150\ncount = 5\nscatter = -1\n"))
            .rfind("NC7004@7", 0) == 0);
  CHECK(all(wired("[conveyor]\nmode = \"spindle\"\n[conveyor.workpieces]\nfirst = 100\n"
                  "pitch = 150\ncount = 5\nscater = 1\n"))
            .find("did you mean `scatter`") != std::string::npos);
}

}  // namespace ncsim::scenario
