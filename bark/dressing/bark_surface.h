// BarkSurface: what the renderer and the preview take from a bark model for one surface
// (DESIGN.md data flow). For strip bark it is one cylinder's dressed FractureField reduced to
// what shading needs: the displacement into the fracture (metres, along the inward normal),
// the fracture coverage, the normalized depth and the dressed albedo (depth darkening
// included), sampled bilinearly over (u = θ / 2π periodic, v = s / length).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "bark/strips/fracture_field.h"

namespace phellem::bark {

class BarkSurface {
 public:
  BarkSurface() = default;
  // `max_depth` normalizes the depth for the `crack` AOV and darkening.
  BarkSurface(const FractureField& dressed, double max_depth);

  struct Shade {
    float mask = 0;        // fracture coverage in [0, 1]
    float depth = 0;       // normalized depth in [0, 1]
    Eigen::Vector3f albedo{0, 0, 0};
  };
  // Metres below the epidermis at (u, v).
  float depth(double u, double v) const;
  Shade shade(double u, double v) const;

  int width() const { return width_; }
  int height() const { return height_; }
  double length() const { return length_; }
  size_t memory_bytes() const { return texels_.capacity() * sizeof(Texel); }

 private:
  struct Texel {
    float depth, mask, r, g, b;
  };
  template <class F>
  auto bilinear(double u, double v, F&& get) const;
  int width_ = 0, height_ = 0;
  double length_ = 0, max_depth_ = 1;
  std::vector<Texel> texels_;
};

}  // namespace phellem::bark
