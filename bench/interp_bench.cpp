// interp_bench: interpreter throughput.
//   BM_InterpretProgram - a generated 1,000,000-block program (bench/grammar_generator: G0/G1/
//                         G2/G3 with I/J, F, comments, block numbers, expressions) decoded to
//                         its command stream; counter blocks/s (target >= 1,000,000).
//   BM_ForLoop          - `$FOR` with 10,000,000 passes of two arithmetic assignments;
//                         counter iterations/s (target >= 5,000,000).
// Both report the interpreter's container sizes at the end (memory flat: they do not grow
// with the number of blocks decoded beyond the 12-byte block index).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

#include "bench/grammar_generator.hpp"
#include "interp/interpreter.hpp"
#include "machines/loader.hpp"

namespace {

using namespace ncsim;

machines::Machine load() {
  const char* env = std::getenv("NCSIM_SOURCE_DIR");
  const std::filesystem::path root = env != nullptr ? env : NCSIM_SOURCE_ROOT;
  auto r = machines::load_machine(machines::bundled_machine_dir(root, "portal_3x"));
  if (!r.machine) std::abort();
  return std::move(*r.machine);
}

void BM_InterpretProgram(benchmark::State& state) {
  const auto blocks = static_cast<std::uint64_t>(state.range(0));
  const machines::Machine machine = load();
  const core::SourceFile file("bench.nc",
                              bench::generate_program(bench::Dialect::isg, {blocks, 1}));
  std::uint64_t commands = 0;
  for (auto _ : state) {
    interp::Options options;
    interp::Interpreter interp(file, machine, options);
    while (auto c = interp.next_decode_only())
      ++commands;
    if (interp.error() != nullptr) state.SkipWithError(interp.error()->message.c_str());
    state.counters["indexed_blocks"] = static_cast<double>(interp.footprint().indexed_blocks);
  }
  state.counters["blocks/s"] =
      benchmark::Counter(static_cast<double>(blocks) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
  state.counters["commands"] = static_cast<double>(commands / state.iterations());
}
BENCHMARK(BM_InterpretProgram)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_ForLoop(benchmark::State& state) {
  const auto passes = state.range(0);
  const machines::Machine machine = load();
  const core::SourceFile file("loop.nc", "%loop\nP2 = 0\nP3 = 1\n$FOR P1 = 1, " +
                                             std::to_string(passes) +
                                             ", 1\nP2 = P2 + P1 * 0.5\nP3 = [P3 + 1] / 2\n"
                                             "$ENDFOR\nG00 X[P3]\nM30\n");
  for (auto _ : state) {
    interp::Options options;
    options.max_blocks_without_motion = 0;
    interp::Interpreter interp(file, machine, options);
    while (auto c = interp.next_decode_only())
      benchmark::DoNotOptimize(c);
    if (interp.error() != nullptr) state.SkipWithError(interp.error()->message.c_str());
    state.counters["control_frames"] = static_cast<double>(interp.footprint().control_frames);
  }
  state.counters["iterations/s"] =
      benchmark::Counter(static_cast<double>(passes) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ForLoop)->Arg(10000000)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
