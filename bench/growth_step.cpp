// Google Benchmark of one cambial growth step (issue 24): advance_interface (Eq. 1 with the
// DSC's retessellation of blocked moves and the smoothing) + growth_repair_step (splits,
// collapses, quality flips) on icospheres of 2.6k, 10k and 41k interface vertices, each step
// thickening by a fifth of an edge. Target: ≤ 16 ms a step at 10k–39k vertices.
//   build/bench/phellem_bench_growth_step --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/complex_repair.h"
#include "bark/growth/interface_motion.h"
#include "bark/growth/interface_refinement.h"

using namespace phellem;
using namespace phellem::bark;

static void BM_GrowthStep(benchmark::State& state) {
  const TetComplex start = tetrahedralize_surface(icosphere(int(state.range(0)), 0.5), TetSettings{}, "bench", "/0");
  double band_max = 0, mean = 0;
  const auto edges = interface_edges(start);
  for (const auto& e : edges) {
    const double l = (start.points[e[0]] - start.points[e[1]]).norm();
    band_max = std::max(band_max, l);
    mean += l / double(edges.size());
  }
  GrowthFunction g;
  g.weibull_c = 1;
  g.thickness = float(0.2 * mean / 0.01);  // c = 1: over t ∈ [k·0.01, (k+1)·0.01] about 0.2 edge
  TetComplex c = start;
  int k = 0;
  long interface_vertices = 0;
  for (auto _ : state) {
    advance_interface(c, g, 0.01 * k, 0.01 * (k + 1));
    growth_repair_step(c, 0.4 * band_max, band_max);
    ++k;
  }
  for (uint8_t f : c.on_interface) interface_vertices += f;
  state.counters["interface_vertices"] = double(interface_vertices);
  state.counters["tets"] = double(c.tets.size());
}
BENCHMARK(BM_GrowthStep)->Arg(4)->Arg(5)->Arg(6)->Iterations(3)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
