#include "scenario/player.hpp"

#include <doctest/doctest.h>

#include <random>
#include <string>

#include "scenario/loader.hpp"

namespace ncsim::scenario {
namespace {

Scenario load(std::string text) {
  const core::SourceFile file("s.toml", std::move(text));
  LoadResult r = parse_scenario(file);
  REQUIRE_MESSAGE(r.scenario, (r.diagnostics.items().empty() ? std::string()
                                                             : r.diagnostics.items()[0].message));
  return std::move(*r.scenario);
}

// One line of text per action, for comparing sequences.
std::string text(const Action& a) {
  if (const auto* p = std::get_if<PathOverride>(&a)) return "ovr " + std::to_string(p->fraction);
  if (const auto* x = std::get_if<AxisOverride>(&a)) {
    return "axis " + x->axis + " " + std::to_string(x->fraction);
  }
  if (const auto* h = std::get_if<FeedHold>(&a)) return h->on ? "hold" : "release";
  const auto& v = std::get<VeWrite>(a);
  return "ve " + v.name + "=" + std::to_string(v.value);
}

std::string texts(const std::vector<Action>& actions) {
  std::string out;
  for (const Action& a : actions)
    out += (out.empty() ? "" : "; ") + text(a);
  return out;
}

constexpr double kCycle = 0.001;  // [s]

TEST_CASE("a time event is due at the first cycle at or after its time") {
  const Scenario s = load("[[event]]\nat = 0.0025\noverride = 50\n");
  Player p(s);
  CHECK(p.step(0, 0.0).empty());
  CHECK(p.step(1, kCycle).empty());
  CHECK(p.step(2, 2 * kCycle).empty());
  CHECK(texts(p.step(3, 3 * kCycle)) == "ovr 0.500000");
  CHECK(p.path_override() == doctest::Approx(0.5));
  CHECK(p.step(4, 4 * kCycle).empty());
}

TEST_CASE("a time that is a sum of cycles is due in its own cycle (no rounding miss)") {
  const Scenario s = load("[[event]]\nat = 2.5\nfeed_hold = true\n");
  Player p(s);
  double t = 0.0;
  std::uint64_t fired_at = 0;
  for (std::uint64_t k = 0; k < 3000; ++k, t += kCycle) {
    if (!p.step(k, t).empty()) fired_at = k;
  }
  CHECK(fired_at == 2500);
  CHECK(p.feed_hold());
}

TEST_CASE("a line event fires in the cycle its n-th pass starts") {
  const Scenario s = load("[[event]]\nline = 7\npass = 2\nve = { PART = 4 }\n");
  Player p(s);
  p.block_started(7);
  CHECK(p.step(0, 0.0).empty());
  p.block_started(8);
  CHECK(p.step(1, kCycle).empty());
  p.block_started(7);
  CHECK(p.passes(7) == 2);
  CHECK(texts(p.step(2, 2 * kCycle)) == "ve PART=4.000000");
  CHECK(p.ve().read("PART") == 4.0);
  p.block_started(7);
  CHECK(p.step(3, 3 * kCycle).empty());
  CHECK(p.passes(8) == 0);  // not named by the scenario: not counted
}

TEST_CASE("a block too short for a cycle still counts its pass") {
  const Scenario s = load("[[event]]\nline = 3\npass = 2\noverride = 20\n");
  Player p(s);
  p.block_started(3);
  p.block_started(4);
  p.block_started(3);  // three blocks within one cycle
  CHECK(texts(p.step(0, 0.0)) == "ovr 0.200000");
}

TEST_CASE("fire_lines fires a line event inside the cycle its block starts, at that time") {
  const Scenario s = load(
      "[[event]]\nline = 3\npass = 2\nfeed_hold = true\nduration = 0.002\n"
      "[[event]]\nline = 3\npass = 2\nve = { A = 1 }\n"
      "[stop]\nline = 4\npasses = 1\n");
  Player p(s);
  CHECK(p.step(0, 0.0).empty());
  p.block_started(3);
  CHECK(p.fire_lines().empty());  // pass 1: no event
  CHECK(p.step(1, kCycle).empty());
  p.block_started(3);
  CHECK(texts(p.fire_lines()) == "hold; ve A=1.000000");  // in cycle 1, not at step(2)
  CHECK(p.ve().read("A") == 1.0);
  CHECK(p.step(2, 2 * kCycle).empty());              // fired once
  CHECK(texts(p.step(3, 3 * kCycle)) == "release");  // 0.002 s after cycle 1's time
  p.block_started(4);
  p.block_started(3);  // the stop line's pass ended: the run ends before the next cycle
  CHECK(p.fire_lines().empty());
  CHECK(p.step(4, 4 * kCycle).empty());
  CHECK(p.stop() == StopReason::line_passes);
}

TEST_CASE("events due in one cycle fire in file order, releases first") {
  const Scenario s = load(R"(
[[event]]
at = 0
feed_hold = true
duration = 0.002
[[event]]
line = 5
override = 30
[[event]]
at = 0.002
axis_override = { C = 40 }
ve = { B = 2, A = 1 }
[[event]]
at = 0.002
override = 90
)");
  Player p(s);
  CHECK(texts(p.step(0, 0.0)) == "hold");
  CHECK(p.step(1, kCycle).empty());
  p.block_started(5);
  CHECK(texts(p.step(2, 2 * kCycle)) ==
        "release; ovr 0.300000; axis C 0.400000; ve A=1.000000; ve B=2.000000; ovr 0.900000");
  CHECK_FALSE(p.feed_hold());
  CHECK(p.path_override() == doctest::Approx(0.9));
  CHECK(p.axis_override("C") == doctest::Approx(0.4));
  CHECK(p.axis_override("X") == 1.0);
}

TEST_CASE("stop conditions end the run before the cycle that meets them") {
  SUBCASE("time") {
    const Scenario s = load("[stop]\ntime = 0.003\n[[event]]\nat = 0.003\noverride = 5\n");
    Player p(s);
    for (std::uint64_t k = 0; k < 3; ++k)
      p.step(k, static_cast<double>(k) * kCycle);
    CHECK_FALSE(p.stop());
    CHECK(p.step(3, 3 * kCycle).empty());  // the stop wins: the event does not fire
    CHECK(p.stop() == StopReason::time);
    CHECK(p.step(4, 4 * kCycle).empty());
  }
  SUBCASE("cycles") {
    const Scenario s = load("[stop]\ncycles = 2\n");
    Player p(s);
    p.step(0, 0.0);
    p.step(1, kCycle);
    CHECK_FALSE(p.stop());
    p.step(2, 2 * kCycle);
    CHECK(p.stop() == StopReason::cycles);
    CHECK(to_string(*p.stop()) == "stop.cycles");
  }
  SUBCASE("passes: when the n-th pass of the line ends") {
    const Scenario s = load("[stop]\nline = 4\npasses = 2\n");
    Player p(s);
    std::uint64_t k = 0;
    for (int loop = 0; loop < 2; ++loop) {
      p.block_started(3);
      p.step(k, static_cast<double>(k) * kCycle);
      ++k;
      p.block_started(4);
      p.step(k, static_cast<double>(k) * kCycle);
      ++k;
      CHECK_FALSE(p.stop());
    }
    p.block_started(4);  // a block of the same line starts: the second pass ended
    p.step(k, static_cast<double>(k) * kCycle);
    CHECK(p.stop() == StopReason::line_passes);
  }
}

TEST_CASE("the V.E. store answers a barrier with the names it holds") {
  const Scenario s = load("[ve]\nPART = 2\n[[event]]\nat = 0.001\nve = { READY = 1 }\n");
  Player p(s);
  std::map<std::string, double> answer;
  p.ve().answer({"PART", "READY", "OTHER"}, answer);
  CHECK(answer == std::map<std::string, double>{{"PART", 2.0}});
  const std::uint64_t g = p.ve().generation();
  p.step(0, 0.0);
  p.step(1, kCycle);
  CHECK(p.ve().generation() == g + 1);
  answer.clear();
  p.ve().answer({"PART", "READY"}, answer);
  CHECK(answer == std::map<std::string, double>{{"PART", 2.0}, {"READY", 1.0}});
}

TEST_CASE("seeded random progress: every time event fires once, in order; reruns are equal") {
  std::string spec;
  for (int i = 0; i < 40; ++i) {
    spec += "[[event]]\nat = " + std::to_string(i * 0.0137) + "\noverride = " + std::to_string(i) +
            "\n";
    spec += "[[event]]\nline = " + std::to_string(1 + i % 9) +
            "\npass = " + std::to_string(1 + i % 4) + "\nve = { V" + std::to_string(i) + " = 1 }\n";
  }
  const Scenario s = load(spec);
  const auto run = [&](std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::uint32_t> line(1, 10);
    std::uniform_int_distribution<int> blocks(0, 3);
    Player p(s);
    std::string log;
    int overrides = 0;
    double last = -1.0;
    for (std::uint64_t k = 0; k < 2000; ++k) {
      for (int b = blocks(rng); b > 0; --b)
        p.block_started(line(rng));
      for (const Action& a : p.step(k, static_cast<double>(k) * kCycle)) {
        if (const auto* o = std::get_if<PathOverride>(&a)) {
          CHECK(o->fraction >= last);
          last = o->fraction;
          ++overrides;
        }
        log += std::to_string(k) + ":" + text(a) + "\n";
      }
    }
    CHECK(overrides == 40);
    return log;
  };
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    CAPTURE(seed);
    CHECK(run(seed) == run(seed));
  }
}

}  // namespace
}  // namespace ncsim::scenario
