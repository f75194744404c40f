// Interpolator: a long line reaching F and a short one that cannot (peak = closed form), the
// 90 degree VELOJUMP corner (10 mm/s at C0 = 1, A = 10000, T = 1 ms), the remainder carried
// across joints (cycles = sum of profile durations rounded up once), dwell and G60 rounding,
// bounded memory on an endless source, no allocation inside a segment, errors as Status.

#include "ipo/interpolator.hpp"

#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include "ipo/test_support.hpp"
#include "planner/lookahead.hpp"

namespace {
std::atomic<long long> g_news{0};
std::atomic<long long> g_live{0};
}  // namespace

void* operator new(std::size_t n) {
  ++g_news;
  ++g_live;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  if (p) --g_live;
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  if (p) --g_live;
  std::free(p);
}

namespace {

using namespace ncsim::ipo;
using namespace ncsim::ipo::test;
namespace planner = ncsim::planner;

Config config(std::vector<planner::AxisLimits> axes, double t = 0.001) {
  Config c;
  c.axes = std::move(axes);
  c.channel.t_cycle = t;
  return c;
}

/// Records every cycle and joint.
struct Recorder final : Sink {
  std::vector<Cycle> cycles;
  std::vector<Joint> joints;
  void on_joint(const Joint& j) override { joints.push_back(j); }
  void on_cycle(const Cycle& c) override { cycles.push_back(c); }
};

std::vector<Cycle> run(Config cfg, std::vector<Item> items, Recorder* rec = nullptr) {
  ListSource src(std::move(items));
  Recorder local;
  Recorder& r = rec ? *rec : local;
  PathInterpolator ipo(std::move(cfg), src, &r);
  while (ipo.step() == Status::running) {
  }
  return r.cycles;
}

double max_v(const std::vector<Cycle>& cs) {
  double v = 0.0;
  for (const Cycle& c : cs)
    v = std::max(v, c.path.v);
  return v;
}

TEST_CASE("a long line reaches F; a short one peaks at the closed form (L^2 J / 4)^(1/3)") {
  const auto ax = axis(200.0, 10000.0, 1e5);
  const auto cs = run(config({ax, ax, ax}), {line(vec(0, 0), vec(100, 0), 50.0, 1)});
  CHECK(max_v(cs) == 50.0);
  CHECK(cs.back().x[0] == 100.0);

  const double l = 1.0;
  const double peak = std::cbrt(l * l * 1e5 / 4.0);  // 29.24 mm/s, A not reached
  REQUIRE(std::sqrt(peak * 1e5) < 10000.0);
  const auto cs2 = run(config({ax, ax, ax}), {line(vec(0, 0), vec(l, 0), 100.0, 1)});
  // Sampled at 1 ms: the velocity near the peak is peak - J t^2 / 2, |t| <= T / 2.
  CHECK(max_v(cs2) <= peak * (1.0 + 1e-9));
  CHECK(max_v(cs2) >= peak - 1e5 * 0.0005 * 0.0005 / 2.0 - 1e-9);
  CHECK(cs2.back().x[0] == l);
}

TEST_CASE("a 90 degree corner at C0 = 1, A = 10000 mm/s^2, T = 1 ms is passed at 10 mm/s") {
  const auto ax = axis(200.0, 10000.0, 1e5, 1.0);
  Recorder rec;
  run(config({ax, ax, ax}),
      {line(vec(0, 0), vec(50, 0), 100.0, 1), line(vec(50, 0), vec(50, 50), 100.0, 2)}, &rec);
  REQUIRE(rec.joints.size() == 1);
  const Joint& j = rec.joints[0];
  CHECK(j.cls == planner::TransitionClass::c0);
  CHECK(j.v == doctest::Approx(10.0).epsilon(1e-12));
  CHECK(j.dv[0] == doctest::Approx(-10.0).epsilon(1e-12));
  CHECK(j.dv[1] == doctest::Approx(10.0).epsilon(1e-12));
  CHECK(j.line == 1);
  // The axis velocities sampled in the cycles either side of the joint: within J T^2 / 2 of it
  // (the path acceleration is 0 at a C0 joint).
  std::size_t k = 0;
  while (rec.cycles[k].t < j.t)
    ++k;
  const double near = 1e5 * 0.001 * 0.001 / 2.0 + 1e-9;
  CHECK(std::abs(rec.cycles[k - 1].v[0] - 10.0) <= near);
  CHECK(std::abs(rec.cycles[k].v[1] - 10.0) <= near);
  CHECK(rec.cycles[k - 1].v[1] == 0.0);
  CHECK(std::abs(rec.cycles[k].v[0]) < 1e-9);
}

/// Sum of the profile durations of a program without events, by the planner alone.
double planned_time(const std::vector<planner::AxisLimits>& axes, double t_cycle,
                    const std::vector<Item>& items) {
  planner::ChannelLimits ch;
  ch.t_cycle = t_cycle;
  planner::Preparer prep(axes, ch);
  planner::LookAhead window(120, t_cycle);
  std::vector<planner::PreparedSegment> ready;
  double total = 0.0;
  auto drain = [&](bool all) {
    for (auto& s : ready) {
      while (window.full())
        total += planner::profile(window.pop()).time();
      window.push(std::move(s));
    }
    ready.clear();
    while (all && !window.empty())
      total += planner::profile(window.pop()).time();
  };
  for (const Item& it : items) {
    prep.push(std::get<planner::Move>(it), ready);
    drain(false);
  }
  prep.finish(ready);
  drain(true);
  return total;
}

TEST_CASE("no time is lost or gained at joints: cycles = sum of profile durations, rounded once") {
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const auto axes = random_limits(rng);
    const double t = 0.00025 * (1 + trial % 16);
    RandomProgram p;
    p.stops = false;
    const auto items = random_program(rng, p);
    const double planned = planned_time(axes, t, items);
    const auto cs = run(config(axes, t), items);
    CAPTURE(trial);
    CHECK(cs.size() == static_cast<std::size_t>(std::ceil(planned / t - 1e-9)));
  }
}

TEST_CASE("a dwell is rounded up to whole cycles and holds the position; G60 waits the settling") {
  const auto ax = axis(100.0, 1000.0, 1e5);
  Config cfg = config({ax, ax, ax});
  cfg.exact_stop = {ExactStop{0.01, 0.05}, ExactStop{0.01, 0.02}, ExactStop{0.01, 0.5}};
  planner::Move g60 = line(vec(10, 0), vec(10, 10), 20.0, 3);
  g60.exact_stop = true;
  const auto cs = run(cfg, {line(vec(0, 0), vec(10, 0), 20.0, 1), Dwell{0.1, 2}, g60,
                            Dwell{0.0105, 4}, line(vec(10, 10), vec(0, 10), 20.0, 5)});
  int dwell2 = 0, dwell4 = 0, settle = 0;
  for (const Cycle& c : cs) {
    if (c.activity == Activity::dwell && c.line == 2) {
      ++dwell2;
      CHECK(c.x[0] == 10.0);
      CHECK(c.x[1] == 0.0);
    }
    if (c.activity == Activity::dwell && c.line == 4) ++dwell4;
    if (c.activity == Activity::exact_stop) {
      ++settle;
      CHECK(c.line == 3);
      CHECK(c.x[1] == 10.0);
    }
  }
  CHECK(dwell2 == 100);  // 0.1 s at 1 ms
  CHECK(dwell4 == 11);   // 10.5 ms rounded up
  CHECK(settle == 20);   // only Y moved in the G60 block: its 20 ms
  CHECK(cs.back().x[0] == 0.0);
  CHECK(cs.back().x[1] == 10.0);
}

/// An endless source of lines with turns.
struct Endless final : Source {
  std::mt19937_64 rng{7};
  AxisVec pos{};
  std::uint32_t ln = 0;
  bool next(Item& out) override {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double dir = 6.283185307179586 * u(rng);
    const double len = 0.1 + 5.0 * u(rng);
    AxisVec end = pos;
    end[0] += len * std::cos(dir);
    end[1] += len * std::sin(dir);
    planner::Move m = line(pos, end, 50.0, ++ln);
    if (ln % 3 == 0) {
      m.contour = planner::Contour::tolerance;
      m.path_dev = 0.05;
    }
    out = m;
    pos = end;
    return true;
  }
};

TEST_CASE("an endless program runs in bounded memory") {
  const auto ax = axis(100.0, 2000.0, 1e5);
  Endless src;
  Config cfg = config({ax, ax, ax});
  cfg.window = 30;
  PathInterpolator ipo(std::move(cfg), src);
  const std::size_t ring = ipo.queue().ring_capacity();
  long long peak_first = 0, peak_second = 0;
  for (int k = 0; k < 200000; ++k) {
    REQUIRE(ipo.step() == Status::running);
    if (k > 10000)
      (k < 100000 ? peak_first : peak_second) =
          std::max(k < 100000 ? peak_first : peak_second, g_live.load());
    CHECK(ipo.queue().window().size() <= 30);
  }
  CHECK(ipo.queue().ring_capacity() == ring);
  CHECK(src.ln > 1000);
  CHECK(peak_second <= peak_first + 64);
}

TEST_CASE("stepping inside a segment allocates nothing") {
  const auto ax = axis(100.0, 1000.0, 1e5);
  ListSource src({line(vec(0, 0), vec(1000, 0), 50.0, 1)});
  Recorder rec;
  rec.cycles.reserve(100);
  PathInterpolator ipo(config({ax, ax, ax}), src);
  for (int k = 0; k < 10; ++k)
    REQUIRE(ipo.step() == Status::running);
  const long long before = g_news.load();
  for (int k = 0; k < 10000; ++k)
    REQUIRE(ipo.step() == Status::running);
  CHECK(g_news.load() == before);
}

TEST_CASE("a malformed Move or a failing source ends the stream with an error, not a throw") {
  const auto ax = axis(100.0, 1000.0, 1e5);
  planner::Move bad = line(vec(0, 0), vec(1, 0), 10.0, 2);
  bad.feed = std::nan("");
  ListSource src({line(vec(0, 0), vec(1, 0), 10.0, 1), bad});
  PathInterpolator ipo(config({ax, ax, ax}), src);
  Status st = Status::running;
  for (int k = 0; k < 100000 && st == Status::running; ++k)
    st = ipo.step();
  CHECK(st == Status::error);
  CHECK(ipo.message().find("feed") != std::string::npos);
  CHECK(ipo.step() == Status::error);

  planner::Move dw = line(vec(0, 0), vec(1, 0), 10.0, 1);
  ListSource src2({dw, Dwell{-1.0, 2}});
  PathInterpolator ipo2(config({ax, ax, ax}), src2);
  st = Status::running;
  for (int k = 0; k < 100000 && st == Status::running; ++k)
    st = ipo2.step();
  CHECK(st == Status::error);
  CHECK(ipo2.message().find("G04") != std::string::npos);
}

TEST_CASE("a dwell beyond one day ends the stream with an error, never a 0 s dwell") {
  // issue 34 item 1: ceil(1e17 / t) converted to uint64_t was undefined (a 0 s dwell)
  const auto ax = axis(100.0, 1000.0, 1e5);
  for (const double seconds : {1e17, 1e300, 86'400.5}) {
    CAPTURE(seconds);
    ListSource src({line(vec(0, 0), vec(1, 0), 10.0, 1), Dwell{seconds, 2}});
    Recorder rec;
    PathInterpolator ipo(config({ax, ax, ax}), src, &rec);
    Status st = Status::running;
    for (int k = 0; k < 100000 && st == Status::running; ++k)
      st = ipo.step();
    CHECK(st == Status::error);
    CHECK(ipo.message().find("86400") != std::string::npos);
    for (const Cycle& c : rec.cycles)
      CHECK(c.activity != Activity::dwell);
  }
}

TEST_CASE("a callback source: the program ends when it returns false") {
  const auto ax = axis(100.0, 1000.0, 1e5);
  int calls = 0;
  CallbackSource src([&](Item& out) {
    if (calls == 2) return false;
    const double x = 10.0 * calls++;
    out = line(vec(x, 0), vec(x + 10.0, 0), 20.0, static_cast<std::uint32_t>(calls));
    return true;
  });
  PathInterpolator ipo(config({ax, ax, ax}), src);
  while (ipo.step() == Status::running) {
  }
  CHECK(ipo.cycle().x[0] == 20.0);
  CHECK(ipo.cycle().line == 2);
}

TEST_CASE("configuration errors throw naming the parameter") {
  const auto ax = axis(100.0, 1000.0, 1e5);
  ListSource src({});
  Config cfg = config({ax, ax, ax});
  cfg.exact_stop = {ExactStop{0.0, 0.0}, ExactStop{}, ExactStop{}};
  CHECK_THROWS_WITH_AS(PathInterpolator(cfg, src), doctest::Contains("P-AXIS-00236"),
                       std::invalid_argument);
  cfg.exact_stop = {ExactStop{0.01, -1.0}, ExactStop{}, ExactStop{}};
  CHECK_THROWS_WITH_AS(PathInterpolator(cfg, src), doctest::Contains("P-AXIS-00532"),
                       std::invalid_argument);
}

TEST_CASE("zero-length blocks: a program of only those finishes without motion") {
  const auto ax = axis(100.0, 1000.0, 1e5);
  std::vector<Item> items;
  for (int k = 0; k < 10000; ++k)
    items.emplace_back(line(vec(1, 1), vec(1, 1), 10.0, static_cast<std::uint32_t>(k + 1)));
  ListSource src(std::move(items));
  PathInterpolator ipo(config({ax, ax, ax}), src);
  int cycles = 0;
  while (ipo.step() == Status::running)
    ++cycles;
  CHECK(cycles <= 3);
  CHECK(ipo.step() == Status::finished);
}

}  // namespace
