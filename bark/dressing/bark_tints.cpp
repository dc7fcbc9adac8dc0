#include "bark/dressing/bark_tints.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/noise.h"

namespace phellem::bark {

namespace {
float luminance(const Eigen::Vector3f& c) { return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z(); }
constexpr float kBorder = 0.15f;  // the blend band across a plate border, in cells
constexpr float kWarp = 0.4f;     // the borders' wander, in cells
}  // namespace

TintPalette::TintPalette(std::vector<Eigen::Vector3f> tints) : tints_(std::move(tints)) {
  std::stable_sort(tints_.begin(), tints_.end(),
                   [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) { return luminance(a) < luminance(b); });
}

Eigen::Vector3f TintPalette::at(float t) const {
  if (tints_.empty()) return Eigen::Vector3f::Ones();
  const float n = float(tints_.size());
  const float x = std::clamp((std::isfinite(t) ? t : 0.5f) * n - 0.5f, 0.0f, n - 1);
  const size_t i = std::min(tints_.size() - 1, size_t(x));
  const size_t j = std::min(tints_.size() - 1, i + 1);
  const float f = x - float(i);
  return (1 - f) * tints_[i] + f * tints_[j];
}

Eigen::Vector3f TintPalette::pick(float t) const {
  if (tints_.empty()) return Eigen::Vector3f::Ones();
  const float x = std::clamp(std::isfinite(t) ? t : 0.5f, 0.0f, 1.0f) * float(tints_.size());
  return tints_[std::min(tints_.size() - 1, size_t(x))];
}

TintPlates::Pick TintPlates::at(const Vec3f& p) const {
  Pick out;
  Vec3f q = p / size_;
  if (!q.allFinite() || !(q.cwiseAbs().maxCoeff() < 1e9f)) return out;
  // Warped by noise so the borders wander instead of running straight.
  q += kWarp * Vec3f(fbm(q, seed_ + 11, 2), fbm(q, seed_ + 12, 2), fbm(q, seed_ + 13, 2));
  const int64_t cx = int64_t(std::floor(q.x())), cy = int64_t(std::floor(q.y())), cz = int64_t(std::floor(q.z()));
  auto hash = [&](int64_t x, int64_t y, int64_t z, uint32_t k) {
    return lattice_hash01(x, y * 0x10001 + z * 0x3fffb, seed_ + k * 0x9e3779b9u, 0, 0);
  };
  std::array<std::pair<float, float>, 27> sites;  // (distance, coordinate)
  size_t n = 0;
  float nearest = std::numeric_limits<float>::infinity();
  for (int64_t x = cx - 1; x <= cx + 1; ++x)
    for (int64_t y = cy - 1; y <= cy + 1; ++y)
      for (int64_t z = cz - 1; z <= cz + 1; ++z) {
        const Vec3f site(float(x) + hash(x, y, z, 1), float(y) + hash(x, y, z, 2), float(z) + hash(x, y, z, 3));
        sites[n++] = {(site - q).norm(), hash(x, y, z, 0)};
        nearest = std::min(nearest, sites[n - 1].first);
      }
  // The sites within the band, nearest first (a fixed order: the blend's sum is deterministic).
  std::sort(sites.begin(), sites.end());
  float total = 0;
  for (size_t i = 0; i < sites.size() && out.n < int(out.weight.size()); ++i) {
    const float t = (sites[i].first - nearest) / kBorder;
    if (t >= 1) break;
    out.coordinate[size_t(out.n)] = sites[i].second;
    out.weight[size_t(out.n)] = 1 - t * t * (3 - 2 * t);
    total += out.weight[size_t(out.n++)];
  }
  for (int i = 0; i < out.n; ++i) out.weight[size_t(i)] /= total;
  return out;
}

}  // namespace phellem::bark
