// CrackBarkSurface: a cracked mesh's BarkSurface (bark/dressing/bark_surface.h). The cracks of
// the stress model (Spicker 2014, Algorithm 1) carve V-profiles into the surface (sec. 4.2 as
// real geometry, bark/dressing/crack_profile.h); the attributes a displaced point keeps are
// (normalized depth, crack mask), and shading darkens the material's base colour with depth.
#pragma once

#include <cstdint>

#include "bark/dressing/bark_surface.h"
#include "bark/dressing/crack_profile.h"

namespace phellem::bark {

class CrackBarkSurface final : public BarkSurface {
 public:
  CrackBarkSurface(const CrackedMesh& mesh, const CrackLook& look, uint32_t seed);

  BarkDisplacement displace(const SurfacePoint& p) const override;
  // attributes = (normalized depth, mask); albedo × (1 − darkening × depth).
  BarkShade shade(const Eigen::Vector2f& attributes) const override;
  bool reaches(const Eigen::Vector3f& a, const Eigen::Vector3f& b) const override { return profile_.reaches(a, b); }
  size_t memory_bytes() const override { return profile_.segments() * 64; }

  const CrackProfile& profile() const { return profile_; }

 private:
  CrackProfile profile_;
  CrackLook look_;
};

}  // namespace phellem::bark
