#include "compare/stress_patch.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "bark/geometry/irregular_remesh.h"
#include "bark/geometry/procedural_meshes.h"
#include "bark/stress/stress_cracker.h"
#include "bark/stress/stress_mesh.h"

namespace phellem {

HeightField stress_patch(const StressPatchParams& in, const PatchSize& size, uint64_t seed) {
  const double margin = kStressPatchMarginM;
  const double w = size.width_m() + 2 * margin, h = size.height_m() + 2 * margin;
  // The sheet at about the target edge length, then remeshed irregularly (sec. 3.1.4).
  const int nx = std::max(2, int(std::lround(w / in.edge_length))), ny = std::max(2, int(std::lround(h / in.edge_length)));
  bark::TriMesh sheet = bark::jittered_sheet(nx, ny, w, h, in.jitter, seed);
  bark::RemeshOptions ro;
  ro.edge_length = in.edge_length;
  ro.jitter = in.jitter;
  ro.seed = seed;
  sheet = bark::irregular_remesh(sheet, ro);
  bark::StressParams p = in.params;
  p.seed = seed;
  bark::StressCracker cracker(bark::StressMesh::from(sheet), p);
  cracker.run();
  const CrackProfile profile(cracker.result(), in.look, uint32_t(seed));
  HeightField out;
  out.width = size.width;
  out.height = size.height;
  out.px_per_cm = size.px_per_cm;
  out.z.resize(size_t(size.width) * size_t(size.height));
  const double m_per_px = 1.0 / (100 * size.px_per_cm);
  const Vec3f n(0, 0, 1);
  // Row 0 is the top of the sheet (+Y up).
  tbb::parallel_for(0, size.height, [&](int y) {
    const double py = h - margin - (y + 0.5) * m_per_px;
    for (int x = 0; x < size.width; ++x) {
      const Vec3f q(float(margin + (x + 0.5) * m_per_px), float(py), 0.0f);
      out.z[size_t(y) * size.width + x] = -profile.at(q, n).depth;
    }
  });
  return out;
}

}  // namespace phellem
