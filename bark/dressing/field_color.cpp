#include "bark/dressing/field_color.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "util/noise.h"

namespace phellem::bark {

namespace {

// A feature size fitted to a whole number of repeats of `period` (unchanged without one).
double fit(double size, double period, int64_t* cells) {
  if (period <= 0) {
    *cells = 0;
    return size;
  }
  *cells = std::max<int64_t>(1, std::llround(period / size));
  return period / double(*cells);
}

// The tint of the lattice cell (i, j) (wrapping after nx cells), smoothstep-blended between
// cells like value noise (util/noise.h).
Eigen::Vector3f tint_at(const std::vector<Eigen::Vector3f>& tints, double x, double y, double size, double period_x,
                        uint32_t seed) {
  int64_t nx;
  const double cx = fit(size, period_x, &nx);
  const double u = x / cx, v = y / size, fu = std::floor(u), fv = std::floor(v);
  double tu = u - fu, tv = v - fv;
  tu = tu * tu * (3 - 2 * tu);
  tv = tv * tv * (3 - 2 * tv);
  auto pick = [&](int64_t i, int64_t j) {
    return tints[std::min(tints.size() - 1, size_t(lattice_hash01(i, j, seed, nx, 0) * float(tints.size())))];
  };
  const int64_t i = int64_t(fu), j = int64_t(fv);
  return float((1 - tv) * (1 - tu)) * pick(i, j) + float((1 - tv) * tu) * pick(i + 1, j) + float(tv * (1 - tu)) * pick(i, j + 1) +
         float(tv * tu) * pick(i + 1, j + 1);
}

// A fracture's tint: hashed from its skeleton id.
const Eigen::Vector3f& fracture_tint(const std::vector<Eigen::Vector3f>& tints, float id) {
  return tints[std::min(tints.size() - 1, size_t(lattice_hash01(int64_t(id), 0, 0x7f4a7c15u, 0, 0) * float(tints.size())))];
}

}  // namespace

Eigen::Vector3f ColorSample::at(double x, double y, double period_x, double period_y) const {
  if (!rgb.empty()) {
    int64_t nx, ny;
    double u = x / fit(size_x, period_x, &nx), v = y / fit(size_y, period_y, &ny);
    u = (u - std::floor(u)) * width - 0.5;
    v = (1.0 - (v - std::floor(v))) * height - 0.5;  // row 0 is the top of the image
    const double fu = std::floor(u), fv = std::floor(v);
    const double tu = u - fu, tv = v - fv;
    auto px = [&](long i, long j) {
      i = ((i % width) + width) % width;
      j = ((j % height) + height) % height;
      return Eigen::Vector3f(&rgb[(size_t(j) * width + size_t(i)) * 3]);
    };
    const long i = long(fu), j = long(fv);
    return float((1 - tv) * (1 - tu)) * px(i, j) + float((1 - tv) * tu) * px(i + 1, j) + float(tv * (1 - tu)) * px(i, j + 1) +
           float(tv * tu) * px(i + 1, j + 1);
  }
  // Fibres: noise stretched 12× along the axis, over two octaves of blotches.
  auto noise = [&](double cx, double cy, uint32_t sd) {
    int64_t nx, ny;
    const double gx = fit(cx, period_x, &nx), gy = fit(cy, period_y, &ny);
    return tileable_value_noise(x / gx, y / gy, sd, nx, ny);
  };
  const double g = grain;
  const float fibre = noise(g, 12 * g, seed);
  const float blotch = 0.65f * noise(8 * g, 8 * g, seed + 1) + 0.35f * noise(3 * g, 3 * g, seed + 2);
  const float m = 1.0f + variation * (1.2f * (fibre - 0.5f) + 1.0f * (blotch - 0.5f));
  return base * std::max(0.0f, m);
}

void dress_colors(FractureField& f, const FieldColors& c, double max_depth, double initial_circumference, bool tile_s) {
  const double C = f.circumference, C0 = initial_circumference, Py = tile_s ? f.length : 0.0;
  if (c.roughness.enabled()) f.roughness.assign(size_t(f.width) * f.height, 0.0f);
  tbb::parallel_for(0, f.height, [&](int y) {
    const double s = (y + 0.5) / f.height * f.length;
    for (int x = 0; x < f.width; ++x) {
      const size_t p = f.index(x, y);
      const double around = (x + 0.5) / f.width * C;
      const ColorSample& skin_sample = f.level[p] > 0 && f.opening[p] <= 0 ? c.hardened : c.epidermis;
      // The epidermis is quasi-rigid: its pattern lives at the material coordinate (metres of
      // the original circumference), not at the current position.
      Eigen::Vector3f skin = skin_sample.at(f.uv0[2 * p] * C0, s, C0, Py);
      if (!c.ridge_tints.empty()) skin = skin.cwiseProduct(tint_at(c.ridge_tints, f.uv0[2 * p] * C0, s, c.tint_size, C0, 0x51ed27u));
      Eigen::Vector3f base = skin;
      if (f.opening[p] > 0) {
        Eigen::Vector3f inner = c.fracture.at(around, s, C, Py) * (1.0f - c.interior_darkening * f.interior[p]);
        if (!c.fissure_tints.empty()) inner = inner.cwiseProduct(fracture_tint(c.fissure_tints, f.fracture_id[p]));
        base = skin + f.opening[p] * (inner - skin);
      }
      const float dark = 1.0f - c.depth_darkening * float(std::clamp(f.depth[p] / max_depth, 0.0, 1.0));
      for (int k = 0; k < 3; ++k) f.color[3 * p + size_t(k)] = std::max(0.0f, base[k] * dark);
      if (c.roughness.enabled()) {
        const BarkRoughness& r = c.roughness;
        int64_t nx;
        const double cell = fit(r.noise_size, C, &nx);
        const float n = 2 * tileable_value_noise(around / cell, s / r.noise_size, r.seed, nx, 0) - 1;
        f.roughness[p] = r.at(f.opening[p], n);
      }
    }
  });
}

}  // namespace phellem::bark
