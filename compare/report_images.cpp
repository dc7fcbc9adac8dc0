#include "compare/report_images.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "compare/percentile.h"
#include "io/image_output.h"
#include "io/png_encode.h"

namespace phellem {

namespace {

// Box-filtered float RGB of `width`×`height` source pixels whose colour `at(x, y)` gives,
// shrunk by a whole factor until it fits in `max_side`.
struct Picture {
  int width = 0, height = 0;
  std::vector<float> rgb;
};

template <class F>
Picture filtered(int width, int height, int max_side, F&& at) {
  const int k = std::max(1, (std::max(width, height) + max_side - 1) / max_side);
  Picture p;
  p.width = std::max(1, width / k);
  p.height = std::max(1, height / k);
  p.rgb.assign(size_t(p.width) * p.height * 3, 0.0f);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      float* out = &p.rgb[(size_t(y) * p.width + x) * 3];
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          const std::array<float, 3> c = at(std::min(x * k + i, width - 1), std::min(y * k + j, height - 1));
          for (int ch = 0; ch < 3; ++ch) out[ch] += c[ch];
        }
      for (int ch = 0; ch < 3; ++ch) out[ch] /= float(k * k);
    }
  return p;
}

std::vector<unsigned char> png(const Picture& p) {
  std::vector<uint8_t> rgb(p.rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t(std::lround(std::clamp(p.rgb[i], 0.0f, 1.0f) * 255.0f));
  return encode_png(p.width, p.height, 3, rgb.data());
}

// Maps heights to [0, 1] between their 1st and 99th percentiles.
struct Stretch {
  float lo = 0, scale = 1;
  explicit Stretch(const std::vector<float>& z) {
    const std::vector<double> p = percentiles(z, {1, 99});
    lo = float(p[0]);
    scale = p[1] > p[0] ? float(1.0 / (p[1] - p[0])) : 0.0f;
  }
  float operator()(float z) const { return std::clamp((z - lo) * scale, 0.0f, 1.0f); }
};

}  // namespace

std::vector<unsigned char> height_png(const HeightField& f, int max_side) {
  const Stretch grey(f.z);
  return png(filtered(f.width, f.height, max_side, [&](int x, int y) {
    const float v = grey(f.at(x, y));
    return std::array<float, 3>{v, v, v};
  }));
}

std::vector<unsigned char> mask_overlay_png(const HeightField& f, const std::vector<uint8_t>& mask, int max_side) {
  const Stretch grey(f.z);
  return png(filtered(f.width, f.height, max_side, [&](int x, int y) {
    const float v = 0.35f + 0.65f * grey(f.at(x, y));
    if (mask[size_t(y) * f.width + x]) return std::array<float, 3>{0.45f * v + 0.55f, 0.45f * v + 0.2f, 0.45f * v};
    return std::array<float, 3>{v, v, v};
  }));
}

std::vector<unsigned char> albedo_png(const AlbedoField& a, int max_side) {
  Picture p = filtered(a.width, a.height, max_side, [&](int x, int y) {
    const float* c = &a.rgb[(size_t(y) * a.width + x) * 3];
    return std::array<float, 3>{c[0], c[1], c[2]};
  });
  apply_display_view(p.rgb, "Standard");  // linear Rec.709 -> sRGB display, through OCIO
  return png(p);
}

}  // namespace phellem
