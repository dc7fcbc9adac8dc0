// A cross-section of grown wood (Kratt et al., Fig. 6a): the growth rings traced in a plane
// (growth_rings.h) drawn as wood shows them: the first ring's inside a darker heartwood, the
// bands between rings alternately lighter and darker, the rings as thin dark lines
// (anti-aliased), the outermost (the bark surface) thicker, and the obstacles' sections grey.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bark/geometry/tri_mesh.h"
#include "bark/growth/growth_rings.h"

namespace phellem::bark {

struct SectionPlane {
  int axis = 1;       // the plane's normal: 0 x, 1 y, 2 z
  double value = 0;   // its coordinate along that axis (m)
};

struct SectionImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row 0 at the top
  double metres_per_pixel = 0;
  long segments = 0;  // ring segments drawn (0: the plane misses the wood)
};

// The image frames the rings' section with a 15 % margin, one scale on both axes; `width` ×
// `height` pixels (each at least 16). Image right and up are the plane's two other axes in
// increasing order (plane y: x right, z up).
SectionImage draw_ring_section(const std::vector<GrowthRing>& rings, const std::vector<TriMesh>& obstacles,
                               const SectionPlane& plane, int width, int height);

// The ring's trace as 2D segments in the plane's coordinates (the two axes other than
// plane.axis, in increasing order).
std::vector<std::array<Eigen::Vector2d, 2>> section_segments(const GrowthRing& ring, const SectionPlane& plane);

}  // namespace phellem::bark
