// Override and feed hold (issue 13; 000 §7.5.6 l.351-357, §7.5.11 l.366; 002 l.346-391): the
// manual's example in both iterated types (seed-reading A1), a hold in the middle of an arc and
// inside a tolerance ball, an override change deferred until the ball is left, a step to 120 %
// with "Reduced [0 .. >100 %]", and seeded random override / hold sequences over random
// programs (audit clean, contour kept, every stop point reached, deterministic).

#include "ipo/override.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <random>
#include <stdexcept>
#include <string>
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

Config config(std::vector<planner::AxisLimits> axes, OverrideType type = OverrideType::reduced,
              double t = 0.001) {
  Config c;
  c.axes = std::move(axes);
  c.channel.t_cycle = t;
  c.override_type = type;
  return c;
}

/// Records every cycle; runs the audit beside.
struct Recorder final : Sink {
  Audit audit;
  std::vector<Cycle> cycles;
  bool keep = true;               ///< keep every cycle (else only the summary below)
  std::vector<AxisVec> standing;  ///< x of the last motion cycle before each wait / the end
  std::uint64_t hash = 1469598103934665603ull;
  bool any_held = false;
  Cycle last;
  explicit Recorder(const Config& cfg) : audit(cfg.axes, cfg.channel.t_cycle, cfg.start) {}
  std::vector<Joint> joints;
  void on_joint(const Joint& j) override {
    audit.on_joint(j);
    joints.push_back(j);
  }
  void on_cycle(const Cycle& c) override {
    audit.on_cycle(c);
    if (keep) cycles.push_back(c);
    if (c.activity != Activity::motion && last.activity == Activity::motion && last.index > 0)
      standing.push_back(last.x);
    any_held = any_held || c.held;
    const auto* bytes = reinterpret_cast<const unsigned char*>(c.x.data());
    for (std::size_t i = 0; i < sizeof c.x; ++i)
      hash = (hash ^ bytes[i]) * 1099511628211ull;
    last = c;
  }
};

/// Runs `items`; `op(ipo, cycle_index)` is called before each step (the operator).
Status run(const Config& cfg, std::vector<Item> items, Recorder& rec,
           const std::function<void(PathInterpolator&, std::size_t)>& op = {}) {
  ListSource src(std::move(items));
  PathInterpolator ipo(cfg, src, &rec);
  Status st;
  for (std::size_t k = 0;; ++k) {
    if (op) op(ipo, k);
    if ((st = ipo.step()) != Status::running) {
      if (st == Status::error) MESSAGE(ipo.message());
      break;
    }
    if (k > 10'000'000) return Status::error;  // a hold never released: the test fails
  }
  return st;
}

double max_v(const std::vector<Cycle>& cs) {
  double v = 0.0;
  for (const Cycle& c : cs)
    v = std::max(v, c.path.v);
  return v;
}

void check_audit(const Recorder& rec) {
  const Verdict& v = rec.audit.verdict();
  if (!v.ok()) {
    const Violation& x = v.violations.front();
    for (const Cycle& c : rec.cycles)
      if (std::abs(c.t - x.t) < 0.02)
        MESSAGE(c.t << " line " << c.line << " s " << c.path.s << " v " << c.path.v << " a "
                    << c.path.a << " j " << c.path.j << " x0 " << c.x[0] << " f " << c.factor
                    << " held " << c.held << " xs " << std::setprecision(17) << c.x[0] << " "
                    << c.x[1] << " " << c.x[2] << " jl " << c.interval_jerk_limited);
    for (const Joint& j : rec.joints)
      if (std::abs(j.t - x.t) < 0.005)
        MESSAGE("joint " << j.t << " cls " << static_cast<int>(j.cls) << " v " << j.v << " da "
                         << j.da[0] << " dv " << j.dv[0] << " jl " << j.jerk_limited);
    CAPTURE(static_cast<int>(x.quantity));
    CAPTURE(static_cast<int>(x.method));
    CAPTURE(x.axis);
    CAPTURE(x.t);
    CAPTURE(x.value);
    CAPTURE(x.limit);
    CHECK(v.ok());
  }
}

/// The manual's example (000 l.105/258, seed-reading A1): F = 1000 mm/s on 168 mm,
/// A = 5000 mm/s^2, J = 50000 mm/s^3: the 100 % profile peaks at 700 mm/s.
double example_peak(OverrideType type, double factor) {
  const auto ax = axis(2000.0, 5000.0, 50000.0);
  const Config cfg = config({ax, ax, ax}, type);
  Recorder rec(cfg);
  const Status st = run(cfg, {line(vec(0, 0), vec(168, 0), 1000.0, 1)}, rec,
                        [&](PathInterpolator& ipo, std::size_t k) {
                          if (k == 0) ipo.path_override().set_override(factor);
                        });
  CHECK(st == Status::finished);
  check_audit(rec);
  CHECK(rec.cycles.back().x[0] == 168.0);
  return max_v(rec.cycles);
}

TEST_CASE("manual example, Reduced (iterated): 700 mm/s x override (000 l.354, A1)") {
  CHECK(example_peak(OverrideType::reduced, 1.0) == doctest::Approx(700.0).epsilon(1e-9));
  CHECK(example_peak(OverrideType::reduced, 0.5) == doctest::Approx(350.0).epsilon(1e-9));
  CHECK(example_peak(OverrideType::reduced, 0.8) == doctest::Approx(560.0).epsilon(1e-9));
}

TEST_CASE("manual example, Original (iterated): min(1000 x override, 700) (000 l.357, A1)") {
  CHECK(example_peak(OverrideType::original, 0.5) == doctest::Approx(500.0).epsilon(1e-9));
  CHECK(example_peak(OverrideType::original, 0.8) == doctest::Approx(700.0).epsilon(1e-9));
  CHECK(example_peak(OverrideType::original, 0.3) == doctest::Approx(300.0).epsilon(1e-9));
}

TEST_CASE("override levels per type; factors outside the type's range are refused") {
  CHECK(override_level(OverrideType::reduced, 0.5, 700.0, 1000.0, 0.0) == 350.0);
  CHECK(override_level(OverrideType::original, 0.5, 700.0, 1000.0, 0.0) == 500.0);
  CHECK(override_level(OverrideType::original, 0.8, 700.0, 1000.0, 0.0) == 700.0);
  CHECK(override_level(OverrideType::reduced_above_100, 1.2, 700.0, 1000.0, 800.0) == 800.0);
  CHECK(override_level(OverrideType::reduced_above_100, 1.2, 700.0, 1000.0, 900.0) ==
        doctest::Approx(840.0));
  const auto ax = axis(100.0, 1000.0, 1e5);
  ListSource src({});
  PathInterpolator reduced(config({ax, ax, ax}), src);
  CHECK_THROWS_AS(reduced.path_override().set_override(1.2), std::invalid_argument);
  CHECK_THROWS_AS(reduced.path_override().set_override(-0.1), std::invalid_argument);
  CHECK_THROWS_AS(reduced.path_override().set_override(std::nan("")), std::invalid_argument);
  PathInterpolator above(config({ax, ax, ax}, OverrideType::reduced_above_100), src);
  CHECK_NOTHROW(above.path_override().set_override(1.2));
  CHECK_THROWS_AS(above.path_override().set_override(kMaxOverride * 1.01), std::invalid_argument);
}

TEST_CASE("a change mid-block ramps with the jerk limit; at 100 % nothing differs from the plan") {
  const auto ax = axis(200.0, 2000.0, 2e4);
  const Config cfg = config({ax, ax, ax});
  const std::vector<Item> prog = {line(vec(0, 0), vec(300, 0), 100.0, 1),
                                  line(vec(300, 0), vec(300, 200), 100.0, 2)};
  Recorder plain(cfg);
  run(cfg, prog, plain);
  Recorder same(cfg);
  run(cfg, prog, same, [](PathInterpolator& ipo, std::size_t k) {
    if (k == 500) ipo.path_override().set_override(1.0);
  });
  REQUIRE(plain.cycles.size() == same.cycles.size());
  for (std::size_t k = 0; k < plain.cycles.size(); ++k)
    CHECK(plain.cycles[k].x == same.cycles[k].x);
  Recorder slow(cfg);
  run(cfg, prog, slow, [](PathInterpolator& ipo, std::size_t k) {
    if (k == 1500) ipo.path_override().set_override(0.4);
    if (k == 3500) ipo.path_override().set_override(0.9);
  });
  check_audit(slow);
  // Before the change the path is on plan; after the ramp it cruises at 40 mm/s.
  CHECK(slow.cycles[1400].path.v == doctest::Approx(100.0));
  CHECK(slow.cycles[1600].path.v < 100.0);
  CHECK(slow.cycles[1600].path.v > 40.0);  // still ramping: no velocity step
  CHECK(slow.cycles[3000].path.v == doctest::Approx(40.0));
  CHECK(slow.cycles[3000].factor == 0.4);
  double lost = 0.0;
  for (const Cycle& c : slow.cycles)
    lost += c.lost;
  // The time lost on the path equals the time difference to the 100 % run, to a cycle per stop.
  const double diff = static_cast<double>(slow.cycles.size() - plain.cycles.size()) * 0.001;
  CHECK(std::abs(lost - diff) <= 2 * 0.001 + 1e-9);
  CHECK(slow.cycles.back().x[1] == 200.0);
}

TEST_CASE("feed hold in the middle of an arc stops on the arc, holds, resumes and completes") {
  const auto ax = axis(200.0, 2000.0, 5e4);
  const Config cfg = config({ax, ax, ax});
  planner::Move arc = line(vec(50, 0), vec(-50, 0), 80.0, 1);
  arc.arc = planner::Arc{0, 1, 0.0, 0.0, false, false};  // half circle R = 50, CCW
  Config arc_cfg = cfg;
  arc_cfg.start = vec(50, 0);
  Recorder rec(arc_cfg);
  std::size_t hold_from = 0;
  const Status st = run(arc_cfg, {arc}, rec, [&](PathInterpolator& ipo, std::size_t k) {
    if (k == 800) ipo.path_override().set_feed_hold(true);
    if (k == 2000) ipo.path_override().set_feed_hold(false);
    hold_from = k;
  });
  CHECK(st == Status::finished);
  check_audit(rec);
  int held = 0;
  AxisVec at{};
  for (std::size_t k = 0; k < rec.cycles.size(); ++k) {
    const Cycle& c = rec.cycles[k];
    CHECK(std::hypot(c.x[0], c.x[1]) == doctest::Approx(50.0).epsilon(1e-9));  // on the arc
    if (c.held) {
      if (held == 0) at = c.x;
      CHECK(c.x == at);
      CHECK(c.path.v == 0.0);
      CHECK(c.lost == doctest::Approx(0.001));
      ++held;
    }
  }
  CHECK(held > 1000);
  CHECK(at[1] > 10.0);  // stopped in the middle of the arc
  CHECK(rec.cycles.back().x[0] == -50.0);
  CHECK(std::abs(rec.cycles.back().x[1]) < 1e-9);
  CHECK(rec.audit.verdict().contour_max < 1e-9);
}

/// Two lines with a G261 tolerance ball of radius 4 mm at the corner (100, 0).
std::vector<Item> ball_program() {
  planner::Move a = line(vec(0, 0), vec(100, 0), 60.0, 1);
  a.contour = planner::Contour::tolerance;
  a.path_dev = 4.0;
  return {a, line(vec(100, 0), vec(100, 100), 60.0, 2)};
}

bool in_ball(const Cycle& c) {
  return std::hypot(c.x[0] - 100.0, c.x[1]) < 4.0 - 1e-9;
}

TEST_CASE("an override change inside the tolerance ball waits until the ball is left") {
  const auto ax = axis(200.0, 2000.0, 5e4);
  const Config cfg = config({ax, ax, ax});
  Recorder rec(cfg);
  bool requested = false;
  const Status st = run(cfg, ball_program(), rec, [&](PathInterpolator& ipo, std::size_t k) {
    if (!requested && k > 0 && in_ball(rec.cycles.back())) {
      ipo.path_override().set_override(0.3);
      requested = true;
    }
  });
  CHECK(st == Status::finished);
  CHECK(requested);
  check_audit(rec);
  bool left = false;
  bool applied = false;
  for (const Cycle& c : rec.cycles) {
    if (in_ball(c)) {
      CHECK(c.factor == 1.0);  // 000 l.366: no override inside the ball
    } else if (requested && c.x[1] > 0.0) {
      left = true;
      applied = applied || c.factor == 0.3;
    }
  }
  CHECK(left);
  CHECK(applied);
  CHECK(rec.cycles.back().path.v == 0.0);
  CHECK(rec.cycles.back().x[1] == 100.0);
}

TEST_CASE("feed hold inside the tolerance ball stops at once on the blend curve (002 l.391)") {
  const auto ax = axis(200.0, 2000.0, 5e4);
  const Config cfg = config({ax, ax, ax});
  Recorder rec(cfg);
  std::size_t on = 0;
  std::string message;
  const Status st = run(cfg, ball_program(), rec, [&](PathInterpolator& ipo, std::size_t k) {
    message = ipo.message();
    if (on == 0 && k > 0 && in_ball(rec.cycles.back()) && rec.cycles.back().x[1] > 0.01) {
      ipo.path_override().set_feed_hold(true);
      on = k;
    }
    if (on != 0 && k == on + 500) ipo.path_override().set_feed_hold(false);
  });
  CAPTURE(message);
  CHECK(st == Status::finished);
  check_audit(rec);
  bool stood = false;
  for (const Cycle& c : rec.cycles)
    if (c.held) {
      stood = true;
      CHECK(std::hypot(c.x[0] - 100.0, c.x[1]) <= 4.0);  // inside the ball, on the blend
    }
  CHECK(stood);
  CHECK(rec.audit.verdict().contour_max <= 4.0 + 1e-9);
  CHECK(rec.cycles.back().x[1] == 100.0);
}

TEST_CASE("Reduced [0 .. >100 %]: a step to 120 % speeds up to 1.2 F within the G00 velocity") {
  auto ax = axis(200.0, 2000.0, 5e4);
  ax.v_rapid = 150.0;
  const Config cfg = config({ax, ax, ax}, OverrideType::reduced_above_100);
  const std::vector<Item> prog = {line(vec(0, 0), vec(400, 0), 100.0, 1)};
  Recorder rec(cfg);
  run(cfg, prog, rec, [](PathInterpolator& ipo, std::size_t k) {
    if (k == 1000) ipo.path_override().set_override(1.2);
  });
  check_audit(rec);
  CHECK(rec.cycles[900].path.v == doctest::Approx(100.0));
  CHECK(max_v(rec.cycles) == doctest::Approx(120.0).epsilon(1e-9));
  CHECK(rec.cycles.back().x[0] == 400.0);
  double lost = 0.0;
  for (const Cycle& c : rec.cycles)
    lost += c.lost;
  CHECK(lost < -0.3);  // time gained
  // 200 % is limited by the axis's G00 velocity 150 mm/s (000 l.357).
  Recorder fast(cfg);
  run(cfg, prog, fast, [](PathInterpolator& ipo, std::size_t k) {
    if (k == 0) ipo.path_override().set_override(2.0);
  });
  check_audit(fast);
  CHECK(max_v(fast.cycles) == doctest::Approx(150.0).epsilon(1e-9));
}

TEST_CASE("above 100 % the planned stops and corners hold: the exit never exceeds the plan") {
  auto ax = axis(200.0, 2000.0, 5e4);
  const Config cfg = config({ax, ax, ax}, OverrideType::reduced_above_100);
  planner::Move a = line(vec(0, 0), vec(50, 0), 100.0, 1);
  a.exact_stop = true;
  const std::vector<Item> prog = {a, line(vec(50, 0), vec(50, 50), 100.0, 2),
                                  line(vec(50, 50), vec(0, 50), 100.0, 3)};
  Recorder rec(cfg);
  run(cfg, prog, rec, [](PathInterpolator& ipo, std::size_t k) {
    if (k == 0) ipo.path_override().set_override(3.0);
  });
  check_audit(rec);
  bool stopped = false;
  for (const Cycle& c : rec.cycles)
    if (c.activity == Activity::motion && c.x[0] == 50.0 && c.x[1] == 0.0 && c.path.v == 0.0)
      stopped = true;
  CHECK(stopped);
  CHECK(max_v(rec.cycles) == doctest::Approx(200.0).epsilon(1e-9));
}

TEST_CASE("override 0 from the start holds at the start point until released") {
  const auto ax = axis(100.0, 1000.0, 1e4);
  const Config cfg = config({ax, ax, ax});
  Recorder rec(cfg);
  run(cfg, {line(vec(0, 0), vec(10, 0), 50.0, 7)}, rec, [](PathInterpolator& ipo, std::size_t k) {
    if (k == 0) ipo.path_override().set_override(0.0);
    if (k == 100) ipo.path_override().set_override(0.5);
  });
  for (std::size_t k = 0; k < 100; ++k) {
    CHECK(rec.cycles[k].held);
    CHECK(rec.cycles[k].line == 7);
    CHECK(rec.cycles[k].x[0] == 0.0);
  }
  CHECK_FALSE(rec.cycles[100].held);
  CHECK(rec.cycles.back().x[0] == 10.0);
  check_audit(rec);
}

TEST_CASE("machining time counts held cycles and the time lost per block") {
  const auto ax = axis(100.0, 1000.0, 1e4);
  Config cfg = config({ax, ax, ax});
  ListSource src({line(vec(0, 0), vec(50, 0), 50.0, 1), line(vec(50, 0), vec(50, 50), 50.0, 2)});
  double block_lost = 0.0;
  double block_held = 0.0;
  const TimeResult r = machining_time(
      cfg, src,
      [&](const BlockTime& b) {
        block_lost += b.lost;
        block_held += b.split.held;
      },
      0,
      [](PathInterpolator& ipo, std::uint64_t k) {
        ipo.path_override().set_feed_hold(k >= 300 && k < 800);
      });
  CHECK(r.status == Status::finished);
  CHECK(r.split.held == doctest::Approx(block_held));
  CHECK(r.split.held > 0.3);  // 500 cycles of hold minus the ramp down (0.15 s)
  CHECK(r.lost == doctest::Approx(block_lost));
  CHECK(r.lost > r.split.held);  // the hold plus the ramps down and up
  CHECK(r.total == doctest::Approx(r.split.rapid + r.split.feed + r.split.dwell +
                                   r.split.exact_stop + r.split.starved + r.split.held));
}

/// Seeded operator: random override changes and holds.
struct RandomOperator {
  std::mt19937_64 rng;
  OverrideType type;
  void operator()(PathInterpolator& ipo, std::size_t) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double e = u(rng);
    if (e < 0.004) {
      ipo.path_override().set_override(type == OverrideType::reduced_above_100 ? 1.5 * u(rng)
                                                                               : u(rng));
    } else if (e < 0.0045) {
      ipo.path_override().set_override(0.0);
    } else if (e < 0.005) {
      ipo.path_override().set_override(1.0);
    } else if (e < 0.006) {
      ipo.path_override().set_feed_hold(!ipo.path_override().feed_hold());
    }
  }
};

TEST_CASE("property: random override and hold sequences keep limits and contour, complete") {
  std::mt19937_64 rng(1313);
  int held_runs = 0;
  for (int trial = 0; trial < 24; ++trial) {
    Config cfg = random_config(rng, 16, 0.002);
    cfg.override_type = static_cast<OverrideType>(rng() % 3);
    RandomProgram p;
    p.moves = 30;
    auto items = random_program(rng, p);
    // One slope per program: a chain that joins a STEP blend to a TRAPEZ block is planned
    // jerk-limited without the curvature-jerk cap of STEP, which the audit flags (the path
    // passed there below the 100 % plan's velocity: a planner matter, docs/ipo.md).
    const auto slope = rng() % 4 == 0 ? planner::SlopeType::step : planner::SlopeType::trapez;
    for (Item& it : items)
      if (auto* m = std::get_if<planner::Move>(&it)) m->slope = slope;
    std::vector<AxisVec> expected;
    for (std::size_t k = 0; k < items.size(); ++k) {
      const auto* m = std::get_if<planner::Move>(&items[k]);
      if (!m) continue;
      const bool before_dwell = k + 1 < items.size() && std::holds_alternative<Dwell>(items[k + 1]);
      if (m->exact_stop || before_dwell || k + 1 == items.size()) expected.push_back(m->end);
    }
    const std::uint64_t seed = rng();
    std::uint64_t first_hash = 0;
    for (int rerun = 0; rerun < 2; ++rerun) {
      Recorder rec(cfg);
      rec.keep = false;
      RandomOperator op{std::mt19937_64(seed), cfg.override_type};
      const Status st = run(cfg, items, rec, [&](PathInterpolator& ipo, std::size_t k) {
        op(ipo, k);
        if (k % 20000 == 19999) {  // never stay stopped: the program must complete
          ipo.path_override().set_feed_hold(false);
          ipo.path_override().set_override(1.0);
        }
      });
      CAPTURE(trial);
      REQUIRE(st == Status::finished);
      check_audit(rec);
      // Where the path stood by program (not by hold): the G60 / dwell / final end points.
      if (rec.last.activity == Activity::motion) rec.standing.push_back(rec.last.x);
      if (cfg.channel.t_cycle <= 0.002) {
        REQUIRE(rec.standing.size() == expected.size());
        for (std::size_t k = 0; k < expected.size(); ++k)
          for (std::size_t i = 0; i < 3; ++i)
            CHECK(rec.standing[k][i] == expected[k][i]);
      } else {
        for (std::size_t i = 0; i < 3; ++i)
          CHECK(rec.standing.back()[i] == expected.back()[i]);
      }
      if (rerun == 0) {
        held_runs += rec.any_held ? 1 : 0;
        first_hash = rec.hash;
      } else {
        CHECK(rec.hash == first_hash);  // deterministic
      }
    }
  }
  CHECK(held_runs > 5);
}

TEST_CASE("carried speed-ups and brakes under random override and hold changes keep limits") {
  // Straight runs of short collinear lines at random feeds: soft joints between different
  // caps, where the 100 % plan carries a speed-up or a brake, through one joint or several
  // (planner/lookahead.hpp). An override plan ends at a = 0 below the 100 % exit (below a
  // carried brake: the exit with a = 0 at the joint), from which the next entry is planned
  // again (docs/ipo.md "Override and feed hold"); every run completes.
  std::mt19937_64 rng(1414);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int carried_runs = 0;
  int brake_on_runs = 0;  // runs where a brake crosses two joints in a row (brake_through)
  for (int trial = 0; trial < 80; ++trial) {
    Config cfg;
    cfg.axes = random_limits(rng);
    cfg.channel.t_cycle = 0.00025 * static_cast<double>(1 + rng() % 16);
    cfg.window = 10 + rng() % 60;
    cfg.override_type = static_cast<OverrideType>(rng() % 3);
    std::vector<Item> items;
    AxisVec p = vec(0, 0);
    double heading = 6.28 * u(rng);
    for (std::uint32_t k = 0; k < 40; ++k) {
      if (u(rng) < 0.1) heading += u(rng) - 0.5;  // now and then a bend (C0)
      const double len = 0.2 + 5.0 * u(rng) * u(rng);
      const AxisVec q = vec(p[0] + len * std::cos(heading), p[1] + len * std::sin(heading));
      items.emplace_back(line(p, q, 20.0 + 300.0 * u(rng), k + 1));
      p = q;
    }
    const std::uint64_t seed = rng();
    for (int pass = 0; pass < 2; ++pass) {  // 100 %, then with the operator
      Recorder rec(cfg);
      double a_at_joint = 0.0;  // largest path acceleration in a cycle that changed the line
      std::uint32_t line_before = 0;
      bool brake_on = false;
      RandomOperator op{std::mt19937_64(seed), cfg.override_type};
      const Status st = run(cfg, items, rec, [&](PathInterpolator& ipo, std::size_t k) {
        if (pass == 1) op(ipo, k);
        if (k % 20000 == 19999) {
          ipo.path_override().set_feed_hold(false);
          ipo.path_override().set_override(1.0);
        }
        const Cycle& c = ipo.cycle();
        if (c.line != line_before && line_before != 0) a_at_joint = std::max(a_at_joint, c.path.a);
        line_before = c.line;
        const planner::PlannedSegment* e = ipo.active_entry();
        brake_on = brake_on || (e && e->shape == planner::ProfileShape::brake_through);
      });
      CAPTURE(trial);
      CAPTURE(pass);
      REQUIRE(st == Status::finished);
      check_audit(rec);
      for (std::size_t i = 0; i < 2; ++i)
        CHECK(rec.last.x[i] == p[i]);
      if (pass == 0 && a_at_joint > 0.3 * cfg.axes[0].a_max) ++carried_runs;
      if (pass == 0 && brake_on) ++brake_on_runs;
    }
  }
  MESSAGE(carried_runs, " runs carry a speed-up, ", brake_on_runs, " a brake across two joints");
  CHECK(carried_runs > 20);
  CHECK(brake_on_runs > 10);
}

}  // namespace

TEST_CASE("above 100 % under #TRAFO ON the raised cap is the joints' G00 rule, not the TCP's") {
  // trafo-conveyor (issue 12; ipo/override_trafo.cpp): a 100 mm line along X whose joints are
  // q = 2 x (2 deg per mm): each joint at MIN(rapid, reference, max) = 100 deg/s gives a path
  // cap of 50 mm/s; a, j from the joints too, and never above the planned ones.
  planner::Move m;
  m.feed = 20.0;
  m.end[0] = 100.0;
  const planner::Segment seg = planner::Segment::from_move(m);
  planner::PlannedSegment e;
  e.segment.path = planner::Chain(seg);
  e.segment.limits.v_max = 20.0;
  e.segment.limits.a_max = e.segment.limits.d_max = 1000.0;
  e.segment.limits.j_max = 1e5;
  e.a_max = e.d_max = 1000.0;
  e.j_max = 1e5;
  planner::JointLimits joints;
  joints.inverse = [](const planner::AxisVec& x, planner::AxisVec& q) {
    for (std::size_t i = 0; i < planner::kMaxAxes; ++i)
      q[i] = 2.0 * x[i];
    return true;
  };
  planner::AxisLimits j;
  j.v_max = 150.0;
  j.v_reference = 200.0;
  j.v_rapid = 100.0;          // the G00 velocity decides: MIN(100, 200, 150)
  j.a_max = j.d_max = 400.0;  // the path's a at most 200 mm/s^2 through the joints
  j.j_max = 1e6;
  joints.joints = {j, j, j};
  const RaisedLimits r = raised_limits_joints(e, joints);
  CHECK(r.v_max == doctest::Approx(50.0).epsilon(1e-6));
  CHECK(r.a <= 200.0 * (1 + 1e-9));
  CHECK(r.d <= 200.0 * (1 + 1e-9));
  CHECK(r.j <= 1e5);
  // The Cartesian stand-ins would have raised it without bound (why NC6001 stood here before).
  std::vector<planner::AxisLimits> cart(3);
  for (planner::AxisLimits& c : cart) {
    c.v_max = c.v_reference = c.v_rapid = 1e6;
    c.a_max = c.d_max = 1e9;
    c.j_max = 1e12;
  }
  CHECK(raised_limits(e, cart).v_max > 1000.0);
  // A map that fails keeps the planned limits.
  joints.inverse = [](const planner::AxisVec&, planner::AxisVec&) { return false; };
  CHECK(raised_limits_joints(e, joints).v_max == doctest::Approx(20.0));
}
