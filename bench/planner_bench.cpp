// Throughput of the planner (planner/lookahead.hpp, planner/prepare.hpp). Target on one core,
// Release: the look-ahead alone >= 1,000,000 segments/s at N = 120 (issue 12).
// The segments are prepared up front from a seeded program (dense lines and arcs, corners of
// all angles, no blends) so the timed loop of BM_LookAhead only pushes and pops the window:
// backward pass on push, forward pass on pop. Segments are moved in and out, as the channel
// loop will.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "planner/limits.hpp"
#include "planner/lookahead.hpp"
#include "planner/spline.hpp"

namespace {

using namespace ncsim::planner;
namespace jerk = ncsim::jerk;

std::array<AxisLimits, 3> limits() {
  AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = 500.0;
  ax.a_max = ax.d_max = 5000.0;
  ax.j_max = 1e5;
  return {ax, ax, ax};
}

std::vector<Move> program(std::size_t n, bool blends) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Move> moves;
  AxisVec p{};
  for (std::size_t k = 0; k < n; ++k) {
    Move m;
    m.start = p;
    m.slope = SlopeType::trapez;
    m.feed = 20.0 + 80.0 * u(rng);
    // Mostly short CAM-like steps with small direction changes, some long moves and arcs.
    const double len = u(rng) < 0.8 ? 0.05 + 0.5 * u(rng) : 5.0 + 20.0 * u(rng);
    const double dir = 6.283 * u(rng);
    m.end = p;
    m.end[0] += len * std::cos(dir);
    m.end[1] += len * std::sin(dir);
    if (k % 5 == 2) {
      const double r = 1.0 + 10.0 * u(rng);
      m.arc = Arc{0, 1, p[0] - r, p[1], u(rng) < 0.5, false};
      const double a1 = 2.0 * (u(rng) - 0.5);
      m.end[0] = m.arc->centre_1 + r * std::cos(a1);
      m.end[1] = m.arc->centre_2 + r * std::sin(a1);
    }
    if (blends) {
      m.contour = Contour::tolerance;
      m.path_dev = 0.01;
    }
    moves.push_back(m);
    p = m.end;
  }
  return moves;
}

std::vector<PreparedSegment> prepared(std::size_t n) {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  for (const Move& m : program(n, false))
    prep.push(m, out);
  prep.finish(out);
  return out;
}

// Pushes precomputed segments through a window of N = state.range(0); pops when full.
void BM_LookAhead(benchmark::State& state) {
  const auto segments = prepared(4096);
  const auto n = static_cast<std::size_t>(state.range(0));
  LookAhead window(n, 0.001);
  std::size_t i = 0;
  for (auto _ : state) {
    while (window.full())
      benchmark::DoNotOptimize(window.pop().v_exit);
    window.push(segments[i++ % segments.size()]);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LookAhead)->Arg(30)->Arg(120)->Arg(190);

// The pure profile of a planned segment (level search over the kernel's ramps).
void BM_Profile(benchmark::State& state) {
  const auto segments = prepared(4096);
  LookAhead window(120, 0.001);
  std::vector<PlannedSegment> planned;
  for (const auto& s : segments) {
    while (window.full())
      planned.push_back(window.pop());
    window.push(s);
  }
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(profile(planned[i++ % planned.size()]).time());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Profile);

// Preparation: geometry, path limits and joints (with and without tolerance balls).
void BM_Prepare(benchmark::State& state) {
  const auto moves = program(4096, state.range(0) != 0);
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  std::size_t i = 0;
  for (auto _ : state) {
    // Consecutive moves only (wrap: restart the stream so the chain stays joined).
    if (i % moves.size() == 0) {
      prep.finish(out);
      prep = Preparer(ax, ChannelLimits{});
    }
    prep.push(moves[i++ % moves.size()], out);
    out.clear();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Prepare)->Arg(0)->Arg(1);

// Spline pieces (Akima = 0, B-spline = 1) from a stream of CAM-like points 0.1 mm apart, with
// the path limits of each piece: what a #SPLINE section costs per point.
void BM_Spline(benchmark::State& state) {
  const auto type = state.range(0) == 0 ? SplineType::akima : SplineType::bspline;
  const auto ax = limits();
  SplineBuilder builder(type, 3, 0b111);
  Move m;
  m.feed = 100.0;
  m.slope = SlopeType::trapez;
  SplineVertex v;
  std::uint64_t k = 0;
  for (auto _ : state) {
    v.point[0] = 0.1 * static_cast<double>(k);
    v.point[1] = 2.0 * std::sin(0.013 * static_cast<double>(k));
    v.point[2] = 0.5 * std::cos(0.007 * static_cast<double>(k));
    ++k;
    for (const SplinePiece& p : builder.push(v))
      benchmark::DoNotOptimize(path_limits(p.curve, m, ax).v_max);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Spline)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
