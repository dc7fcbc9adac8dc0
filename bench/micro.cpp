// Google Benchmark micro-benchmarks of the hot building blocks.
#include <benchmark/benchmark.h>

#include "renderer/bsdf.h"
#include "renderer/displacement.h"
#include "renderer/sampler.h"
#include "renderer/tessellation.h"
#include "renderer/tree_surface.h"

using namespace phellem;

static void BM_SamplerGet4D(benchmark::State& state) {
  uint32_t i = 0;
  for (auto _ : state) {
    Sampler s(i & 1023, i >> 10, i, 7);
    benchmark::DoNotOptimize(s.get4d());
    ++i;
  }
}
BENCHMARK(BM_SamplerGet4D);

static void BM_SamplerGet4DSamePixel(benchmark::State& state) {
  uint32_t i = 0;
  const uint32_t seed = Sampler::hash_pixel(3, 4, 7);
  for (auto _ : state) {
    Sampler s(seed, i++);
    benchmark::DoNotOptimize(s.get4d());
    benchmark::DoNotOptimize(s.get4d());
    benchmark::DoNotOptimize(s.get4d());
  }
}
BENCHMARK(BM_SamplerGet4DSamePixel);

static void BM_BarkSample(benchmark::State& state) {
  BSDF b;
  b.type = BSDF::Type::Bark;
  b.alpha = 0.3f;
  const Vec3f wo = Vec3f(0.3f, 0.2f, 0.9f).normalized();
  float u = 0.1f;
  for (auto _ : state) {
    u = u + 0.618034f;
    u -= std::floor(u);
    benchmark::DoNotOptimize(b.sample(wo, u, Vec2f(u, 1 - u)));
  }
}
BENCHMARK(BM_BarkSample);

static void BM_DiceDisplacedTrunk(benchmark::State& state) {
  TreeDesc t;
  t.axis = {Vec3f(0, 0, 0), Vec3f(0, 2, 0)};
  t.radius = {0.3f, 0.2f};
  DisplacementDesc dd;
  dd.type = DisplacementDesc::Type::Grooves;
  dd.amplitude = 0.02f;
  const auto parts = build_tree(t, make_displacement(dd));
  DicingParams d;
  d.screen_space = false;
  d.target = 0.01f * float(state.range(0)) / 4.0f;
  long long tris = 0;
  for (auto _ : state) tris = dice(parts[0].surface, d).triangle_count();
  state.counters["triangles"] = double(tris);
  state.counters["tri/s"] = benchmark::Counter(double(tris), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_DiceDisplacedTrunk)->Arg(4)->Arg(2)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
