// Warps from [0,1)² to directions and tabulated distributions, each with its pdf.
// Every routine here has a chi-square test in tests/renderer/test_sampling_chi2.cpp.
#pragma once

#include <vector>

#include "util/math.h"

namespace phellem {

Vec2f sample_concentric_disk(const Vec2f& u);
// Cosine-weighted hemisphere around +z; pdf = cosθ / π.
Vec3f sample_cosine_hemisphere(const Vec2f& u);
inline float cosine_hemisphere_pdf(float cos_theta) { return std::max(0.0f, cos_theta) * kInvPi; }
// Uniform over the cone of half-angle acos(cos_max) around +z; pdf = 1 / (2π(1 - cos_max)).
Vec3f sample_uniform_cone(const Vec2f& u, float cos_max);
inline float uniform_cone_pdf(float cos_max) { return 1.0f / (kTwoPi * (1.0f - cos_max)); }
Vec3f sample_uniform_sphere(const Vec2f& u);
// Uniform barycentrics on a triangle (b1, b2).
Vec2f sample_uniform_triangle(const Vec2f& u);

inline float power_heuristic(float f, float g) {
  const float f2 = f * f, g2 = g * g;
  return (f2 + g2) > 0.0f ? f2 / (f2 + g2) : 0.0f;
}

// Piecewise-constant 1D distribution on [0, 1), inverted through its cdf. A guide table
// (Chen & Asau 1974, "On generating random variates from an empirical distribution") maps u
// to the first bin that can hold it, so sampling costs O(1) on average instead of a binary
// search, and the map u -> x stays the monotone inverse cdf (stratification survives).
class Distribution1D {
 public:
  Distribution1D() = default;
  explicit Distribution1D(std::vector<float> f);
  // Returns x ∈ [0,1), its pdf (density w.r.t. x) and the bin.
  float sample(float u, float* pdf, int* bin = nullptr) const;
  size_t discrete(float u, float* pmf) const;  // pick a bin with probability ∝ f
  float pdf(float x) const;
  float integral() const { return integral_; }
  size_t size() const { return f_.size(); }
  float pmf(size_t i) const { return integral_ > 0 ? f_[i] / (integral_ * f_.size()) : 1.0f / f_.size(); }

 private:
  std::vector<float> f_, cdf_;
  std::vector<uint32_t> guide_;  // guide_[k] = bin holding u = k / guide_.size()
  float integral_ = 0;
};

// Piecewise-constant 2D distribution on [0,1)², rows along v (marginal) then u (conditional).
class Distribution2D {
 public:
  Distribution2D() = default;
  Distribution2D(const std::vector<float>& f, int nu, int nv);
  Vec2f sample(const Vec2f& u, float* pdf) const;
  float pdf(const Vec2f& p) const;

 private:
  std::vector<Distribution1D> conditional_;
  std::vector<float> pdf_;  // density of each cell, row-major (one load per pdf query)
  Distribution1D marginal_;
  int nu_ = 0, nv_ = 0;
};

}  // namespace phellem
