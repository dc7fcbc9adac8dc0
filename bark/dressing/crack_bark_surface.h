// CrackBarkSurface: a cracked mesh's BarkSurface (bark/dressing/bark_surface.h). The cracks of
// the stress model (Spicker 2014, Algorithm 1) carve V-profiles into the surface (sec. 4.2 as
// real geometry, bark/dressing/crack_profile.h); the attributes a displaced point keeps are
// (normalized depth, crack mask, crack chain coordinate, 0), and shading darkens the colour
// with depth and tints it per crack and per plate of its position (bark_tints.h).
#pragma once

#include <cstdint>

#include "bark/dressing/bark_surface.h"
#include "bark/dressing/bark_tints.h"
#include "bark/dressing/crack_profile.h"

namespace phellem::bark {

class CrackBarkSurface final : public BarkSurface {
 public:
  CrackBarkSurface(const CrackedMesh& mesh, const CrackLook& look, uint32_t seed);

  BarkDisplacement displace(const SurfacePoint& p) const override;
  // Colour: the ridge colour (or the material's) × the plate's tint, blended by the mask into
  // the fissure colour × the crack's tint, × (1 − darkening × depth).
  BarkShade shade(const Eigen::Vector4f& attributes, const Eigen::Vector3f& position) const override;
  bool reaches(const Eigen::Vector3f& a, const Eigen::Vector3f& b) const override { return profile_.reaches(a, b); }
  size_t memory_bytes() const override { return profile_.segments() * 64; }

  const CrackProfile& profile() const { return profile_; }
  const TintPalette& ridge_palette() const { return ridge_tints_; }
  const TintPalette& fissure_palette() const { return fissure_tints_; }
  const TintPlates& plates() const { return plates_; }

 private:
  CrackProfile profile_;
  CrackLook look_;
  TintPalette ridge_tints_, fissure_tints_;
  TintPlates plates_;
};

}  // namespace phellem::bark
