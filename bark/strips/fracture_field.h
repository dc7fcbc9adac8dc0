// FractureField: the strip model's result rasterized over the (s, θ) parameter space of one
// cylinder (Lefebvre & Neyret 2002, sec. 5.4 "mappable dressing", texture case). Columns are
// θ ∈ [0, 2π) (u = θ / 2π, periodic), rows are s ∈ [0, length] from the bottom (row 0) up,
// whichever way the strips run (strips along the axis are rasterized in their own space and
// transposed).
//
// Fracture silhouettes are reconstructed from the skeleton (sec. 3.3): a fracture element and
// the element it links to in the next strip bound a trapezoid; a tip without a link closes
// in a half-ellipse half a strip beyond its element. Coverage is anti-aliased across θ.
#pragma once

#include <vector>

#include "bark/strips/strip_model.h"

namespace phellem::bark {

// Normalized depth profile across a fracture (papers' Figure 14 / 2001 Figure 8): depth at
// normalized distance q from the lip (0) to the axis (1), in [0, 1].
// Power: 1 − (1 − q)^exponent, the family between them (1 = V, 2 = U; below 1 a narrow
// cusp at the axis, above 2 towards a box), so a fit can search the shape continuously.
enum class DepthProfileShape { V, U, Box, Round, Power };
struct DepthProfile {
  DepthProfileShape shape = DepthProfileShape::U;
  double exponent = 2;  // Power only, in [0.25, 8]
  double depth_per_width = 0.6;  // depth grows with width ...
  double max_depth = 0.02;       // ... up to this (m)
  double evaluate(double q) const;
};

struct FractureField {
  int width = 0, height = 0;  // columns (θ), rows (s)
  double length = 0;          // metres along the axis
  double circumference = 0;   // mean final circumference (m), for aspect-correct sizes
  // Per pixel (row-major, row 0 at s = 0):
  std::vector<float> opening;      // fracture coverage in [0, 1]
  std::vector<float> depth;        // metres below the epidermis
  std::vector<float> uv0;          // 2 per pixel: material coordinate on the original epidermis (u), s / length (v);
                                   // strips along the axis: θ / 2π (u), material coordinate along the axis (v)
  std::vector<float> interior;     // across the fracture, 0 where the newest material appears (Figure 13), 1 at the oldest
  std::vector<float> fracture_id;  // skeleton component (+1; 0 = epidermis)
  std::vector<float> age;          // growth steps since the fracture appeared (0 on epidermis)
  std::vector<float> level;        // refracture level of the surface (0 = original epidermis)
  std::vector<float> color;        // 3 per pixel, filled by dressing
  std::vector<float> roughness;    // filled by dressing when it varies the roughness (else empty)
  size_t index(int x, int y) const { return size_t(y) * width + x; }
};

FractureField rasterize(const StripModel& model, int width, int height, const DepthProfile& profile);

}  // namespace phellem::bark
