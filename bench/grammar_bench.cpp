// grammar_bench: throughput of the syntax check (grammar::check_program) on the generated
// benchmark program, in blocks per second (Google Benchmark items/s). Target (docs/benchmarks.md):
// >= 2,000,000 blocks/s, Release build, one core.
//
// The program is generated in memory once per benchmark, outside the timed loop; each
// iteration checks the whole file. A program that is not clean would measure the error path,
// so the benchmark fails (SkipWithError) if check_program reports anything.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "bench/grammar_generator.hpp"
#include "core/source_file.hpp"
#include "grammar/check.hpp"

namespace {

void BM_CheckGeneratedProgram(benchmark::State& state) {
  const auto blocks = static_cast<std::uint64_t>(state.range(0));
  const ncsim::core::SourceFile file(
      "bench.nc", ncsim::bench::generate_program(ncsim::bench::Dialect::isg, {blocks, 1}));
  const auto first = ncsim::grammar::check_program(file);
  if (!first.items().empty()) {
    state.SkipWithError(
        ("generated program has diagnostics, first: " + first.items().front().message).c_str());
    return;
  }
  for (auto _ : state) {
    auto diagnostics = ncsim::grammar::check_program(file);
    benchmark::DoNotOptimize(diagnostics);
  }
  // Every line is one block: prologue, body and epilogue.
  const auto total_blocks =
      static_cast<std::int64_t>(std::count(file.text().begin(), file.text().end(), '\n'));
  state.SetItemsProcessed(state.iterations() * total_blocks);
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(file.text().size()));
  state.counters["blocks"] = static_cast<double>(total_blocks);
}

}  // namespace

BENCHMARK(BM_CheckGeneratedProgram)->Arg(10'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
