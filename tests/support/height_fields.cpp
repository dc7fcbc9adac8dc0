#include "tests/support/height_fields.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace phellem::test {

namespace {

struct Fissure {
  double x, y0, y1, half_width, slant;  // cm
};

template <class F>
Heights sample(double width_cm, double height_cm, double px_per_cm, F&& f) {
  Heights h;
  h.width = int(std::lround(width_cm * px_per_cm));
  h.height = int(std::lround(height_cm * px_per_cm));
  h.z.resize(size_t(h.width) * h.height);
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      double sum = 0;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) sum += f((x + (i + 0.5) / 3) / px_per_cm, (y + (j + 0.5) / 3) / px_per_cm);
      h.z[size_t(y) * h.width + x] = float(sum / 9);
    }
  return h;
}

// A smooth value noise of period-free lattice `cell` cm (cosine-interpolated hashes).
double lattice_noise(double x, double y, double cell, uint32_t seed) {
  auto hash = [&](int64_t i, int64_t j) {
    uint64_t v = uint64_t(i) * 0x9E3779B97F4A7C15ull ^ uint64_t(j) * 0xC2B2AE3D27D4EB4Full ^ seed;
    v ^= v >> 29;
    v *= 0xBF58476D1CE4E5B9ull;
    v ^= v >> 32;
    return double(v >> 11) / double(1ull << 53);
  };
  const double u = x / cell, v = y / cell;
  const auto i = int64_t(std::floor(u)), j = int64_t(std::floor(v));
  const double fu = u - double(i), fv = v - double(j);
  const double su = (1 - std::cos(fu * M_PI)) / 2, sv = (1 - std::cos(fv * M_PI)) / 2;
  const double a = hash(i, j) + (hash(i + 1, j) - hash(i, j)) * su;
  const double b = hash(i, j + 1) + (hash(i + 1, j + 1) - hash(i, j + 1)) * su;
  return a + (b - a) * sv;
}

}  // namespace

Heights fissured_bark(double width_cm, double height_cm, double px_per_cm, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Fissure> fissures;
  const int count = int(width_cm * height_cm / 40.0);
  for (int k = 0; k < count; ++k) {
    Fissure f;
    f.x = u(rng) * width_cm;
    const double len = 5 + 15 * u(rng);
    f.y0 = u(rng) * height_cm - len / 2;
    f.y1 = f.y0 + len;
    f.half_width = (0.3 + 0.5 * u(rng)) / 2;
    f.slant = (u(rng) - 0.5) * 0.3;
    fissures.push_back(f);
  }
  // Fissures by the 1 cm columns they cross, so each sample looks at a few.
  std::vector<std::vector<int>> column(size_t(std::ceil(width_cm)) + 1);
  for (int k = 0; k < int(fissures.size()); ++k) {
    const Fissure& f = fissures[k];
    const double x0 = std::min(f.x, f.x + f.slant * (f.y1 - f.y0)) - f.half_width;
    const double x1 = std::max(f.x, f.x + f.slant * (f.y1 - f.y0)) + f.half_width;
    for (int c = std::max(0, int(std::floor(x0))); c <= std::min(int(column.size()) - 1, int(std::floor(x1))); ++c)
      column[size_t(c)].push_back(k);
  }
  return sample(width_cm, height_cm, px_per_cm, [&](double x, double y) {
    double z = 0.15 * lattice_noise(x, y, 0.8, seed) + 0.1 * lattice_noise(x, y, 3.0, seed + 1);
    for (int k : column[std::min(column.size() - 1, size_t(x))]) {
      const Fissure& f = fissures[size_t(k)];
      if (y < f.y0 || y > f.y1) continue;
      const double d = std::abs(x - (f.x + f.slant * (y - f.y0)));
      if (d < f.half_width) z = std::min(z, -1.0 * (1 - d / f.half_width));
    }
    return z;
  });
}

Heights smooth_noise(double width_cm, double height_cm, double px_per_cm, double feature_cm, uint32_t seed) {
  return sample(width_cm, height_cm, px_per_cm, [&](double x, double y) {
    return lattice_noise(x, y, feature_cm, seed) + 0.5 * lattice_noise(x, y, feature_cm / 2, seed + 7);
  });
}

void write_height_png16(const std::string& path, const Heights& h) {
  const auto [lo, hi] = std::minmax_element(h.z.begin(), h.z.end());
  const float scale = *hi > *lo ? 65535.0f / (*hi - *lo) : 0.0f;
  std::vector<uint16_t> px(h.z.size());
  for (size_t i = 0; i < px.size(); ++i) px[i] = uint16_t(std::lround((h.z[i] - *lo) * scale));
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(h.width, h.height, 1, OIIO::TypeDesc::UINT16);
  out->open(path, spec);
  out->write_image(OIIO::TypeDesc::UINT16, px.data());
  out->close();
}

void write_albedo_png(const std::string& path, const Heights& h, const float ridge[3], const float fissure[3]) {
  const auto [lo, hi] = std::minmax_element(h.z.begin(), h.z.end());
  std::vector<uint8_t> px(h.z.size() * 3);
  for (size_t i = 0; i < h.z.size(); ++i) {
    const float t = *hi > *lo ? (h.z[i] - *lo) / (*hi - *lo) : 1.0f;  // 0 in the deepest fissure, 1 on the highest ridge
    // A slow warm/cool drift across the image, as lichen and weathering give a photograph.
    const int x = int(i % size_t(h.width)), y = int(i / size_t(h.width));
    const float drift = 0.12f * std::sin(0.05f * float(x)) * std::cos(0.07f * float(y));
    const float shift[3] = {drift, 0.0f, -drift};
    for (int k = 0; k < 3; ++k)
      px[i * 3 + k] =
          uint8_t(std::lround(std::clamp(fissure[k] + (ridge[k] - fissure[k]) * t + shift[k], 0.0f, 1.0f) * 255));
  }
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(h.width, h.height, 3, OIIO::TypeDesc::UINT8);
  out->open(path, spec);
  out->write_image(OIIO::TypeDesc::UINT8, px.data());
  out->close();
}

}  // namespace phellem::test
