// Speed of the fissure statistics (issue 22): analyse two synthetic fields (random V-fissures
// plus noise, tests/compare/synthetic_fields) and compare them, at 1024² and 4096².
//   phellem_bench_compare_stats --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// analyse_one times a single field (what `phellem fit` does per evaluation); its CPU column is
// the process's (all threads), the wall time is what the load of the machine leaves of it.
#include <benchmark/benchmark.h>

#include "compare/compare_score.h"
#include "tests/compare/synthetic_fields.h"

namespace {

using namespace phellem;

void analyse_and_compare(benchmark::State& state) {
  const int n = int(state.range(0));
  // 260 fissures per 1024² (the plan's two-scale test), as many per area at 4096².
  const int count = 260 * (n / 1024) * (n / 1024);
  const HeightField a = test::v_fissures(n, 10, count, 5), b = test::v_fissures(n, 10, count, 6);
  for (auto _ : state) {
    const FissureAnalysis fa = analyse_fissures(a, nullptr, "a"), fb = analyse_fissures(b, nullptr, "b");
    benchmark::DoNotOptimize(compare_fissures(fa.stats, fb.stats).score);
  }
  state.counters["fields/s"] = benchmark::Counter(2.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(analyse_and_compare)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime();

// One field, as `phellem fit` analyses one candidate per evaluation: {size px, px/cm}.
void analyse_one(benchmark::State& state) {
  const int n = int(state.range(0));
  const double s = double(state.range(1));
  const HeightField a = test::v_fissures(n, s, int(260.0 * n * n / (1024.0 * 1024.0)), 5);
  for (auto _ : state) benchmark::DoNotOptimize(analyse_fissures(a, nullptr, "a").stats.vertical_fraction);
}
BENCHMARK(analyse_one)
    ->Args({1024, 10})
    ->Args({512, 5})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();  // CPU: all threads of the process

}  // namespace

BENCHMARK_MAIN();
