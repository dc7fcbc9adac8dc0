#include "bark/dressing/bark_tints.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/hash.h"
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
  q += kWarp * Vec3f(fbm(q, seed_ + 11, 1), fbm(q, seed_ + 12, 1), fbm(q, seed_ + 13, 1));
  const int32_t cx = int32_t(std::floor(q.x())), cy = int32_t(std::floor(q.y())), cz = int32_t(std::floor(q.z()));
  std::array<std::pair<float, float>, 27> sites;  // (distance, coordinate)
  size_t n = 0;
  float nearest = std::numeric_limits<float>::infinity();
  for (int32_t x = cx - 1; x <= cx + 1; ++x) {
    const uint32_t hx = hash_combine(seed_, uint32_t(x));
    for (int32_t y = cy - 1; y <= cy + 1; ++y) {
      const uint32_t hxy = hash_combine(hx, uint32_t(y));
      for (int32_t z = cz - 1; z <= cz + 1; ++z) {
        // One hash per cell (util/hash.h, built coordinate by coordinate: cheap on a GPU too):
        // its top 24 bits are the plate's coordinate, a second round's three 10-bit fields the
        // site's place in the cell.
        const uint32_t h = hash_combine(hxy, uint32_t(z)), j = hash_u32(h ^ 0x2545f491u);
        const Vec3f site(float(x) + (float(j & 1023u) + 0.5f) / 1024.0f, float(y) + (float((j >> 10) & 1023u) + 0.5f) / 1024.0f,
                         float(z) + (float((j >> 20) & 1023u) + 0.5f) / 1024.0f);
        sites[n++] = {(site - q).norm(), float(h >> 8) * (1.0f / 16777216.0f)};
        nearest = std::min(nearest, sites[n - 1].first);
      }
    }
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
