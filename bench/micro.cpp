// Google Benchmark micro-benchmarks of the hot building blocks.
#include <benchmark/benchmark.h>

#include <vector>

#include "bark/geometry/tessellation.h"
#include "bark/strips/strip_equilibrium.h"
#include "renderer/bsdf.h"
#include "renderer/sampler.h"
#include "scene/displacement.h"
#include "scene/tree_surface.h"

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

// A cyclic strip like those of the benchmark trunk at the end of its growth: 178 elements,
// a third of them fractures, attached to the substrate.
static bark::Strip benchmark_strip() {
  bark::Strip s;
  s.cyclic = true;
  s.circumference = 0.94;
  const int n = 178;
  for (int i = 0; i < n; ++i) {
    bark::Element e;
    e.kind = i % 3 == 1 ? bark::ElementKind::Fracture : bark::ElementKind::Epidermis;
    e.rest = 0.005;
    e.stiffness = e.kind == bark::ElementKind::Fracture ? 0.3 : 2.0;
    s.elements.push_back(e);
    s.x.push_back(i * s.circumference / n);
  }
  s.anchor = s.x;
  s.attach.assign(size_t(n), 0.1);
  return s;
}

// Equilibrium of one strip per iteration (items = elements). Arg 0: eliminate every time;
// arg 1: reuse the factor (the model's case between breaks). The anchors move a little each
// time, as growth moves them.
static void BM_StripSolve(benchmark::State& state) {
  bark::Strip s = benchmark_strip();
  bark::EquilibriumFactor f;
  size_t k = 0;
  for (auto _ : state) {
    s.anchor[k++ % s.anchor.size()] += 1e-9;
    bark::solve_equilibrium(s, state.range(0) ? &f : nullptr);
    benchmark::DoNotOptimize(s.x.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.size()));
}
BENCHMARK(BM_StripSolve)->Arg(0)->Arg(1);

// The same over N strips in turn (arg; 14 KB each: elements, positions, anchors and factor),
// the way one step of the benchmark trunk (1000 strips) touches them all: the cost per strip
// as the strips outgrow the caches (on the development VM: 0.8–1.1 µs up to 600 strips,
// 8.5 MB, then 1.8 µs at 800 and 1.9 µs at 1000).
static void BM_StripSolveManyStrips(benchmark::State& state) {
  std::vector<bark::Strip> strips(size_t(state.range(0)), benchmark_strip());
  std::vector<bark::EquilibriumFactor> f(strips.size());
  size_t k = 0;
  for (auto _ : state) {
    bark::Strip& s = strips[k % strips.size()];
    for (double& a : s.anchor) a *= 1.0000001;
    bark::solve_equilibrium(s, &f[k % strips.size()]);
    benchmark::DoNotOptimize(s.x.data());
    ++k;
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * 178);
}
BENCHMARK(BM_StripSolveManyStrips)->Arg(100)->Arg(300)->Arg(500)->Arg(600)->Arg(800)->Arg(1000)->Arg(2000);

BENCHMARK_MAIN();
