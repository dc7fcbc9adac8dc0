#include "compare/strip_patch.h"

#include <cmath>
#include <stdexcept>

#include "bark/strips/strip_domain.h"
#include "bark/strips/strip_model.h"

namespace phellem {

namespace {
int margin_px(const PatchSize& size) { return int(std::ceil(kStripPatchMarginM * 100 * size.px_per_cm)); }
}  // namespace

bark::FractureField strip_patch_field(const StripPatchParams& in, const PatchSize& size, uint64_t seed) {
  bark::StripParams p = in.params;
  p.tile_theta = p.tile_s = false;
  p.seed = seed;
  const int margin = margin_px(size);
  const int W = size.width + 2 * margin, H = size.height + 2 * margin;
  const double m_per_px = 1.0 / (100 * size.px_per_cm);
  bark::StripModel model(bark::flat_domain(W * m_per_px, H * m_per_px, p), p);
  while (model.steps_done() < model.steps_total()) model.step();
  model.settle();
  return bark::rasterize(model, W, H, in.depth);
}

HeightField strip_patch_heights(bark::FractureField f, const StripPatchParams& in, const PatchSize& size, uint64_t seed) {
  const int margin = margin_px(size);
  const int H = size.height + 2 * margin;
  if (f.width != size.width + 2 * margin || f.height != H) throw std::logic_error("strip_patch_heights: field of another size");
  if (in.relief.enabled) {
    bark::ReliefLook look = in.relief;
    look.seed = uint32_t(seed ^ (seed >> 32));
    bark::apply_relief(f, look, in.depth);
  }
  HeightField out;
  out.width = size.width;
  out.height = size.height;
  out.px_per_cm = size.px_per_cm;
  out.z.resize(size_t(size.width) * size_t(size.height));
  // The field's row 0 is s = 0 (the bottom); the height field's row 0 is the top.
  for (int y = 0; y < size.height; ++y) {
    const int fy = H - 1 - (y + margin);
    for (int x = 0; x < size.width; ++x) out.z[size_t(y) * size.width + x] = -f.depth[f.index(x + margin, fy)];
  }
  return out;
}

HeightField strip_patch(const StripPatchParams& in, const PatchSize& size, uint64_t seed) {
  return strip_patch_heights(strip_patch_field(in, size, seed), in, size, seed);
}

}  // namespace phellem
