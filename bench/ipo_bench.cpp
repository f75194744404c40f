// Interpolator throughput, as simulated seconds per wall-clock second ("x real time"):
//  - BM_TimeLinesArcs: `time` (Detail::path, no sink) on the seeded 200-move line/arc program
//    of issue 12 (V = 100 mm/s, A = 1000 mm/s^2, J = 1e5 mm/s^3, feeds 20-50 mm/s, VELOJUMP
//    corners), T = 1 ms; target >= 2,000x.
//  - BM_TimeDense: 0.1 mm chords of a smooth curve at F = 6000 mm/min (100 mm/s), T = 1 ms,
//    with and without tolerance balls (0.01 mm); target >= 500x.
//  - BM_RunAudit: the stepping loop with points, axis values and the audit sink (for scale).
// Deterministic programs (seeded); the wall clock is Google Benchmark's.

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "audit/audit.hpp"
#include "audit/time.hpp"
#include "bench/move200.hpp"
#include "ipo/interpolator.hpp"

namespace {

using namespace ncsim;
using ipo::Item;

class ListSource final : public ipo::Source {
 public:
  explicit ListSource(const std::vector<Item>& items) : items_(items) {}
  bool next(Item& out) override {
    if (next_ >= items_.size()) return false;
    out = items_[next_++];
    return true;
  }

 private:
  const std::vector<Item>& items_;
  std::size_t next_ = 0;
};

planner::AxisLimits axis(double v, double a, double j) {
  planner::AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = v;
  ax.a_max = ax.d_max = a;
  ax.j_max = j;
  return ax;
}

std::vector<Item> lines_arcs() {
  std::vector<Item> items;
  for (const planner::Move& m : bench::move200())
    items.emplace_back(m);
  return items;
}

/// 0.1 mm chords along a wavy curve (radius of curvature >= 20 mm), 20,000 segments.
std::vector<Item> dense(bool balls) {
  std::vector<Item> items;
  planner::AxisVec p{};
  double dir = 0.0;
  for (int k = 0; k < 20000; ++k) {
    planner::Move m;
    m.start = p;
    dir += 0.1 / 20.0 * std::sin(k * 0.002);
    p[0] += 0.1 * std::cos(dir);
    p[1] += 0.1 * std::sin(dir);
    m.end = p;
    m.feed = 100.0;  // 6000 mm/min
    m.slope = planner::SlopeType::trapez;
    m.line = static_cast<std::uint32_t>(k + 1);
    if (balls) {
      m.contour = planner::Contour::tolerance;
      m.path_dev = 0.01;
    }
    items.emplace_back(m);
  }
  return items;
}

ipo::Config config(double v, double a, double j) {
  ipo::Config c;
  c.axes = {axis(v, a, j), axis(v, a, j), axis(v, a, j)};
  c.channel.t_cycle = 0.001;
  return c;
}

void run_time(benchmark::State& state, const std::vector<Item>& items, const ipo::Config& cfg) {
  double simulated = 0.0;
  for (auto _ : state) {
    ListSource src(items);
    const audit::TimeResult r = audit::machining_time(cfg, src);
    benchmark::DoNotOptimize(r.cycles);
    simulated += r.total;
  }
  state.counters["x_real_time"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["program_s"] = simulated / static_cast<double>(state.iterations());
}

void BM_TimeLinesArcs(benchmark::State& state) {
  static const std::vector<Item> items = lines_arcs();
  run_time(state, items, config(100.0, 1000.0, 1e5));
}
BENCHMARK(BM_TimeLinesArcs)->Unit(benchmark::kMillisecond);

void BM_TimeDense(benchmark::State& state) {
  static const std::vector<Item> plain = dense(false);
  static const std::vector<Item> balls = dense(true);
  run_time(state, state.range(0) ? balls : plain, config(200.0, 2000.0, 1e5));
}
BENCHMARK(BM_TimeDense)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_RunAudit(benchmark::State& state) {
  static const std::vector<Item> items = lines_arcs();
  const ipo::Config cfg = config(100.0, 1000.0, 1e5);
  double simulated = 0.0;
  for (auto _ : state) {
    ListSource src(items);
    audit::Audit audit(cfg.axes, cfg.channel.t_cycle, cfg.start);
    ipo::PathInterpolator interp(cfg, src, &audit);
    while (interp.step() == ipo::Status::running) {
    }
    simulated += interp.cycle().t;
    benchmark::DoNotOptimize(audit.verdict().ok());
  }
  state.counters["x_real_time"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RunAudit)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
