// Film: per-pixel averages of the beauty and the AOVs (filter-importance-sampled, so every
// sample weighs the same). Layers and channel names are documented in docs/scene-format.md.
#pragma once

#include <cstddef>
#include <vector>

namespace phellem {

struct Film {
  int width = 0, height = 0;
  std::vector<float> beauty;     // RGBA (A = coverage)
  std::vector<float> albedo;     // RGB
  std::vector<float> normal;     // XYZ world-space shading normal
  std::vector<float> depth;      // Z: distance along the camera ray (0 where nothing is hit)
  std::vector<float> position;   // XYZ world position
  std::vector<float> object_id;  // id: 1-based object index of the first sample (0: none)
  std::vector<float> crack;      // bark fracture coverage and normalized depth (0 off bark)
  // D: offset of the first hit along the normal of the undisplaced surface, m (averaged over
  // the samples that hit; 0 where nothing is hit and on undisplaced geometry)
  std::vector<float> displacement;

  // Floats per pixel over all the layers above.
  static constexpr size_t kChannels = 4 + 3 + 3 + 1 + 3 + 1 + 2 + 1;

  Film() = default;
  Film(int w, int h)
      : width(w), height(h), beauty(size_t(w) * h * 4), albedo(size_t(w) * h * 3), normal(size_t(w) * h * 3),
        depth(size_t(w) * h), position(size_t(w) * h * 3), object_id(size_t(w) * h), crack(size_t(w) * h * 2),
        displacement(size_t(w) * h) {}
};

}  // namespace phellem
