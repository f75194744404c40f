// Throughput of the PTP setpoint generator (axes/profile.hpp) and the jerk kernel. Targets on
// one core, Release (issue 11): >= 6e6 rest-to-rest plans/s, >= 3e6 plans/s from arbitrary
// start states, at(t) < 5 ns. Figures: docs/benchmarks.md.
// Inputs are drawn up front from a seeded generator so the timed loop only plans.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <vector>

#include "axes/profile.hpp"
#include "bench/axes_inputs.hpp"

namespace {

using ncsim::axes::Dynamics;
using ncsim::axes::MotionState;
using ncsim::axes::PositionTarget;
using ncsim::axes::Profile;
using ncsim::axes::ProfileRule;

using Input = ncsim::bench::AxesInput;

std::vector<Input> make_inputs(bool moving, std::size_t n) {
  return ncsim::bench::make_axes_inputs(moving, n);
}

// Plans 4096 precomputed requests in turn; the argument selects rest-to-rest (0) or moving
// starts with velocity, acceleration and arrival velocities (1).
void plan_benchmark(benchmark::State& state, bool moving, ProfileRule rule = ProfileRule::manual) {
  const auto inputs = make_inputs(moving, 4096);
  Profile p;
  std::size_t i = 0;
  for (auto _ : state) {
    const Input& in = inputs[i++ & 4095];
    benchmark::DoNotOptimize(ncsim::axes::plan_position(in.start, in.target, in.dyn, p, rule));
    benchmark::DoNotOptimize(p.duration());
  }
  state.SetItemsProcessed(state.iterations());
}
void BM_PlanRestToRest(benchmark::State& state) {
  plan_benchmark(state, false);
}
void BM_PlanFromState(benchmark::State& state) {
  plan_benchmark(state, true);
}
void BM_PlanRestToRestTimeOptimal(benchmark::State& state) {
  plan_benchmark(state, false, ProfileRule::time_optimal);
}
void BM_PlanFromStateTimeOptimal(benchmark::State& state) {
  plan_benchmark(state, true, ProfileRule::time_optimal);
}
BENCHMARK(BM_PlanRestToRest);
BENCHMARK(BM_PlanFromState);
BENCHMARK(BM_PlanRestToRestTimeOptimal);
BENCHMARK(BM_PlanFromStateTimeOptimal);

// Three axes synchronised to the slowest (catch-up "all axes at once").
void BM_PlanSynchronized3(benchmark::State& state) {
  const auto inputs = make_inputs(false, 4098);
  std::array<Profile, 3> p;
  std::size_t i = 0;
  for (auto _ : state) {
    std::array<MotionState, 3> s;
    std::array<PositionTarget, 3> t;
    std::array<Dynamics, 3> d;
    for (std::size_t k = 0; k < 3; ++k) {
      const Input& in = inputs[(i + k) % 4098];
      s[k] = in.start;
      t[k] = in.target;
      d[k] = in.dyn;
    }
    i += 3;
    benchmark::DoNotOptimize(ncsim::axes::plan_synchronized(s, t, d, ProfileRule::manual, 0.0, p));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PlanSynchronized3);

// A target moving with the belt: earliest meeting (a bisection over plans).
void BM_PlanMovingTarget(benchmark::State& state) {
  const auto inputs = make_inputs(true, 4096);
  Profile p;
  std::size_t i = 0;
  double t_meet = 0.0;
  for (auto _ : state) {
    const Input& in = inputs[i++ & 4095];
    benchmark::DoNotOptimize(ncsim::axes::plan_moving_target(
        in.start, in.target.p, 0.3 * in.dyn.v_max, in.dyn, p, t_meet));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PlanMovingTarget);

// The planner's forward-pass primitive.
void BM_ReachableVelocity(benchmark::State& state) {
  const auto inputs = make_inputs(true, 4096);
  std::size_t i = 0;
  for (auto _ : state) {
    const Input& in = inputs[i++ & 4095];
    benchmark::DoNotOptimize(ncsim::jerk::reachable_velocity(
        std::abs(in.start.v), 0.0, std::abs(in.target.p), in.dyn.a_max, in.dyn.j_max));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ReachableVelocity);

void BM_ProfileAt(benchmark::State& state) {
  Profile p;
  ncsim::axes::plan_position(MotionState{}, PositionTarget{1000.0, 0.0},
                             Dynamics{2000.0, 5000.0, 5000.0, 50000.0}, p);
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(p.at(t));
    t += 1e-3;
    if (t > p.duration()) t = 0.0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ProfileAt);

}  // namespace

BENCHMARK_MAIN();
