// Growth quality at large ratios (issue 24): a jittered log grown to about twice its radius
// with uniform speed should stay a log of radius R0 + thickening. Prints, per step, the moves
// that were shortened or clamped, and at the end the radial error of the interface on the
// log's middle section (mean, standard deviation, worst lag and lead) and how far interface
// normals turn from the radial direction there.
//   build/bench/phellem_bench_growth_quality [triangles-around] [steps] [growth-ratio] [remesh-blocked] [jitter-seed]
// The jitter seed (default 7) draws another log of the same size: bench/run_growth_quality.sh
// runs several and reports the worst.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/cambial_growth.h"

using namespace phellem;
using namespace phellem::bark;

int main(int argc, char** argv) {
  const int around = argc > 1 ? std::atoi(argv[1]) : 60;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 40;
  const double ratio = argc > 3 ? std::atof(argv[3]) : 2.0;
  // "-" (or nothing) for remesh-blocked: the library's default.
  const double remesh = argc > 4 && std::string(argv[4]) != "-" ? std::atof(argv[4]) : CambialGrowthSettings{}.remesh_blocked;
  const uint64_t seed = argc > 5 ? std::strtoull(argv[5], nullptr, 10) : 7;
  const double r0 = 0.08, height = 0.4;
  const int along = int(std::lround(around * height / (2 * M_PI * r0)));
  const TriMesh log = log_mesh(r0, height, around, along, 0.2, seed);
  CambialGrowthSettings s;
  s.function.weibull_c = 1;
  // Nearly uniform speed: ages 0..1 of a scale of 10 (the speed drops by 10 % over the run).
  s.function.age_scale = 10;
  s.function.thickness = float((ratio - 1) * r0 / (1 - std::exp(-0.1)));
  s.age_start = 0;
  s.age_end = 1;
  s.steps = steps;
  s.ring_interval = 0;
  s.remesh_blocked = remesh;
  CambialGrowth g(log, {}, s, "bench", "/log");
  std::printf("%zu interface vertices, band [%.4f, %.4f] m\n", g.stats().vertices_start, g.settings().edge_min,
              g.settings().edge_max);
  long shortened = 0, clamped = 0;
  while (g.step()) {
    const auto& st = g.stats();
    std::printf("step %3d: %6zu vertices, %5ld shortened, %5ld clamped, %ld remeshes\n", g.steps_done(), st.vertices_end,
                st.shortened - shortened, st.clamped - clamped, st.remeshes);
    shortened = st.shortened;
    clamped = st.clamped;
  }
  const double r = r0 + s.function.cumulative(s.age_end);
  const GrowthSurface surf = extract_interface(g.complex());
  const TriMesh& m = surf.mesh;
  std::vector<Eigen::Vector3d> n(m.positions.size(), Eigen::Vector3d::Zero());
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d a = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    for (uint32_t v : t) n[v] += a;
  }
  double sum = 0, sum2 = 0, lag = 0, lead = 0, turn = 0;
  long k = 0;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const Eigen::Vector3d& p = m.positions[i];
    if (p.y() < 0.3 * height || p.y() > 0.7 * height) continue;
    const double e = std::hypot(p.x(), p.z()) - r;
    sum += e;
    sum2 += e * e;
    lag = std::min(lag, e);
    lead = std::max(lead, e);
    const Eigen::Vector3d radial = Eigen::Vector3d(p.x(), 0, p.z()).normalized();
    turn = std::max(turn, std::acos(std::clamp(n[i].normalized().dot(radial), -1.0, 1.0)));
    ++k;
  }
  const double mean = sum / double(k);
  std::printf("radius %.4f m: middle section %ld vertices, error mean %+.5f sd %.5f, worst lag %.5f lead %.5f m, "
              "worst normal turn %.1f deg; %ld shortened, %ld clamped; %.2f s steps, %ld remeshes (%ld refused) %.2f s\n",
              r, k, mean, std::sqrt(std::max(0.0, sum2 / double(k) - mean * mean)), -lag, lead, turn * 180 / M_PI,
              g.stats().shortened, g.stats().clamped, g.stats().steps_s, g.stats().remeshes, g.stats().remesh_refused, g.stats().remesh_s);
}
