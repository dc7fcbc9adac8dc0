#include "bark/dressing/crack_bark_surface.h"

namespace phellem::bark {

CrackBarkSurface::CrackBarkSurface(const CrackedMesh& mesh, const CrackLook& look, uint32_t seed)
    : profile_(mesh, look, seed), look_(look) {}

BarkDisplacement CrackBarkSurface::displace(const SurfacePoint& p) const {
  const CrackProfile::Sample s = profile_.at(p.position, p.normal);
  BarkDisplacement d;
  d.offset = -s.depth;
  d.attributes = Eigen::Vector2f(s.relative, s.mask);
  return d;
}

BarkShade CrackBarkSurface::shade(const Eigen::Vector2f& attributes) const {
  BarkShade s;
  s.depth = attributes.x();
  s.mask = attributes.y();
  s.albedo_scale = 1.0f - look_.darkening * attributes.x();
  if (look_.roughness.enabled()) s.roughness = look_.roughness.at(s.mask, 0.0f);
  if (look_.colored) {
    s.replaces_albedo = true;
    s.albedo = (look_.ridge_color + s.mask * (look_.fissure_color - look_.ridge_color)) * s.albedo_scale;
    s.albedo_scale = 1.0f;
  }
  return s;
}

}  // namespace phellem::bark
