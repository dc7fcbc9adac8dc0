#include "scene/growth_time.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/memory_estimate.h"

namespace phellem {

namespace {

// Measured with 2 threads (README, "Cambial growth"; docs/growth-performance-history.md): the
// tree close-up (10k → 28k interface vertices, 200 steps) takes 96 ms a step, about 5 µs per
// interface vertex and step, re-tetrahedralizations included; with its crack coupling (3
// stress iterations a step) 390 ms a step at 10k → 34k, about 13 µs more (more moves block
// among the crack points, and the cracking itself). TetGen's set-up took 1.5–2.3 s of it:
// about 200 µs per input vertex. A small surface adds little per step beyond its vertices: a
// log of 430 interface vertices took 9.2 ms a step while the close-up's first steps took 790 ms
// (61 µs per vertex, on a machine running about 7 times slower than the README's figures that
// day), so kPerStep is only a floor for the volume's own scans.
constexpr double kPerVertexStep = 5e-6;
constexpr double kCrackPerVertexStep = 13e-6;
constexpr double kSetupPerVertex = 2e-4;
constexpr double kPerStep = 2e-4;

}  // namespace

std::vector<GrowthTime> estimate_growth_times(const SceneDesc& desc) {
  std::vector<GrowthTime> out;
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& o = desc.objects[oi];
    if (!o.growth) continue;
    const GrowthInputSize in = growth_input_size(o);
    const GrowthSize end = estimate_growth_size(*o.growth, size_t(in.vertices), in.area, in.mean_edge);
    GrowthTime t;
    t.object = !o.name.empty() ? o.name : (o.type == ObjectType::Tree ? "tree" : "mesh") + std::to_string(oi);
    t.file = o.growth->where.file;
    t.where = o.growth->where.path + "/steps";
    t.steps = std::max(1, o.growth->settings.steps);
    // The interface grows with the area from the input's size to the end's (a mean of the two
    // over the steps: a fair middle for the Weibull curve's slow start and end).
    t.vertices = 0.5 * (in.vertices + std::max(in.vertices, end.interface_vertices));
    const bool cracks = o.stress_bark && o.growth->cracks;
    const double per_vertex = kPerVertexStep + (cracks ? kCrackPerVertexStep : 0.0);
    t.seconds = kSetupPerVertex * in.vertices + double(t.steps) * (kPerStep + per_vertex * t.vertices);
    out.push_back(t);
  }
  return out;
}

std::string human_duration(double seconds) {
  if (!(seconds < 1e12)) return "forever";
  const long long s = std::llround(std::max(seconds, 1.0));
  const long long m = (s + 30) / 60, h = (m + 30) / 60;  // rounded minutes and hours
  char out[48];
  if (s < 60)
    std::snprintf(out, sizeof out, "%lld s", s);
  else if (m < 60)
    std::snprintf(out, sizeof out, "%lld min", m);
  else if (m < 48 * 60 && m % 60 != 0)
    std::snprintf(out, sizeof out, "%lld h %lld min", m / 60, m % 60);
  else if (m < 48 * 60)
    std::snprintf(out, sizeof out, "%lld h", m / 60);
  else if (h % 24 != 0)
    std::snprintf(out, sizeof out, "%lld d %lld h", h / 24, h % 24);
  else
    std::snprintf(out, sizeof out, "%lld d", h / 24);
  return out;
}

}  // namespace phellem
