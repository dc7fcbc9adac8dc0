#include "bark/growth/ring_section.h"

#include <algorithm>
#include <cmath>

namespace phellem::bark {

namespace {

// The plane's in-plane axes: x → (y, z), y → (x, z), z → (x, y).
std::array<int, 2> plane_axes(int axis) { return axis == 0 ? std::array{1, 2} : axis == 1 ? std::array{0, 2} : std::array{0, 1}; }

// Even-odd coverage of a closed polygon soup (in pixel coordinates) by scanlines at pixel
// centres: 1 inside.
std::vector<uint8_t> fill(const std::vector<std::array<Eigen::Vector2d, 2>>& segs, int w, int h) {
  std::vector<uint8_t> mask(size_t(w) * size_t(h), 0);
  std::vector<double> xs;
  for (int y = 0; y < h; ++y) {
    const double sy = y + 0.5;
    xs.clear();
    for (const auto& s : segs) {
      const Eigen::Vector2d &a = s[0], &b = s[1];
      if ((a.y() <= sy) == (b.y() <= sy)) continue;  // half-open: a vertex on the line counts once
      xs.push_back(a.x() + (sy - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int x0 = std::max(0, int(std::ceil(xs[k] - 0.5))), x1 = std::min(w - 1, int(std::floor(xs[k + 1] - 0.5)));
      for (int x = x0; x <= x1; ++x) mask[size_t(y) * size_t(w) + size_t(x)] = 1;
    }
  }
  return mask;
}

// Darkens the pixels within `half` px of the segment, anti-aliased (coverage by distance).
void line(std::vector<float>& rgb, int w, int h, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double half,
          const std::array<float, 3>& ink) {
  const int x0 = std::max(0, int(std::floor(std::min(a.x(), b.x()) - half - 1))), x1 = std::min(w - 1, int(std::ceil(std::max(a.x(), b.x()) + half + 1)));
  const int y0 = std::max(0, int(std::floor(std::min(a.y(), b.y()) - half - 1))), y1 = std::min(h - 1, int(std::ceil(std::max(a.y(), b.y()) + half + 1)));
  const Eigen::Vector2d d = b - a;
  const double len2 = std::max(d.squaredNorm(), 1e-18);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d p(x + 0.5, y + 0.5);
      const double t = std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
      const double dist = (a + t * d - p).norm();
      const float cover = float(std::clamp(half + 0.5 - dist, 0.0, 1.0));
      if (cover <= 0) continue;
      float* px = &rgb[3 * (size_t(y) * size_t(w) + size_t(x))];
      for (int c = 0; c < 3; ++c) px[c] = std::min(px[c], px[c] * (1 - cover) + ink[size_t(c)] * cover);
    }
}

}  // namespace

std::vector<std::array<Eigen::Vector2d, 2>> section_segments(const GrowthRing& ring, const SectionPlane& plane) {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
  origin[plane.axis] = plane.value;
  normal[plane.axis] = 1;
  const auto [u, v] = plane_axes(plane.axis);
  std::vector<std::array<Eigen::Vector2d, 2>> out;
  for (const auto& s : slice_ring(ring, origin, normal))
    out.push_back({Eigen::Vector2d(s[0][u], s[0][v]), Eigen::Vector2d(s[1][u], s[1][v])});
  return out;
}

SectionImage draw_ring_section(const std::vector<GrowthRing>& rings, const std::vector<TriMesh>& obstacles,
                               const SectionPlane& plane, int width, int height) {
  SectionImage img;
  img.width = std::max(16, width);
  img.height = std::max(16, height);
  std::vector<std::vector<std::array<Eigen::Vector2d, 2>>> ring_segs, obstacle_segs;
  for (const auto& r : rings) ring_segs.push_back(section_segments(r, plane));
  for (const auto& m : obstacles) obstacle_segs.push_back(section_segments(GrowthRing{0, m.positions, m.triangles}, plane));
  // The frame: the last ring's section, with 15 % margin, at one scale on both axes.
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& segs : ring_segs)
    for (const auto& s : segs)
      for (const auto& p : s) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (const auto& segs : ring_segs) img.segments += long(segs.size());
  if (img.segments == 0) return img;
  const Eigen::Vector2d size = (hi - lo).cwiseMax(1e-9) * 1.3, centre = 0.5 * (lo + hi);
  img.metres_per_pixel = std::max(size.x() / img.width, size.y() / img.height);
  // Plane coordinates → pixels (image y down: the second axis points up).
  auto to_px = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d((p.x() - centre.x()) / img.metres_per_pixel + 0.5 * img.width,
                           0.5 * img.height - (p.y() - centre.y()) / img.metres_per_pixel);
  };
  auto in_px = [&](std::vector<std::array<Eigen::Vector2d, 2>> segs) {
    for (auto& s : segs) s = {to_px(s[0]), to_px(s[1])};
    return segs;
  };
  const size_t n = size_t(img.width) * size_t(img.height);
  std::vector<float> rgb(3 * n, 0.0f);
  for (size_t i = 0; i < n; ++i) rgb[3 * i] = 0.86f, rgb[3 * i + 1] = 0.87f, rgb[3 * i + 2] = 0.88f;  // background
  // Wood: each ring's inside painted over the last, from the outermost inwards, so a pixel
  // ends with the colour of the innermost ring that contains it: the first ring (the stem that
  // started to grow) a darker heartwood, then bands alternately lighter and darker.
  const size_t nr = ring_segs.size();
  for (size_t k = nr; k-- > 0;) {
    const std::vector<uint8_t> inside = fill(in_px(ring_segs[k]), img.width, img.height);
    std::array<float, 3> c = k % 2 ? std::array{0.84f, 0.66f, 0.45f} : std::array{0.78f, 0.59f, 0.39f};
    if (k == 0) c = {0.66f, 0.48f, 0.31f};
    for (size_t i = 0; i < n; ++i)
      if (inside[i]) std::copy(c.begin(), c.end(), &rgb[3 * i]);
  }
  for (const auto& segs : obstacle_segs) {
    const std::vector<uint8_t> inside = fill(in_px(segs), img.width, img.height);
    for (size_t i = 0; i < n; ++i)
      if (inside[i]) rgb[3 * i] = 0.42f, rgb[3 * i + 1] = 0.43f, rgb[3 * i + 2] = 0.46f;
  }
  const double half = std::max(0.6, img.width / 900.0);
  // The ring boundaries; the outermost (the bark surface now) three times as thick.
  for (size_t k = 0; k < nr; ++k)
    for (const auto& s : in_px(ring_segs[k]))
      line(rgb, img.width, img.height, s[0], s[1], k + 1 == nr ? 3 * half : half, {0.25f, 0.15f, 0.08f});
  for (const auto& segs : obstacle_segs)
    for (const auto& s : in_px(segs)) line(rgb, img.width, img.height, s[0], s[1], half, {0.15f, 0.15f, 0.17f});
  img.rgb.resize(3 * n);
  for (size_t i = 0; i < 3 * n; ++i) img.rgb[i] = uint8_t(std::lround(std::clamp(rgb[i], 0.0f, 1.0f) * 255));
  return img;
}

}  // namespace phellem::bark
