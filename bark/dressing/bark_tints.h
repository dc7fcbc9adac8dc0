// Per-plate and per-crack colour variation of stress bark (issue 22). A palette of tints (the
// colours of a photo's 1 cm ridge or fissure patches relative to their group's mean,
// scene/bark_photo.h, or a grey ramp) is looked up by a coordinate in [0, 1] that each vertex
// keeps (bark/dressing/bark_surface.h): per crack, a hash of the crack's chain; per plate, the
// hash of the Voronoi cell the surface point lies in, so every tint of the palette is used
// as often as the photo's patches were.
#pragma once

#include <Eigen/Core>
#include <array>
#include <type_traits>
#include <cstdint>
#include <vector>

#include "util/math.h"

namespace phellem::bark {

class TintPalette {
 public:
  TintPalette() = default;  // empty: white everywhere
  // Sorted by luminance, so nearby coordinates give similar tints and an interpolated
  // coordinate (across a triangle, between two cracks at a junction) a colour between them.
  explicit TintPalette(std::vector<Eigen::Vector3f> tints);
  // Piecewise linear over the sorted tints: entry i is centred at (i + 0.5) / n; t is clamped.
  Eigen::Vector3f at(float t) const;
  // The entry t picks, floor(t · n), without blending (t is clamped).
  Eigen::Vector3f pick(float t) const;
  bool empty() const { return tints_.empty(); }
  const std::vector<Eigen::Vector3f>& tints() const { return tints_; }

 private:
  std::vector<Eigen::Vector3f> tints_;
};

// Plates: a Voronoi partition of space (one jittered site per cell of `size` metres, the
// space warped by one octave of noise so the borders wander) that the surface cuts into
// irregular patches. Ported to GLSL in shaders/bark_tints.glsl (the preview). Each plate has a coordinate uniform on [0, 1) (a
// hash of its cell), so it picks every tint of a palette as often as the photo's patches.
// Across borders the plates blend over a band of 0.15 cell: every site whose
// distance is within that band of the nearest one weighs 1 − smoothstep(Δd / band), and the
// weights are normalized, which keeps the blend continuous where three plates meet.
class TintPlates {
 public:
  TintPlates(float size, uint32_t seed) : size_(size), seed_(seed) {}
  struct Pick {
    int n = 0;                              // plates in the blend (1 inside a plate)
    std::array<float, 8> coordinate{}, weight{};  // weights sum to 1
    // Σ weight · f(coordinate), e.g. a palette's pick; with n = 0 (a non-finite point), f(½).
    template <class F>
    auto blend(F&& f) const -> std::decay_t<decltype(f(0.5f))> {
      using T = std::decay_t<decltype(f(0.5f))>;
      if (n == 0) return f(0.5f);
      T sum = weight[0] * f(coordinate[0]);
      for (int i = 1; i < n; ++i) sum += weight[size_t(i)] * f(coordinate[size_t(i)]);
      return sum;
    }
  };
  Pick at(const Vec3f& p) const;
  float size() const { return size_; }
  uint32_t seed() const { return seed_; }

 private:
  float size_;
  uint32_t seed_;
};

}  // namespace phellem::bark
