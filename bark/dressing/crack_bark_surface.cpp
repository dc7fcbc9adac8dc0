#include "bark/dressing/crack_bark_surface.h"

namespace phellem::bark {

CrackBarkSurface::CrackBarkSurface(const CrackedMesh& mesh, const CrackLook& look, uint32_t seed)
    : profile_(mesh, look, seed),
      look_(look),
      ridge_tints_(look.ridge_tints),
      fissure_tints_(look.fissure_tints),
      plates_(look.tint_size, seed ^ 0x1b873593u) {}

BarkDisplacement CrackBarkSurface::displace(const SurfacePoint& p) const {
  const CrackProfile::Sample s = profile_.at(p.position, p.normal);
  BarkDisplacement d;
  d.offset = -s.depth;
  d.attributes = Eigen::Vector4f(s.relative, s.mask, s.chain, 0);
  return d;
}

BarkShade CrackBarkSurface::shade(const Eigen::Vector4f& a, const Eigen::Vector3f& position) const {
  BarkShade s;
  s.depth = a.x();
  s.mask = a.y();
  s.albedo_scale = 1.0f - look_.darkening * a.x();
  const float chain = a.z();
  const bool plated = !ridge_tints_.empty() || (look_.roughness.enabled() && look_.roughness.noise > 0);
  const TintPlates::Pick plate = plated ? plates_.at(position) : TintPlates::Pick{};
  if (look_.roughness.enabled()) {
    // The roughness varies with the plates and the cracks (their coordinates, uniform on [0, 1)).
    const float ridge_n = plate.blend([](float c) { return c; });
    const float n = look_.roughness.noise > 0 ? 2 * (ridge_n + s.mask * (chain - ridge_n)) - 1 : 0.0f;
    s.roughness = look_.roughness.at(s.mask, n);
  }
  const Eigen::Vector3f ridge_tint = plate.blend([&](float c) { return ridge_tints_.pick(c); });
  const Eigen::Vector3f fissure_tint = fissure_tints_.at(chain);
  if (look_.colored) {
    const Eigen::Vector3f ridge = look_.ridge_color.cwiseProduct(ridge_tint);
    const Eigen::Vector3f fissure = look_.fissure_color.cwiseProduct(fissure_tint);
    s.replaces_albedo = true;
    s.albedo = (ridge + s.mask * (fissure - ridge)) * s.albedo_scale;
    s.albedo_scale = 1.0f;
  } else {
    s.tint = ridge_tint + s.mask * (fissure_tint - ridge_tint);
  }
  return s;
}

}  // namespace phellem::bark
