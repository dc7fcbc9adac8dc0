// Fracture ends along the trunk of scenes/strips_fissured.json: a horizontal seam in the bark
// (a height where fractures stop and start again) shows as a run of strips holding many more
// free fracture ends than the rest. Prints the densest 3-strip run against the median run.
//
//   build/bench/phellem_bench_strip_ends [PRESET [SEED [STEPS]]]     (ENDS_TRACE=1: breaks per step)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "bark/geometry/generalized_cylinder.h"
#include "bark/strips/fracture_ends.h"
#include "bark/strips/presets.h"
#include "bark/strips/strip_domain.h"

using namespace phellem::bark;

int main(int argc, char** argv) {
  const std::string preset = argc > 1 ? argv[1] : "fissured";
  const std::optional<StripParams> found = strip_preset(preset);
  if (!found) {
    std::fprintf(stderr, "phellem_bench_strip_ends: error: no preset '%s'\n", preset.c_str());
    return 2;
  }
  StripParams p = *found;
  if (argc > 2) p.seed = std::strtoull(argv[2], nullptr, 10);
  if (argc > 3) p.steps = std::atoi(argv[3]);
  const GeneralizedCylinder trunk({{0, -0.05, 0}, {0.02, 1.0, 0.01}, {0.0, 2.0, 0.02}}, {0.3, 0.24, 0.2});
  StripModel m(oriented_domain(trunk, p), p);
  const bool trace = std::getenv("ENDS_TRACE") != nullptr;
  long long created = 0;
  const auto t0 = std::chrono::steady_clock::now();
  while (m.steps_done() < m.steps_total()) {
    m.step();
    if (trace && m.stats().created != created)
      std::printf("to step %d: %lld new fractures\n", m.steps_done(), m.stats().created - created);
    created = m.stats().created;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::vector<int> ends = fracture_ends_per_strip(m);
  long total = 0;
  for (int e : ends) total += e;
  const EndsPeak peak = ends_peak(ends);
  std::printf(
      "%s seed %llu: %zu strips, %d steps in %.2f s, %lld fractures, %ld free ends; 3-strip runs: median %.0f, densest %d (strip "
      "%zu)\n",
      preset.c_str(), (unsigned long long)p.seed, ends.size(), m.steps_done(), seconds, m.stats().created, total, peak.median,
      peak.peak, peak.strip);
}
