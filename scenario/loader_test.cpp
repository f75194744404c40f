#include "scenario/loader.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

namespace ncsim::scenario {
namespace {

LoadResult parse(std::string text, const Context& context = {}) {
  const core::SourceFile file("s.toml", std::move(text));
  return parse_scenario(file, context);
}

// The one error of `r`; fails the test when there is not exactly one.
core::Diagnostic only_error(const LoadResult& r) {
  REQUIRE(r.diagnostics.error_count() == 1);
  REQUIRE(r.diagnostics.items().size() == 1);
  return r.diagnostics.items().front();
}

bool has(const core::Diagnostic& d, std::string_view id, std::uint32_t line,
         std::string_view text) {
  return d.id == id && d.loc.line == line && d.file == "s.toml" &&
         d.message.find(text) != std::string::npos;
}

TEST_CASE("a complete scenario loads with its values converted to internal units") {
  const LoadResult r = parse(R"(description = "demo"
[ve]
part = 2
Ready = 1.5

[[event]]
at = 2.5
override = 60

[[event]]
line = 12
pass = 3
feed_hold = true
duration = 3

[[event]]
at = 4
axis_override = { c = 50 }
ve = { PART = 3 }

[stop]
time = 30
cycles = 100000
line = 12
passes = 50
)");
  REQUIRE_FALSE(r.diagnostics.has_errors());
  REQUIRE(r.scenario);
  const Scenario& s = *r.scenario;
  CHECK(s.description == "demo");
  REQUIRE(s.ve.size() == 2);
  CHECK(s.ve_initial("PART") == 2.0);
  CHECK(s.ve_initial("READY") == 1.5);
  REQUIRE(s.events.size() == 3);
  CHECK(std::get<AtTime>(s.events[0].trigger).t == 2.5);
  CHECK(std::get<PathOverride>(s.events[0].actions.at(0)).fraction == doctest::Approx(0.6));
  CHECK(std::get<AtLine>(s.events[1].trigger).line == 12);
  CHECK(std::get<AtLine>(s.events[1].trigger).pass == 3);
  CHECK(std::get<FeedHold>(s.events[1].actions.at(0)).on);
  CHECK(s.events[1].hold_release == 3.0);
  CHECK(s.events[1].loc.line == 10);  // its [[event]] header
  REQUIRE(s.events[2].actions.size() == 2);
  CHECK(std::get<AxisOverride>(s.events[2].actions[0]).axis == "C");
  CHECK(std::get<AxisOverride>(s.events[2].actions[0]).fraction == doctest::Approx(0.5));
  CHECK(std::get<VeWrite>(s.events[2].actions[1]).name == "PART");
  CHECK(s.stop.time == 30.0);
  CHECK(s.stop.cycles == 100000u);
  CHECK(s.stop.line == 12u);
  CHECK(s.stop.passes == 50u);
  CHECK(s.needs_channel());
}

TEST_CASE("an empty file is a scenario without events") {
  const LoadResult r = parse("");
  REQUIRE(r.scenario);
  CHECK_FALSE(r.scenario->needs_channel());
}

TEST_CASE("V.E. values alone need no channel loop") {
  const LoadResult r = parse("[ve]\nA = 1\n");
  REQUIRE(r.scenario);
  CHECK_FALSE(r.scenario->needs_channel());
}

TEST_CASE("[tech] gives technology functions' execution times in seconds; bad names and values") {
  const LoadResult r = parse("[tech]\nM6 = 4.5\nh12 = 0.25\nS = 1\nT = 0\n");
  REQUIRE(r.scenario);
  CHECK_FALSE(r.scenario->needs_channel());
  const auto& t = r.scenario->tech;
  REQUIRE(t.size() == 4);
  const auto seconds = [&](char kind, std::uint32_t number) {
    for (const TechDuration& d : t)
      if (d.kind == kind && d.number == number) return d.seconds;
    return -1.0;
  };
  CHECK(seconds('M', 6) == 4.5);
  CHECK(seconds('H', 12) == 0.25);
  CHECK(seconds('S', 0) == 1.0);
  CHECK(seconds('T', 0) == 0.0);
  CHECK(has(only_error(parse("[tech]\nM1000 = 1\n")), "NC7008", 2, "M<n> or H<n>"));
  CHECK(has(only_error(parse("[tech]\nQ = 1\n")), "NC7008", 2, "S or T"));
  CHECK(has(only_error(parse("[tech]\nM = 1\n")), "NC7008", 2, "M<n>"));
  CHECK(has(only_error(parse("[tech]\nM3 = -1\n")), "NC7004", 2, "outside 0 .. 86400 s"));
  CHECK(has(only_error(parse("[tech]\nM3 = 90000\n")), "NC7004", 2, "outside"));
  CHECK(has(only_error(parse("[tech]\nM3 = 'x'\n")), "NC7003", 2, "tech.M3"));
}

TEST_CASE("a TOML syntax error is NC7001 at its line and column") {
  const LoadResult r = parse("[ve]\nA = \n");
  const core::Diagnostic& d = only_error(r);
  CHECK(has(d, "NC7001", 2, "TOML syntax"));
  CHECK(d.loc.column > 0);
  CHECK_FALSE(r.scenario);
}

TEST_CASE("an unknown key is NC7002 with a suggestion") {
  SUBCASE("top level") {
    const core::Diagnostic& d = only_error(parse("\n[[events]]\nat = 1\n"));
    CHECK(has(d, "NC7002", 2, "unknown key `events`; did you mean `event`?"));
  }
  SUBCASE("in an event") {
    const core::Diagnostic& d = only_error(parse("[[event]]\nat = 1\noveride = 50\n"));
    CHECK(has(d, "NC7002", 3, "unknown key `event[1].overide`; did you mean `override`?"));
    CHECK(d.loc.column == 1);
  }
  SUBCASE("in stop, nothing close") {
    const core::Diagnostic& d = only_error(parse("[stop]\nwhenever = 3\n"));
    CHECK(has(d, "NC7002", 2, "unknown key `stop.whenever`"));
    CHECK(d.message.find("did you mean") == std::string::npos);
  }
}

TEST_CASE("a misspelt trigger or action is one error, not also a missing one") {
  CHECK(has(only_error(parse("[[event]]\natt = 1\noverride = 5\n")), "NC7002", 2,
            "did you mean `at`?"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\nfeedhold = true\n")), "NC7002", 3,
            "did you mean `feed_hold`?"));
}

TEST_CASE("a wrong type is NC7003 naming the key and both types") {
  CHECK(has(only_error(parse("[[event]]\nat = \"soon\"\noverride = 5\n")), "NC7003", 2,
            "event[1].at must be a number, not a string"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\nfeed_hold = 1\n")), "NC7003", 3,
            "event[1].feed_hold must be a boolean"));
  CHECK(has(only_error(parse("[stop]\ncycles = 1.5\n")), "NC7003", 2,
            "stop.cycles must be an integer, not a floating-point number"));
  CHECK(has(only_error(parse("event = 3\n")), "NC7003", 1, "event must be an array of tables"));
  CHECK(has(only_error(parse("ve = 3\n")), "NC7003", 1, "ve must be a table"));
  CHECK(has(only_error(parse("[ve]\nA = true\n")), "NC7003", 2, "ve.A must be a number"));
}

TEST_CASE("an out-of-range value is NC7004 with value, range and unit") {
  CHECK(has(only_error(parse("[[event]]\nat = 1\noverride = 1200\n")), "NC7004", 3,
            "event[1].override = 1200 % is out of range 0 .. 1000 %"));
  CHECK(has(only_error(parse("[[event]]\nat = -1\noverride = 10\n")), "NC7004", 2,
            "event[1].at = -1 s is out of range"));
  CHECK(has(only_error(parse("[[event]]\nline = 0\noverride = 10\n")), "NC7004", 2,
            "event[1].line = 0 is out of range 1 .."));
  CHECK(has(only_error(parse("[[event]]\nat = nan\noverride = 10\n")), "NC7004", 2,
            "event[1].at = nan s is not a finite number"));
  CHECK(has(only_error(parse("[ve]\nA = -inf\n")), "NC7004", 2, "ve.A = -inf is not a finite"));
  CHECK(has(only_error(parse("[stop]\ntime = 0\n")), "NC7004", 2, "stop.time = 0 s"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\naxis_override = { C = -5 }\n")), "NC7004", 3,
            "event[1].axis_override.C = -5 %"));
}

TEST_CASE("an override between 0 and 0.1 % or a time beyond one day is NC7004 at its key") {
  // issue 34 items 7, 19: 1e-300 % and a feed hold of 1e9 s were accepted and ran for ages
  CHECK(has(only_error(parse("[[event]]\nat = 1\noverride = 1e-300\n")), "NC7004", 3,
            "event[1].override = 1e-300 % is out of range: 0 (a stop) or 0.1 .. 1000 %"));
  CHECK(
      has(only_error(parse("[[event]]\nat = 1\noverride = 0.09\n")), "NC7004", 3, "0.1 .. 1000 %"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\naxis_override = { C = 1e-9 }\n")), "NC7004", 3,
            "event[1].axis_override.C = 1e-09 % is out of range"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\nfeed_hold = true\nduration = 1e9\n")), "NC7004", 4,
            "event[1].duration = 1000000000 s is out of range 0 .. 86400 s"));
  CHECK(has(only_error(parse("[[event]]\nat = 86401\noverride = 10\n")), "NC7004", 2,
            "out of range 0 .. 86400 s"));
  CHECK(has(only_error(parse("[stop]\ntime = 1e6\n")), "NC7004", 2, "stop.time"));
  // the limits themselves load
  for (const char* ok : {"[[event]]\nat = 1\noverride = 0\n", "[[event]]\nat = 1\noverride = 0.1\n",
                         "[[event]]\nat = 86400\nfeed_hold = true\nduration = 86400\n"}) {
    CAPTURE(ok);
    CHECK(parse(ok).diagnostics.error_count() == 0);
  }
}

TEST_CASE("time events out of order are NC7005 naming both") {
  const core::Diagnostic& d =
      only_error(parse("[[event]]\nat = 2.5\noverride = 50\n[[event]]\nline = 7\noverride = 10\n"
                       "[[event]]\nat = 1.5\noverride = 60\n"));
  CHECK(has(d, "NC7005", 8,
            "event[3].at = 1.5 s comes before event[1].at = 2.5 s (line 2): events with `at` "
            "must be in time order"));
}

TEST_CASE("equal times keep file order and are no error") {
  const LoadResult r =
      parse("[[event]]\nat = 1\noverride = 50\n[[event]]\nat = 1\noverride = 60\n");
  REQUIRE(r.scenario);
  CHECK(r.scenario->events.size() == 2);
}

TEST_CASE("bad combinations are NC7006") {
  CHECK(has(only_error(parse("[[event]]\noverride = 50\n")), "NC7006", 1, "has no trigger"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\nline = 3\noverride = 50\n")), "NC7006", 1,
            "has both `at` and `line`"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\n")), "NC7006", 1, "does nothing"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\npass = 2\noverride = 5\n")), "NC7006", 3,
            "counts passes of a `line`"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\nfeed_hold = false\nduration = 2\n")), "NC7006", 4,
            "needs feed_hold = true"));
  CHECK(has(only_error(parse("[stop]\nline = 4\n")), "NC7006", 1, "go together"));
}

TEST_CASE("the old reserved conveyor tables are unknown keys that point to [conveyor]") {
  CHECK(has(only_error(parse("[belt]\nvelocity = 300\n")), "NC7002", 1, "[conveyor] table"));
  CHECK(has(only_error(parse("[[workpiece]]\nat = 1\n")), "NC7002", 1, "[conveyor] table"));
}

TEST_CASE("reduced_filter events are refused until the channel plays the conveyor (NC7007)") {
  CHECK(has(only_error(parse("[[event]]\nat = 1\nreduced_filter = true\n")), "NC7007", 3,
            "not supported: event[1].reduced_filter"));
  Context wired;
  wired.conveyor_wired = true;
  const LoadResult r = parse("[[event]]\nat = 1\nreduced_filter = true\n", wired);
  REQUIRE(r.scenario);
  REQUIRE(r.scenario->events[0].actions.size() == 1);
  CHECK(std::get<ReducedFilter>(r.scenario->events[0].actions[0]).on);
}

TEST_CASE("bad and duplicate names are NC7008") {
  CHECK(has(only_error(parse("[ve]\nPART = 1\npart = 2\n")), "NC7008", 3, "PART is given twice"));
  CHECK(has(only_error(parse("[ve]\n\"1X\" = 1\n")), "NC7008", 2, "is not a name"));
  CHECK(has(only_error(parse("[ve]\nV.E.PART = 1\n")), "NC7008", 2, "without the `V.E.` prefix"));
}

TEST_CASE("every error of the file is reported, in line order") {
  const LoadResult r = parse(R"([stop]
tyme = 3
[[event]]
at = 1
override = 2000
[[event]]
at = 0.5
feed_hold = "yes"
[ve]
A = "x"
)");
  REQUIRE(r.diagnostics.error_count() == 4);
  const auto& d = r.diagnostics.items();
  CHECK(has(d[0], "NC7002", 2, "stop.tyme"));
  CHECK(has(d[1], "NC7004", 5, "override = 2000"));
  CHECK(has(d[2], "NC7003", 8, "feed_hold"));
  CHECK(has(d[3], "NC7003", 10, "ve.A"));
  CHECK_FALSE(r.scenario);
}

TEST_CASE("the context checks lines against the program and axes against the machine") {
  std::string program;
  for (int i = 0; i < 20; ++i)
    program += "G01 X1 F100\n";
  const core::SourceFile prog("p.nc", program);
  Context c;
  c.program = &prog;
  c.axes = std::vector<std::string>{"X", "Y", "Z", "C"};
  CHECK(has(only_error(parse("[[event]]\nline = 21\noverride = 5\n", c)), "NC7012", 2,
            "event[1].line = 21 is beyond the last line (20) of p.nc"));
  CHECK(
      has(only_error(parse("[stop]\nline = 40\npasses = 2\n", c)), "NC7012", 2, "stop.line = 40"));
  CHECK(has(only_error(parse("[[event]]\nat = 1\naxis_override = { B = 50 }\n", c)), "NC7011", 3,
            "the machine has no axis B (axes: X, Y, Z, C)"));
  CHECK(parse("[[event]]\nline = 20\naxis_override = { c = 50 }\n", c).scenario);
}

TEST_CASE("a line that holds no block is warning NC7013; the scenario still loads") {
  const core::SourceFile prog("p.nc", "%p\n; a comment\n\n(- a comment -)\nG01 X1 F100\nM30\n");
  Context c;
  c.program = &prog;
  for (const char* line : {"2", "3", "4"}) {
    CAPTURE(line);
    const LoadResult r = parse(std::string("[[event]]\nline = ") + line + "\noverride = 5\n", c);
    REQUIRE(r.scenario);
    REQUIRE(r.diagnostics.items().size() == 1);
    const core::Diagnostic& d = r.diagnostics.items()[0];
    CHECK(d.severity == core::Severity::warning);
    CHECK(has(d, "NC7013", 2, "holds no block"));
  }
  CHECK(parse("[[event]]\nline = 5\noverride = 5\n", c).diagnostics.items().empty());
  CHECK(parse("[stop]\nline = 6\npasses = 1\n", c).diagnostics.items().empty());
}

TEST_CASE("a file larger than kMaxScenarioBytes is NC7010, not parsed") {
  const LoadResult r = parse(std::string(kMaxScenarioBytes + 1, '#'));
  CHECK(has(only_error(r), "NC7010", 0, "at most 16777216"));
}

TEST_CASE("a dotted key's implicit table is located at its key") {
  CHECK(has(only_error(parse("\nstop.line = 3\n")), "NC7006", 2, "go together"));
  CHECK(has(only_error(parse("\n\nevent.at = 3\n")), "NC7003", 3, "event must be an array"));
}

TEST_CASE("seeded random corruptions never crash; every error has a position") {
  const std::string valid = R"(description = "demo"
[ve]
PART = 2
[[event]]
at = 2.5
override = 60
[[event]]
line = 12
pass = 3
feed_hold = true
duration = 3
[[event]]
at = 4
axis_override = { C = 50 }
ve = { PART = 3 }
[stop]
time = 30
line = 12
passes = 5
)";
  const std::string alphabet = "[]{}=.,\"#\n 0123456789-+eE_atlinepsovrdfhuxyzVEC";
  std::mt19937 rng(20261123);
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  int loaded = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string text = valid;
    std::uniform_int_distribution<std::size_t> where(0, text.size() - 1);
    for (int edits = 1 + trial % 4; edits > 0; --edits)
      text[where(rng)] = alphabet[pick(rng)];
    CAPTURE(text);
    const LoadResult r = parse(text);
    CHECK(r.scenario.has_value() == !r.diagnostics.has_errors());
    for (const core::Diagnostic& d : r.diagnostics.items()) {
      CHECK(d.loc.line >= 1);
      CHECK(d.id.rfind("NC70", 0) == 0);
    }
    loaded += r.scenario ? 1 : 0;
  }
  CHECK(loaded > 0);  // some corruptions stay valid (a digit for a digit)
}

// The n-th ```toml block of docs/scenario.md.
std::string doc_block(int n) {
  const char* dir = std::getenv("NCSIM_SOURCE_DIR");
  const std::string root = dir != nullptr ? dir : NCSIM_SOURCE_ROOT;
  std::ifstream in(root + "/docs/scenario.md");
  REQUIRE(in.good());
  const std::string doc((std::istreambuf_iterator<char>(in)), {});
  std::size_t at = 0;
  for (int i = 0; i <= n; ++i) {
    at = doc.find("```toml\n", at);
    REQUIRE(at != std::string::npos);
    at += 8;
  }
  return doc.substr(at, doc.find("```", at) - at);
}

TEST_CASE("the complete example of docs/scenario.md loads") {
  const LoadResult r = parse(doc_block(0));
  CHECK(r.diagnostics.items().empty());
  REQUIRE(r.scenario);
  CHECK(r.scenario->events.size() == 4);
  CHECK(r.scenario->stop.passes == 50u);
}

TEST_CASE("the [conveyor] example of docs/scenario.md loads; unwired it is NC7007 once") {
  const LoadResult unwired = parse(doc_block(1));
  CHECK(has(only_error(unwired), "NC7007", only_error(unwired).loc.line, "not supported"));
  Context wired;
  wired.conveyor_wired = true;
  const LoadResult r = parse(doc_block(1), wired);
  CHECK(r.diagnostics.items().empty());
  REQUIRE(r.scenario);
  REQUIRE(r.scenario->conveyor);
  const Conveyor& c = *r.scenario->conveyor;
  CHECK(c.mode == ConveyorMode::encoder);
  CHECK(c.velocity == 300.0);
  CHECK(c.profile.size() == 2);
  CHECK(c.dead_time == doctest::Approx(0.017455));
  REQUIRE(c.fluctuation);
  CHECK(c.fluctuation->amplitude == doctest::Approx(0.05));  // 5 %
  REQUIRE(c.series);
  CHECK(c.series->count == 20u);
}

TEST_CASE("a file that cannot be read is NC7010") {
  const LoadResult r = load_scenario("/nonexistent/scenario.toml");
  REQUIRE(r.diagnostics.error_count() == 1);
  CHECK(r.diagnostics.items()[0].id == "NC7010");
  CHECK(r.diagnostics.items()[0].file == "/nonexistent/scenario.toml");
}

TEST_CASE("overrides beyond the machine's are NC6102 / NC6105 at their values, given the limits") {
  Context limits;
  limits.path_override_max = 1.0;
  limits.axis_override_max = 1.0;
  const LoadResult path = parse("[[event]]\nat = 0.1\noverride = 150\n", limits);
  CHECK(has(only_error(path), "NC6102", 3, "event[1].override = 150 % is above 100 %"));
  CHECK(only_error(path).loc.column == 12);
  const LoadResult axis = parse("[[event]]\nat = 0.1\naxis_override = { C = 120 }\n", limits);
  CHECK(has(only_error(axis), "NC6105", 3, "event[1].axis_override.C = 120 % is above 100 %"));
  CHECK(only_error(axis).loc.column == 19);
  CHECK(parse("[[event]]\nat = 0.1\noverride = 150\n").scenario);  // no limits given
}

TEST_CASE("stop.cycles takes its documented maximum 2^63-1; a range error prints integers") {
  const LoadResult r = parse("[stop]\ncycles = 9223372036854775807\n");
  REQUIRE(r.scenario);
  CHECK(*r.scenario->stop.cycles == 9223372036854775807u);
  const LoadResult zero = parse("[stop]\ncycles = 0\n");
  CHECK(has(only_error(zero), "NC7004", 2,
            "stop.cycles = 0 is out of range 1 .. 9223372036854775807"));
}

TEST_CASE("an axis_override of a path axis is warning NC7020 at its key; an INDP axis's is not") {
  Context c;
  c.axes = std::vector<std::string>{"X", "Y", "C"};
  c.path_axes = std::vector<std::string>{"X", "Y"};
  const LoadResult r = parse("[[event]]\nat = 0.1\naxis_override = { X = 50, C = 50 }\n", c);
  REQUIRE(r.scenario);
  REQUIRE(r.diagnostics.items().size() == 1);
  const core::Diagnostic& d = r.diagnostics.items().front();
  CHECK(d.severity == core::Severity::warning);
  CHECK(has(d, "NC7020", 3, "event[1].axis_override.X: X is a path axis"));
  CHECK(d.loc.column == 19);
}

}  // namespace
}  // namespace ncsim::scenario
