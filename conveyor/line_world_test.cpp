// conveyor/line_world: workpieces shared along the belt by the stations of a line
// (docs/lines.md "Workpieces along the belt").
#include "conveyor/line_world.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <memory>
#include <string>

#include "conveyor/test_world.hpp"

namespace ncsim::conveyor {
namespace {

constexpr double kT = 0.001;  // [s] cycle

// An encoder belt at `v` mm/s with workpieces (by travel) at `travels`, 100 mm long.
scenario::Conveyor stream(double v, const std::vector<double>& travels) {
  scenario::Conveyor c = *test::belt(scenario::ConveyorMode::encoder, v).conveyor;
  for (const double u : travels) {
    scenario::Workpiece w;
    w.travel = u;
    w.length = 100.0;
    c.workpieces.push_back(w);
  }
  return c;
}

// The line world on the test machine: stations at `at` [mm], each with method `signal`.
std::unique_ptr<LineWorld> line(const scenario::Conveyor& c, const std::vector<double>& at,
                                double belt_end, const char* signal = "DRIVE_TYPE_DEFAULT") {
  const machines::Machine m = test::machine(true, signal);
  scenario::Scenario belt_only;
  belt_only.conveyor = c;
  belt_only.conveyor->workpieces.clear();
  std::vector<StationSpec> stations;
  for (std::size_t k = 0; k < at.size(); ++k)
    stations.push_back(station_of(m, static_cast<std::uint8_t>(k + 1), at[k]));
  return std::make_unique<LineWorld>(make_port(m, &belt_only, kT), &c, 1.0, stations, belt_end);
}

machines::ProbeArm probe() {
  machines::ProbeArm a;
  a.axis = 1;  // S, the test machine's conveyor axis
  a.channel = 1;
  return a;
}

bool conserved(const LineWorld& w) {
  return w.arrived() == w.on_belt() + w.taken_total() + w.missed();
}

TEST_CASE("line world: a workpiece the first station does not measure passes on to the next") {
  // 300 mm/s; workpieces at 100 and 400 mm of travel; stations at 0 and 600 mm, the end 900.
  const scenario::Conveyor c = stream(300.0, {100.0, 400.0});
  auto w = line(c, {0.0, 600.0}, 900.0);
  w->port(0).arm_probe(probe());  // channel 1 measures the first only
  w->port(1).arm_probe(probe());  // channel 2 waits for what channel 1 lets pass
  std::optional<double> first;
  std::optional<double> second;
  for (int k = 1; k <= 4000; ++k) {
    const double t = k * kT;
    w->step_once(t);
    if (!first) first = w->port(0).take_latch();
    if (!second) second = w->port(1).take_latch();
    REQUIRE(conserved(*w));
  }
  REQUIRE(first);
  REQUIRE(second);
  CHECK(w->port(0).last_latch().workpiece == 1);
  CHECK(*first == doctest::Approx(100.0).epsilon(1e-9));
  CHECK(w->port(1).last_latch().workpiece == 2);
  CHECK(*second == doctest::Approx(1000.0).epsilon(1e-9));  // 400 + its sensor's 600
  CHECK(w->arrived() == 2);
  CHECK(w->held() == 2);  // both measured, neither finished nor let go
  w->done(0, 1, 4.0);
  CHECK(w->taken(0) == 1);
  CHECK(w->fates()[0].fate == Fate::taken);
  CHECK(w->fates()[0].channel == 1);
  CHECK(w->fates()[0].t == 4.0);
  CHECK(conserved(*w));
}

TEST_CASE("line world: a workpiece let go passes on; free past the belt's end it is missed") {
  const scenario::Conveyor c = stream(300.0, {100.0});
  auto w = line(c, {0.0, 600.0}, 900.0);
  w->port(0).arm_probe(probe());
  double t = 0.0;
  for (int k = 1; k <= 400; ++k) {
    t = k * kT;
    w->step_once(t);
  }
  REQUIRE(w->port(0).take_latch());
  // The PLC's words: the workpiece and its travel since channel 1's sensor (20 mm at 0.4 s).
  const LatchInfo& l = w->port(0).last_latch();
  REQUIRE(l.ve.size() == 2);
  CHECK(l.ve[0].first == kVeWorkpiece);
  CHECK(l.ve[0].second == 1.0);
  CHECK(l.ve[1].first == kVeTravel);
  CHECK(l.ve[1].second == doctest::Approx(300.0 * t - 100.0).epsilon(1e-6));
  w->let_go(0, 1, t);  // the program did not want it
  CHECK(w->fates()[0].fate == Fate::free);
  CHECK(w->more_for(1));
  // Channel 2 is never armed: the workpiece passes its sensor unmeasured, then the end.
  for (int k = 401; k <= 4000; ++k)
    w->step_once(k * kT);
  CHECK(w->missed() == 1);
  CHECK(w->fates()[0].fate == Fate::missed);
  CHECK(w->fates()[0].t == doctest::Approx(1000.0 / 300.0).epsilon(1e-9));  // 100 + 900 mm
  CHECK(w->on_belt() == 0);
  CHECK_FALSE(w->more_for(0));
  w->port(1).arm_probe(probe());  // nothing can come any more: NC9003
  REQUIRE(w->port(1).error());
  CHECK(w->port(1).error()->id == "NC9003");
  CHECK_FALSE(w->port(0).error());
}

TEST_CASE("line world: an armed probe the last workpiece can no longer reach ends with NC9003") {
  // One workpiece; channel 2 (downstream) arms while it is still upstream (LINE_MORE 1),
  // channel 1 measures and takes it: nothing can reach channel 2's sensor any more. Before,
  // channel 2 waited until ncsim's 600 s limit (NC9054).
  const scenario::Conveyor c = stream(300.0, {100.0});
  auto w = line(c, {0.0, 600.0}, 900.0);
  w->port(0).arm_probe(probe());
  w->port(1).arm_probe(probe());
  REQUIRE_FALSE(w->port(1).error());
  int k = 1;
  for (; k <= 400; ++k)
    w->step_once(k * kT);
  REQUIRE(w->port(0).take_latch());
  w->step_once(k++ * kT);
  CHECK_FALSE(w->port(1).error());  // held upstream: it may still be let go
  w->done(0, 1, k * kT);
  // From the cycle the stream is through (the workpiece's rear edge past the line's sensor,
  // 200 mm at 300 mm/s), not at ncsim's time limit.
  for (; k <= 1000 && !w->port(1).error(); ++k)
    w->step_once(k * kT);
  REQUIRE(w->port(1).error());
  CHECK(w->port(1).error()->id == "NC9003");
  CHECK(k * kT == doctest::Approx(200.0 / 300.0).epsilon(0.01));
  CHECK_FALSE(w->port(0).error());
}

TEST_CASE("line world: method 3 queues every workpiece per station; held by one, dropped by all") {
  const scenario::Conveyor c = stream(300.0, {100.0, 250.0, 400.0});
  auto w = line(c, {0.0, 300.0}, 2000.0, "PLC_EXT_LATCH_CONTROL");
  for (int k = 1; k <= 1400; ++k)  // all three passed both sensors (400 + 300 mm at 1.33 s)
    w->step_once(k * kT);
  CHECK(w->on_belt() == 3);
  CHECK(w->held() == 0);
  w->port(1).arm_probe(probe());  // channel 2 asks first: the oldest of its queue
  REQUIRE(w->port(1).take_latch());
  CHECK(w->port(1).last_latch().workpiece == 1);
  w->port(0).arm_probe(probe());  // channel 1's queue still has 1: dropped, it gets 2
  REQUIRE(w->port(0).take_latch());
  CHECK(w->port(0).last_latch().workpiece == 2);
  CHECK(w->held() == 2);
  CHECK(conserved(*w));
}

TEST_CASE("line world: a light barrier's rear edge is not supported at a station (NC9007)") {
  const scenario::Conveyor c = stream(300.0, {100.0});
  auto w = line(c, {0.0}, 900.0);
  machines::ProbeArm a = probe();
  a.edge = machines::ProbeEdge::falling;
  w->port(0).arm_probe(a);
  REQUIRE(w->port(0).error());
  CHECK(w->port(0).error()->id == "NC9007");
}

// SplitMix64: the property test's own seeded numbers.
struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) / 9007199254740992.0; }
};

// A scripted channel: arms, takes, then lets go or works on the workpiece for a while.
struct Picker {
  enum class State { idle, armed, working, ended } state = State::idle;
  double until = 0.0;  // [s] the end of its current idle or work
};

// One seeded line: random stream, 2..3 stations of random methods and places, pickers that
// skip at random. Returns false (with the seed in the failure) if a count is ever off.
void random_line(std::uint64_t seed) {
  Rng rng{seed};
  std::vector<double> travels;
  double u = 50.0;
  const int n = 20 + static_cast<int>(rng.next() % 30);
  for (int i = 0; i < n; ++i) {
    u += 110.0 + rng.uniform() * 400.0;  // gaps of 10 .. 410 mm after 100 mm parts
    travels.push_back(u);
  }
  const std::size_t stations = 2 + rng.next() % 2;
  std::vector<double> at{0.0};
  for (std::size_t k = 1; k < stations; ++k)
    at.push_back(at.back() + 200.0 + rng.uniform() * 800.0);
  const double end = at.back() + rng.uniform() * 600.0;
  const char* signal = rng.next() % 2 == 0 ? "DRIVE_TYPE_DEFAULT" : "PLC_EXT_LATCH_CONTROL";
  const scenario::Conveyor c = stream(300.0, travels);
  auto w = line(c, at, end, signal);
  std::vector<Picker> pickers(stations);
  const double t_last = (u + end + 1000.0) / 300.0;  // every workpiece past the end
  for (std::uint64_t k = 1;; ++k) {
    const double t = static_cast<double>(k) * kT;
    w->step_once(t);
    for (std::size_t s = 0; s < stations; ++s) {
      Picker& p = pickers[s];
      Port& port = w->port(s);
      if (p.state == Picker::State::idle && t >= p.until && w->more_for(s)) {
        port.arm_probe(probe());
        p.state = Picker::State::armed;
      } else if (p.state == Picker::State::armed && port.take_latch()) {
        if (rng.next() % 4 == 0) {  // not this one
          w->let_go(s, port.last_latch().workpiece, t);
          p.state = Picker::State::idle;
        } else {
          p.state = Picker::State::working;
          p.until = t + 0.2 + rng.uniform() * 1.5;
        }
      } else if (p.state == Picker::State::working && t >= p.until) {
        w->done(s, port.last_latch().workpiece, t);
        p.state = Picker::State::idle;
        p.until = t + rng.uniform() * 0.5;
      }
      if (port.error() && p.state != Picker::State::ended) {
        // Armed when the last workpiece that could reach it is taken upstream: NC9003, right
        // then (the channel would end with it), and only then.
        if (port.error()->id == std::string(kNoWorkpieceId) && p.state == Picker::State::armed &&
            !w->more_for(s)) {
          p.state = Picker::State::ended;
          continue;
        }
        FAIL("seed " << seed << " station " << s << " t " << t << ": " << port.error()->message);
      }
    }
    if (!conserved(*w)) FAIL("seed " << seed << " t " << t << ": counts do not close");
    if (t > t_last && w->held() == 0) break;
    if (t > t_last + 10.0) FAIL("seed " << seed << ": a workpiece is still held");
  }
  INFO("seed " << seed);
  CHECK(w->arrived() == static_cast<std::uint64_t>(n));
  CHECK(w->on_belt() == 0);
  CHECK(w->taken_total() + w->missed() == w->arrived());
  std::uint64_t taken = 0;
  std::uint64_t missed = 0;
  for (const WorkpieceFate& f : w->fates()) {
    taken += f.fate == Fate::taken ? 1 : 0;
    missed += f.fate == Fate::missed ? 1 : 0;
  }
  CHECK(taken == w->taken_total());
  CHECK(missed == w->missed());
}

TEST_CASE("line world: taken + missed = arrived over 300 seeded random lines") {
  for (std::uint64_t seed = 1; seed <= 300; ++seed)
    random_line(seed);
}

}  // namespace
}  // namespace ncsim::conveyor
