// FieldBarkSurface: strip bark's BarkSurface (bark/dressing/bark_surface.h) — one cylinder's
// dressed FractureField reduced to what shading needs: the displacement into the fracture (metres, along the inward normal),
// the fracture coverage, the normalized depth and the dressed albedo (depth darkening
// included), sampled bilinearly over (u = θ / 2π periodic, v = s / length).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "bark/dressing/bark_surface.h"
#include "bark/strips/fracture_field.h"

namespace phellem::bark {

class FieldBarkSurface final : public BarkSurface {
 public:
  FieldBarkSurface() = default;
  // `max_depth` normalizes the depth for the `crack` AOV and darkening.
  FieldBarkSurface(const FractureField& dressed, double max_depth);

  // Inwards by the fracture depth at the point's (u, v); the attributes are (u, v) itself.
  BarkDisplacement displace(const SurfacePoint& p) const override;
  // The dressed field at (u, v) = attributes: its albedo replaces the material's.
  BarkShade shade(const Eigen::Vector4f& uv, const Eigen::Vector3f& position) const override;
  bool reaches(const Eigen::Vector3f&, const Eigen::Vector3f&) const override { return !texels_.empty(); }

  // Metres below the epidermis at (u, v).
  float depth(double u, double v) const;
  BarkShade shade_at(double u, double v) const;

  int width() const { return width_; }
  int height() const { return height_; }
  double length() const { return length_; }
  // The texels as the preview's textures take them, row-major from v = 0: (depth, mask) and
  // (r, g, b, 1) per texel; and the depth that normalizes the `crack` AOV.
  void export_texels(std::vector<float>* depth_mask, std::vector<float>* albedo) const;
  double max_depth() const { return max_depth_; }
  size_t memory_bytes() const override { return texels_.capacity() * sizeof(Texel) + roughness_.capacity() * sizeof(float); }

 private:
  struct Texel {
    float depth, mask, r, g, b;
  };
  template <class F>
  auto bilinear(double u, double v, F&& get) const;
  int width_ = 0, height_ = 0;
  double length_ = 0, max_depth_ = 1;
  std::vector<Texel> texels_;
  std::vector<float> roughness_;  // per texel when the dressing varies it (else empty)
};

}  // namespace phellem::bark
