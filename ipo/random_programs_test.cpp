// Seeded random programs at the PathInterpolator level, with the dense-CAM cases of issue 12:
// runs of 0.05-0.5 mm chords along curves of random curvature (knees that carry the path
// acceleration inside chains, and knees that do not) mixed with lines, arcs, helices, tolerance
// balls, stops and dwells, random limits and cycles of 0.25-4 ms. Checked: the audit finds no
// limit exceeded beyond the documented steps (inner knees of chains included), the contour stays
// within tolerance, every programmed end point where the path stands is reached bit for bit,
// `time` (machining_time) equals the stepped cycle count, reruns are byte-identical.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "audit/audit.hpp"
#include "audit/time.hpp"
#include "ipo/interpolator.hpp"
#include "ipo/test_support.hpp"

namespace {

using namespace ncsim::audit;
using namespace ncsim::ipo;
using namespace ncsim::ipo::test;
namespace planner = ncsim::planner;

/// A run of chords of length h along a curve whose direction turns by h / radius a chord
/// (the sign of the turn flips now and then: S-shapes), at one feed.
void chords(std::mt19937_64& rng, std::vector<Item>& items, AxisVec& pos, std::uint32_t& ln) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 20 + static_cast<int>(rng() % 300);
  const double h = 0.05 + 0.45 * u(rng);
  const double radius = 0.5 + 80.0 * u(rng);
  const double feed = 10.0 + 150.0 * u(rng);
  double dir = 2.0 * std::numbers::pi * u(rng);
  double turn = u(rng) < 0.5 ? 1.0 : -1.0;
  const bool contour = u(rng) < 0.2;
  const double dz = u(rng) < 0.2 ? 0.02 * (u(rng) - 0.5) : 0.0;
  for (int k = 0; k < n; ++k) {
    if (u(rng) < 0.02) turn = -turn;
    dir += turn * h / radius;
    AxisVec q = pos;
    q[0] += h * std::cos(dir);
    q[1] += h * std::sin(dir);
    q[2] += dz;
    planner::Move m = line(pos, q, feed, ln++);
    if (contour) {
      m.contour = planner::Contour::tolerance;
      m.path_dev = 0.001 + 0.02 * u(rng);
    }
    items.emplace_back(m);
    pos = q;
  }
}

/// Random lines, arcs, helices, blends, stops and dwells (test_support) with dense chord runs.
std::vector<Item> program(std::mt19937_64& rng) {
  std::vector<Item> items;
  AxisVec pos{};
  std::uint32_t ln = 1;
  for (int part = 0; part < 4; ++part) {
    RandomProgram p;
    p.moves = 8;
    std::vector<Item> mixed = random_program(rng, p);
    // Rebase the mixed part onto the current position and renumber its lines.
    const AxisVec base = pos;
    for (Item& it : mixed) {
      if (auto* m = std::get_if<planner::Move>(&it)) {
        for (std::size_t i = 0; i < 3; ++i) {
          m->start[i] += base[i];
          m->end[i] += base[i];
        }
        if (m->arc) {
          m->arc->centre_1 += base[m->arc->axis_1];
          m->arc->centre_2 += base[m->arc->axis_2];
        }
        m->line = ln++;
        pos = m->end;
      } else {
        std::get<Dwell>(it).line = ln++;
      }
      items.push_back(it);
    }
    chords(rng, items, pos, ln);
  }
  return items;
}

/// The audit, a hash of every cycle's bytes, where the path stood still, and the steps seen.
struct Probe final : Sink {
  Audit audit;
  std::uint64_t hash = 1469598103934665603ull;
  std::uint64_t cycles = 0;
  std::vector<AxisVec> standing;
  Activity last = Activity::motion;
  AxisVec last_x{};
  explicit Probe(const Config& cfg) : audit(cfg.axes, cfg.channel.t_cycle, cfg.start) {}
  void mix(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i)
      hash = (hash ^ b[i]) * 1099511628211ull;
  }
  void on_joint(const Joint& j) override {
    audit.on_joint(j);
    mix(&j.t, sizeof j.t);
    mix(j.dv.data(), sizeof j.dv);
    mix(j.da.data(), sizeof j.da);
  }
  void on_cycle(const Cycle& c) override {
    ++cycles;
    audit.on_cycle(c);
    mix(&c.line, sizeof c.line);
    mix(c.x.data(), sizeof c.x);
    mix(c.v.data(), sizeof c.v);
    mix(c.a.data(), sizeof c.a);
    mix(&c.path.v, sizeof c.path.v);
    if (c.activity != Activity::motion && last == Activity::motion) standing.push_back(last_x);
    last = c.activity;
    last_x = c.x;
  }
};

}  // namespace

TEST_CASE(
    "property: random programs with dense chord runs keep every limit, reach every stop, "
    "time equals run") {
  std::mt19937_64 rng(6400);
  std::uint64_t steps = 0;
  std::uint64_t velojump_steps = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const Config cfg = random_config(rng, 16, 0.0);
    const std::vector<Item> items = program(rng);
    // Where the path must stand: G60 ends, block ends before a dwell, the program end.
    std::vector<AxisVec> expected;
    for (std::size_t k = 0; k < items.size(); ++k) {
      const auto* m = std::get_if<planner::Move>(&items[k]);
      if (!m) continue;
      const bool before_dwell = k + 1 < items.size() && std::holds_alternative<Dwell>(items[k + 1]);
      if (m->exact_stop || before_dwell || k + 1 == items.size()) expected.push_back(m->end);
    }
    CAPTURE(trial);
    std::uint64_t hashes[2] = {0, 0};
    std::uint64_t stepped = 0;
    for (int rerun = 0; rerun < 2; ++rerun) {
      ListSource src(items);
      Probe probe(cfg);
      PathInterpolator ipo(cfg, src, &probe);
      Status st;
      while ((st = ipo.step()) == Status::running) {
      }
      if (probe.last == Activity::motion) probe.standing.push_back(probe.last_x);
      CHECK(st == Status::finished);
      const Verdict& v = probe.audit.verdict();
      if (!v.ok()) {
        const Violation& x = v.violations.front();
        CAPTURE(static_cast<int>(x.quantity));
        CAPTURE(static_cast<int>(x.method));
        CAPTURE(x.axis);
        CAPTURE(x.t);
        CAPTURE(x.line);
        CAPTURE(x.value);
        CAPTURE(x.limit);
        CHECK(v.ok());
      }
      // A G60 without settling time waits no cycle: its stand is then not seen as a wait,
      // only the ends before dwells and the program end are (each a subsequence check).
      std::size_t next = 0;
      for (const AxisVec& s : probe.standing) {
        while (next < expected.size() && expected[next] != s)
          ++next;
        CHECK(next < expected.size());
        ++next;
      }
      REQUIRE_FALSE(probe.standing.empty());
      CHECK(probe.standing.back() == expected.back());
      hashes[rerun] = probe.hash;
      stepped = probe.cycles;
      steps += v.step_count;
      for (const Step& s : v.steps)
        if (s.quantity == Quantity::velojump && s.v_link > 0.0) ++velojump_steps;
    }
    CHECK(hashes[0] == hashes[1]);
    ListSource src(items);
    const TimeResult t = machining_time(cfg, src);
    CHECK(t.status == Status::finished);
    CHECK(t.cycles == stepped);
  }
  CHECK(steps > 1000);
  CHECK(velojump_steps > 1000);
}

TEST_CASE(
    "dense chords at F: the knees carry the acceleration, the feed is reached within "
    "one ramp, every inner knee is audited") {
  // 2000 chords of 0.1 mm along curves of radius >= 20 mm at F = 100 mm/s (the ipo_bench
  // program, shorter), V 200, A 2000, J 1e5, T 1 ms. With a = 0 at every joint the path needs
  // about 100 mm to reach F (0.1 mm raises v by ~0.1 mm/s at 50 mm/s); carried through, one
  // S-ramp of (100/2000 + 2000/1e5) 100 / 2 = 3.5 mm.
  std::vector<Item> items;
  AxisVec p{};
  double dir = 0.0;
  for (int k = 0; k < 2000; ++k) {
    dir += 0.1 / 20.0 * std::sin(k * 0.002);
    AxisVec q = p;
    q[0] += 0.1 * std::cos(dir);
    q[1] += 0.1 * std::sin(dir);
    items.emplace_back(line(p, q, 100.0, static_cast<std::uint32_t>(k + 1)));
    p = q;
  }
  Config cfg;
  cfg.axes = {axis(200, 2000, 1e5), axis(200, 2000, 1e5), axis(200, 2000, 1e5)};
  cfg.channel.t_cycle = 0.001;
  ListSource src(items);
  Probe probe(cfg);
  PathInterpolator ipo(cfg, src, &probe);
  double v_at_5mm = 0.0;
  double s_total = 0.0;
  while (ipo.step() == Status::running) {
    s_total += ipo.cycle().distance;
    if (s_total <= 5.0) v_at_5mm = ipo.cycle().path.v;
  }
  CHECK(v_at_5mm > 99.0);
  const Verdict& v = probe.audit.verdict();
  CHECK(v.ok());
  CHECK(v.step_count > 1000);  // the knees inside chains are reported and checked
  // 200 mm at 100 mm/s plus one ramp up and one down (about 2 x 0.035 s).
  CHECK(static_cast<double>(v.cycles) * 0.001 < 2.1);
}
