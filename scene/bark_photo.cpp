#include "scene/bark_photo.h"

#include <algorithm>
#include <cmath>

#include "io/image_output.h"
#include "scene/json_reader.h"
#include "scene/scene_image.h"

namespace phellem {

namespace {

constexpr size_t kMaxTints = 64;

float luminance(const Eigen::Vector3f& c) { return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z(); }

struct Group {
  Eigen::Vector3d sum{0, 0, 0};
  double lum = 0, lum2 = 0, count = 0;
  void add(const Eigen::Vector3f& c) {
    sum += c.cast<double>();
    const double l = luminance(c);
    lum += l, lum2 += l * l, ++count;
  }
  Eigen::Vector3f mean() const { return count > 0 ? Eigen::Vector3f((sum / count).cast<float>()) : Eigen::Vector3f::Zero(); }
  float variation() const {
    if (count == 0 || lum <= 0) return 0;
    const double m = lum / count;
    return float(std::sqrt(std::max(0.0, lum2 / count - m * m)) / m);
  }
};

// Tints: the mean colour of each patch (`patch` px square) that is at least 30 % of the group,
// relative to the group's mean, pulled towards 1 by `strength`; at most kMaxTints, evenly picked.
std::vector<Eigen::Vector3f> tints(const std::vector<float>& rgb, const std::vector<char>& in, int W, int H, int patch,
                                   const Eigen::Vector3f& mean, float strength) {
  std::vector<Eigen::Vector3f> all;
  for (int y0 = 0; y0 + patch <= H; y0 += patch)
    for (int x0 = 0; x0 + patch <= W; x0 += patch) {
      Group g;
      for (int y = y0; y < y0 + patch; ++y)
        for (int x = x0; x < x0 + patch; ++x) {
          const size_t p = size_t(y) * W + x;
          if (in[p]) g.add(Eigen::Vector3f(rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]));
        }
      if (g.count < 0.3 * patch * patch) continue;  // mostly of the group
      const Eigen::Vector3f t = g.mean().cwiseQuotient(mean.cwiseMax(1e-6f));
      all.push_back(Eigen::Vector3f::Ones() + strength * (t - Eigen::Vector3f::Ones()));
    }
  if (all.size() <= kMaxTints) return all;
  std::vector<Eigen::Vector3f> out;
  for (size_t i = 0; i < kMaxTints; ++i) out.push_back(all[i * all.size() / kMaxTints]);
  return out;
}

}  // namespace

BarkPhoto read_bark_photo(JsonObject o, const std::string& base_dir) {
  const JsonValue albedo_v = o.at("albedo"), height_v = o.at("height");
  const float px_per_cm = o.at("px_per_cm").positive();
  const float ridge_above = o.number("ridge_above", 0.6f), fissure_below = o.number("fissure_below", 0.25f);
  if (!(ridge_above > 0 && ridge_above < 1)) o.fail("ridge_above", "ridge_above must lie in (0, 1) (a height percentile)");
  if (!(fissure_below > 0 && fissure_below < 1)) o.fail("fissure_below", "fissure_below must lie in (0, 1) (a height percentile)");
  if (fissure_below >= ridge_above) o.fail("fissure_below", "fissure_below must be below ridge_above");
  const float strength = o.number("tints", 1.0f);
  if (!(strength >= 0 && strength <= 2)) o.fail("tints", "tints must lie in [0, 2] (0: no per-plate colour variation)");
  o.finish();

  SceneImage a = read_scene_image(albedo_v, base_dir);
  const SceneImage h = read_scene_image(height_v, base_dir);
  if (a.width != h.width || a.height != h.height)
    height_v.fail("the height map is " + std::to_string(h.width) + "×" + std::to_string(h.height) + ", the albedo " +
                  std::to_string(a.width) + "×" + std::to_string(a.height) + ": they must match pixel for pixel");
  const int W = a.width, H = a.height;
  const size_t n = size_t(W) * H;
  std::vector<float> rgb(3 * n);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) rgb[3 * i + size_t(c)] = std::max(0.0f, a.pixels[i * size_t(a.channels) + size_t(std::min(c, a.channels - 1))]);
  if (a.encoded) srgb_texture_to_linear(rgb.data(), long(n), 3);
  for (float v : rgb)
    if (!std::isfinite(v)) albedo_v.fail("image " + a.path + " holds a non-finite value");
  std::vector<float> z(n);
  for (size_t i = 0; i < n; ++i) z[i] = h.pixels[i * size_t(h.channels)];
  std::vector<float> sorted = z;
  std::sort(sorted.begin(), sorted.end());
  const float hi = sorted[size_t(ridge_above * float(n - 1))], lo = sorted[size_t(fissure_below * float(n - 1))];
  if (!(hi > lo)) height_v.fail("the height map " + h.path + " is flat between its percentiles: no ridges and fissures to tell apart");

  std::vector<char> ridge(n), fissure(n);
  Group gr, gf;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f c(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
    if ((ridge[i] = z[i] >= hi)) gr.add(c);
    if ((fissure[i] = z[i] <= lo)) gf.add(c);
  }
  BarkPhoto p;
  p.ridge = gr.mean();
  p.fissure = gf.mean();
  p.ridge_variation = gr.variation();
  p.fissure_variation = gf.variation();
  const int patch = std::max(1, int(std::lround(px_per_cm)));  // 1 cm patches
  p.ridge_tints = tints(rgb, ridge, W, H, patch, p.ridge, strength);
  p.fissure_tints = tints(rgb, fissure, W, H, patch, p.fissure, strength);
  return p;
}

}  // namespace phellem
