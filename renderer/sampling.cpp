#include "renderer/sampling.h"

#include <numeric>

#include "util/fast_trig.h"

namespace phellem {

Vec2f sample_concentric_disk(const Vec2f& u) {
  // Shirley & Chiu 1997.
  const Vec2f o = 2.0f * u - Vec2f(1, 1);
  if (o.x() == 0 && o.y() == 0) return Vec2f(0, 0);
  float r, theta;
  if (std::abs(o.x()) > std::abs(o.y())) {
    r = o.x();
    theta = (kPi / 4) * (o.y() / o.x());
  } else {
    r = o.y();
    theta = kPi / 2 - (kPi / 4) * (o.x() / o.y());
  }
  float s, c;
  fast_sincos(theta, &s, &c);
  return r * Vec2f(c, s);
}

Vec3f sample_cosine_hemisphere(const Vec2f& u) {
  const Vec2f d = sample_concentric_disk(u);
  return Vec3f(d.x(), d.y(), safe_sqrt(1.0f - d.squaredNorm()));
}

Vec3f sample_uniform_cone(const Vec2f& u, float cos_max) {
  const float cos_t = (1.0f - u.x()) + u.x() * cos_max;
  const float sin_t = safe_sqrt(1.0f - cos_t * cos_t);
  float s, c;
  fast_sincos(kTwoPi * u.y(), &s, &c);
  return Vec3f(c * sin_t, s * sin_t, cos_t);
}

Vec3f sample_uniform_sphere(const Vec2f& u) {
  const float z = 1.0f - 2.0f * u.x();
  const float r = safe_sqrt(1.0f - z * z);
  float s, c;
  fast_sincos(kTwoPi * u.y(), &s, &c);
  return Vec3f(r * c, r * s, z);
}

Vec2f sample_uniform_triangle(const Vec2f& u) {
  // Heitz 2019 low-distortion map.
  float b0, b1;
  if (u.x() < u.y()) {
    b0 = u.x() / 2;
    b1 = u.y() - b0;
  } else {
    b1 = u.y() / 2;
    b0 = u.x() - b1;
  }
  return Vec2f(b0, b1);
}

Distribution1D::Distribution1D(std::vector<float> f) : f_(std::move(f)) {
  const size_t n = f_.size();
  cdf_.assign(n + 1, 0.0f);
  double acc = 0;
  for (size_t i = 0; i < n; ++i) {
    acc += std::max(0.0f, f_[i]);
    cdf_[i + 1] = float(acc);
  }
  integral_ = float(acc / double(n));
  if (acc <= 0) {
    for (size_t i = 0; i <= n; ++i) cdf_[i] = float(i) / float(n);
  } else {
    for (size_t i = 1; i <= n; ++i) cdf_[i] = float(double(cdf_[i]) / acc);
  }
  cdf_[n] = 1.0f;
  guide_.resize(n);
  size_t i = 0;
  for (size_t k = 0; k < n; ++k) {
    const float u = float(k) / float(n);
    while (i + 1 < n && cdf_[i + 1] <= u) ++i;
    guide_[k] = uint32_t(i);
  }
}

size_t Distribution1D::discrete(float u, float* pmf_out) const {
  // The bin i with cdf[i] <= u < cdf[i+1]; empty bins (cdf[i] == cdf[i+1]) are never chosen.
  const size_t n = f_.size();
  size_t i = guide_[std::min(size_t(u * float(n)), n - 1)];
  while (i > 0 && cdf_[i] > u) --i;  // u * n rounded up into the next guide cell
  while (i + 1 < n && cdf_[i + 1] <= u) ++i;
  if (pmf_out) *pmf_out = cdf_[i + 1] - cdf_[i];
  return i;
}

float Distribution1D::sample(float u, float* pdf_out, int* bin) const {
  float pmf_i;
  const size_t i = discrete(u, &pmf_i);
  const float width = cdf_[i + 1] - cdf_[i];
  const float du = width > 0 ? (u - cdf_[i]) / width : 0.5f;
  if (pdf_out) *pdf_out = pmf_i * float(f_.size());
  if (bin) *bin = int(i);
  return std::min((float(i) + std::clamp(du, 0.0f, 1.0f)) / float(f_.size()), kOneMinusEpsilon);
}

float Distribution1D::pdf(float x) const {
  const size_t i = std::min<size_t>(size_t(std::max(0.0f, x) * f_.size()), f_.size() - 1);
  return (cdf_[i + 1] - cdf_[i]) * float(f_.size());
}

Distribution2D::Distribution2D(const std::vector<float>& f, int nu, int nv) : nu_(nu), nv_(nv) {
  std::vector<float> row_integral(nv);
  conditional_.reserve(nv);
  for (int v = 0; v < nv; ++v) {
    conditional_.emplace_back(std::vector<float>(f.begin() + size_t(v) * nu, f.begin() + size_t(v + 1) * nu));
    row_integral[v] = conditional_.back().integral();
  }
  marginal_ = Distribution1D(std::move(row_integral));
  pdf_.resize(size_t(nu) * nv);
  for (int v = 0; v < nv; ++v)
    for (int u = 0; u < nu; ++u) {
      const float pu = conditional_[v].pdf((u + 0.5f) / nu), pv = marginal_.pdf((v + 0.5f) / nv);
      pdf_[size_t(v) * nu + u] = pu * pv;
    }
}

Vec2f Distribution2D::sample(const Vec2f& u, float* pdf_out) const {
  float pv, pu;
  int row;
  const float y = marginal_.sample(u.y(), &pv, &row);
  const float x = conditional_[row].sample(u.x(), &pu);
  if (pdf_out) *pdf_out = pu * pv;
  return Vec2f(x, y);
}

float Distribution2D::pdf(const Vec2f& p) const {
  const int row = std::clamp(int(p.y() * nv_), 0, nv_ - 1), col = std::clamp(int(p.x() * nu_), 0, nu_ - 1);
  return pdf_[size_t(row) * nu_ + col];
}

}  // namespace phellem
