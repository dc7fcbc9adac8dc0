#include "bark/dressing/field_bark_surface.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace phellem::bark {

FieldBarkSurface::FieldBarkSurface(const FractureField& f, double max_depth)
    : width_(f.width), height_(f.height), length_(f.length), max_depth_(max_depth > 0 ? max_depth : 1.0) {
  texels_.resize(size_t(width_) * height_);
  for (size_t p = 0; p < texels_.size(); ++p)
    texels_[p] = {f.depth[p], f.opening[p], f.color[3 * p], f.color[3 * p + 1], f.color[3 * p + 2]};
  if (f.roughness.size() == texels_.size()) roughness_ = f.roughness;
}

template <class F>
auto FieldBarkSurface::bilinear(double u, double v, F&& get) const {
  // Texel centres at (i + 0.5) / width; u wraps (cyclic strips), v clamps.
  double x = (u - std::floor(u)) * width_ - 0.5, y = std::clamp(v, 0.0, 1.0) * height_ - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const float tx = float(x - fx), ty = float(y - fy);
  const int x0 = (int(fx) % width_ + width_) % width_, x1 = (x0 + 1) % width_;
  const int y0 = std::clamp(int(fy), 0, height_ - 1), y1 = std::clamp(int(fy) + 1, 0, height_ - 1);
  const Texel& a = texels_[size_t(y0) * width_ + x0];
  const Texel& b = texels_[size_t(y0) * width_ + x1];
  const Texel& c = texels_[size_t(y1) * width_ + x0];
  const Texel& d = texels_[size_t(y1) * width_ + x1];
  using T = std::decay_t<decltype(get(a))>;  // evaluated here: no Eigen expression outlives its operands
  return T((get(a) * (1 - tx) + get(b) * tx) * (1 - ty) + (get(c) * (1 - tx) + get(d) * tx) * ty);
}

float FieldBarkSurface::depth(double u, double v) const {
  if (texels_.empty()) return 0;
  return bilinear(u, v, [](const Texel& t) { return t.depth; });
}

BarkDisplacement FieldBarkSurface::displace(const SurfacePoint& p) const {
  BarkDisplacement d;
  d.offset = -depth(p.param.x(), p.param.y());
  d.attributes << p.param.cast<float>(), 0, 0;
  return d;
}

BarkShade FieldBarkSurface::shade(const Eigen::Vector4f& uv, const Eigen::Vector3f&) const { return shade_at(uv.x(), uv.y()); }

BarkShade FieldBarkSurface::shade_at(double u, double v) const {
  BarkShade s;
  s.replaces_albedo = true;
  if (texels_.empty()) return s;
  s.mask = bilinear(u, v, [](const Texel& t) { return t.mask; });
  s.depth = std::clamp(float(bilinear(u, v, [](const Texel& t) { return t.depth; }) / max_depth_), 0.0f, 1.0f);
  s.albedo = bilinear(u, v, [](const Texel& t) { return Eigen::Vector3f(t.r, t.g, t.b); });
  if (!roughness_.empty())
    s.roughness = bilinear(u, v, [&](const Texel& t) { return roughness_[size_t(&t - texels_.data())]; });
  return s;
}

void FieldBarkSurface::export_texels(std::vector<float>* depth_mask, std::vector<float>* albedo) const {
  depth_mask->clear();
  albedo->clear();
  depth_mask->reserve(2 * texels_.size());
  albedo->reserve(4 * texels_.size());
  for (const Texel& t : texels_) {
    depth_mask->insert(depth_mask->end(), {t.depth, t.mask});
    albedo->insert(albedo->end(), {t.r, t.g, t.b, 1.0f});
  }
}

}  // namespace phellem::bark
