// The cost of one `phellem fit` evaluation: a simulated patch at the photo's size and scale
// (strips: fissured preset as the fit starts it; stress: the pine start), by size and scale.
//   build/bench/phellem_bench_fit_eval --benchmark_filter=Strip
#include <benchmark/benchmark.h>

#include "compare/fit_parameters.h"

using namespace phellem;

static void run(benchmark::State& state, FitModel model) {
  const FitSpace space = fit_space(model);
  const FitCandidate c = space.candidate(space.starts[0]);
  const PatchSize size{int(state.range(0)), int(state.range(0)), double(state.range(1))};
  uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(simulate_candidate(c, size, seed++));
  state.counters["cm"] = size.width / size.px_per_cm;
}

static void BM_StripPatch(benchmark::State& state) { run(state, FitModel::strips); }
BENCHMARK(BM_StripPatch)->Args({1024, 10})->Args({512, 5})->Args({512, 10})->Unit(benchmark::kMillisecond)->Iterations(3);

// The relief dressing alone on a simulated 512² field at 5 px/cm (with its margin): the
// shoulder and walls of a geometry evaluation (detail 0), and with fbm detail.
static void BM_Relief(benchmark::State& state) {
  const FitSpace space = strip_fit_space();
  FitCandidate c = space.candidate(space.starts[0]);
  c.strips.relief.depth_ratio = 1.5;
  c.strips.relief.wall_noise = 0.15;
  c.strips.relief.detail = double(state.range(0)) / 10;
  const PatchSize size{512, 512, 5.0};
  const bark::FractureField f = strip_patch_field(c.strips, size, 3);
  for (auto _ : state) benchmark::DoNotOptimize(strip_patch_heights(f, c.strips, size, 3));
}
BENCHMARK(BM_Relief)->Arg(0)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(5);

static void BM_StressPatch(benchmark::State& state) { run(state, FitModel::stress); }
BENCHMARK(BM_StressPatch)->Args({1024, 10})->Args({512, 5})->Unit(benchmark::kMillisecond)->Iterations(2);

BENCHMARK_MAIN();
