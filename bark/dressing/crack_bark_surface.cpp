#include "bark/dressing/crack_bark_surface.h"

namespace phellem::bark {

CrackBarkSurface::CrackBarkSurface(const CrackedMesh& mesh, const CrackLook& look, uint32_t seed)
    : profile_(mesh, look, seed), darkening_(look.darkening) {}

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
  s.albedo_scale = 1.0f - darkening_ * attributes.x();
  return s;
}

}  // namespace phellem::bark
