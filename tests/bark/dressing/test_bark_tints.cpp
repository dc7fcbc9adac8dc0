// Per-plate and per-crack colour variation of stress bark (bark/dressing/bark_tints.h,
// crack_bark_surface.h): the palette lookup, the plate field's uniform distribution, one tint
// per crack chain, and the shade that multiplies them in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "bark/dressing/bark_tints.h"
#include "bark/dressing/crack_bark_surface.h"
#include "renderer/material.h"
#include "renderer/textures.h"
#include "tests/bark/dressing/cracked_square.h"

using namespace phellem;
using namespace phellem::bark;

namespace {

// Pearson's χ² of `values` in [0, 1] against the uniform distribution, over `bins` bins.
double chi_square_uniform(const std::vector<float>& values, int bins) {
  std::vector<double> count(size_t(bins), 0);
  for (float v : values) count[size_t(std::clamp(int(v * float(bins)), 0, bins - 1))] += 1;
  const double expected = double(values.size()) / bins;
  double chi2 = 0;
  for (double c : count) chi2 += (c - expected) * (c - expected) / expected;
  return chi2;
}

// Points on a lattice two feature sizes apart (nearly independent values), away from the
// region the field's own quantiles were sampled in.
std::vector<Vec3f> spread_points(float size, int n) {
  std::vector<Vec3f> p;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)  // 2.137 sizes apart: not on the noise's lattice, where it is 0
        p.emplace_back(Vec3f(float(i) + 500, float(j) - 300, float(k) + 0.37f) * 2.137f * size);
  return p;
}

// Two cracks: a Y of three chains meeting at vertex 0, and a separate straight crack of two
// edges (one chain) far from it.
CrackedMesh two_cracks() {
  CrackedMesh c;
  c.mesh.positions = {{0, 0, 0},       {0, 0.02, 0},     {0, 0.04, 0},  {-0.02, -0.02, 0}, {0.02, -0.02, 0},
                      {0.1, -0.02, 0}, {0.1, 0.0, 0},    {0.1, 0.02, 0}, {-0.1, -0.1, 0},  {0.2, -0.1, 0},
                      {0.2, 0.1, 0},   {-0.1, 0.1, 0}};
  c.mesh.triangles = {{8, 9, 10}, {8, 10, 11}};
  c.crack_edges = {{0, 1}, {1, 2}, {0, 3}, {0, 4}, {5, 6}, {6, 7}};
  c.crack_width.assign(12, 1.0f);
  c.component.assign(12, 0);
  c.displacement.assign(12, Eigen::Vector3f::Zero());
  return c;
}

const Vec3f kAnywhere(0.3f, 0.7f, 0.1f);

CrackLook narrow_look() {
  CrackLook l;
  l.noise = 0;
  l.min_width = l.max_width = 0.002f;
  l.width_per_edge = 0;
  return l;
}

}  // namespace

TEST(BarkTints, PaletteIsSortedByLuminanceAndInterpolatedBetweenEntryCentres) {
  const TintPalette p({{1.2f, 1.2f, 1.2f}, {0.8f, 0.8f, 0.8f}, {1.0f, 1.0f, 1.0f}});
  EXPECT_FLOAT_EQ(p.tints()[0].x(), 0.8f);
  EXPECT_FLOAT_EQ(p.tints()[2].x(), 1.2f);
  EXPECT_FLOAT_EQ(p.at(0.5f / 3).x(), 0.8f);  // entry centres
  EXPECT_FLOAT_EQ(p.at(1.5f / 3).x(), 1.0f);
  EXPECT_FLOAT_EQ(p.at(2.5f / 3).x(), 1.2f);
  EXPECT_NEAR(p.at(1.0f / 3).x(), 0.9f, 1e-6f);  // half-way between two centres
  EXPECT_FLOAT_EQ(p.at(-4).x(), 0.8f);           // clamped
  EXPECT_FLOAT_EQ(p.at(7).x(), 1.2f);
  EXPECT_FLOAT_EQ(p.at(std::nanf("")).x(), 1.0f);  // NaN: the middle
  EXPECT_TRUE(TintPalette().at(0.3f).isApprox(Eigen::Vector3f::Ones()));
}

TEST(BarkTints, PlatesPickUniformCoordinatesAndBlendContinuouslyAcrossTheirBorders) {
  const float size = 0.04f;
  const TintPlates plates(size, 17);
  std::vector<float> coordinates;
  std::map<float, int> seen;
  int interior = 0;
  for (const Vec3f& p : spread_points(size, 27)) {  // 19683 points, about as many plates
    const TintPlates::Pick k = plates.at(p);
    ASSERT_GE(k.n, 1);
    float total = 0;
    for (int i = 0; i < k.n; ++i) total += k.weight[size_t(i)];
    ASSERT_NEAR(total, 1.0f, 1e-5f);
    if (k.n == 1) ++interior;
    if (seen[k.coordinate[0]]++ == 0) coordinates.push_back(k.coordinate[0]);
  }
  EXPECT_GT(interior, 19683 / 2);  // most points lie inside a plate, away from the border band
  // One coordinate per plate, uniform on [0, 1): χ² with 9 degrees of freedom, 27.9 is the
  // 0.1 % critical value; the same test rejects squared coordinates (it can fail).
  ASSERT_GT(coordinates.size(), 5000u);
  EXPECT_LT(chi_square_uniform(coordinates, 10), 27.9);
  std::vector<float> squared;
  for (float c : coordinates) squared.push_back(c * c);
  EXPECT_GT(chi_square_uniform(squared, 10), 27.9);
  // Continuous: along lines through many plates (and past points where three meet) a
  // two-entry palette's blend never jumps by more than its steepest slope allows.
  const TintPalette ramp({Eigen::Vector3f::Zero(), Eigen::Vector3f::Ones()});
  auto colour = [&](const Vec3f& p) { return plates.at(p).blend([&](float c) { return ramp.pick(c).x(); }); };
  int changes = 0, whole = 0;
  for (int line = 0; line < 20; ++line) {
    const Vec3f start(0, 0.37f * float(line) * size, 0.13f * float(line) * size), step(size / 400, 0, 0);
    float prev = colour(start);
    for (int i = 1; i <= 4000; ++i) {  // 10 plates across
      const float c = colour(start + float(i) * step);
      EXPECT_LT(std::abs(c - prev), 0.05f) << line << " " << i;
      changes += c != prev;
      whole += c == 0 || c == 1;
      prev = c;
    }
  }
  EXPECT_GT(changes, 100);
  EXPECT_GT(whole, 20 * 4000 / 2);
}

TEST(BarkTints, EachCrackChainHasOneCoordinateAndChainsDiffer) {
  const CrackedMesh c = two_cracks();
  const CrackProfile profile(c, narrow_look(), 5);
  const Vec3f n(0, 0, 1);
  auto chain_at = [&](const Vec3f& p) {
    const CrackProfile::Sample s = profile.at(p, n);
    EXPECT_EQ(s.mask, 1.0f);
    return s.chain;
  };
  // The Y's stem is two edges through a vertex of degree 2: one chain.
  const float stem = chain_at({0, 0.01f, 0});
  EXPECT_EQ(chain_at({0, 0.03f, 0}), stem);
  const float left = chain_at({-0.01f, -0.01f, 0}), right = chain_at({0.01f, -0.01f, 0});
  const float other = chain_at({0.1f, -0.01f, 0});
  EXPECT_EQ(chain_at({0.1f, 0.01f, 0}), other);  // the separate crack: one chain
  const std::set<float> distinct{stem, left, right, other};
  EXPECT_EQ(distinct.size(), 4u);  // the junction splits the Y into three chains
  for (float v : distinct) {
    EXPECT_GE(v, 0.0f);
    EXPECT_LT(v, 1.0f);
  }
  // Beside a crack (outside its width, within the look's reach) the point keeps that crack's
  // coordinate, so the colour does not jump at the lip.
  CrackLook wide = narrow_look();
  wide.shoulder_width = 0.004f;  // reach: half-width + shoulder width (no shoulder depth)
  const CrackProfile::Sample beside = CrackProfile(c, wide, 5).at({0.1f + 0.004f, 0.01f, 0}, n);
  EXPECT_EQ(beside.mask, 0.0f);
  EXPECT_EQ(beside.chain, other);
  // Same mesh and seed: the same coordinates; another seed: others.
  EXPECT_EQ(CrackProfile(c, narrow_look(), 5).at({0, 0.01f, 0}, n).chain, stem);
  EXPECT_NE(CrackProfile(c, narrow_look(), 6).at({0, 0.01f, 0}, n).chain, stem);
}

TEST(BarkTints, StressBarkTintsItsPlatesAndCracksAndNothingWithoutTints) {
  CrackLook look = narrow_look();
  look.ridge_tints = {Eigen::Vector3f::Constant(0.5f), Eigen::Vector3f::Constant(1.5f)};
  look.fissure_tints = {Eigen::Vector3f(0.5f, 1.0f, 1.0f), Eigen::Vector3f(1.0f, 0.5f, 0.5f)};  // luminance 0.89, 0.61
  look.darkening = 0;
  const CrackedMesh c = two_cracks();
  const CrackBarkSurface tinted(c, look, 5);
  // In a crack the chain's tint (the palette sorted by luminance), whatever the position.
  EXPECT_TRUE(tinted.shade({0, 1, 0.0f, 0}, kAnywhere).tint.isApprox(Eigen::Vector3f(1.0f, 0.5f, 0.5f)));
  EXPECT_TRUE(tinted.shade({0, 1, 1.0f, 0}, Vec3f(5, 1, 2)).tint.isApprox(Eigen::Vector3f(0.5f, 1.0f, 1.0f)));
  // On the ridges the plate's tint at the position: over 3 m × 2 m the plates take both
  // entries about equally often, most points one of them exactly (inside a plate).
  double sum = 0;
  int count = 0, exact = 0;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 40; ++j) {
      SurfacePoint p;
      p.position = Vec3f(-1 + 3 * float(i) / 59, -1 + 2 * float(j) / 39, 0.013f);
      const BarkDisplacement d = tinted.displace(p);
      if (d.attributes.y() > 0) continue;
      const Eigen::Vector3f t = tinted.shade(d.attributes, p.position).tint;
      ASSERT_GE(t.x(), 0.5f - 1e-6f);
      ASSERT_LE(t.x(), 1.5f + 1e-6f);
      sum += t.x();
      exact += std::abs(t.x() - 0.5f) < 1e-6f || std::abs(t.x() - 1.5f) < 1e-6f;
      ++count;
      // Half-way into a crack: half the plate's tint, half the crack's.
      const Eigen::Vector3f half = tinted.shade({0, 0.5f, 0.0f, 0}, p.position).tint;
      ASSERT_TRUE(half.isApprox(0.5f * t + 0.5f * Eigen::Vector3f(1.0f, 0.5f, 0.5f))) << i << " " << j;
    }
  EXPECT_NEAR(sum / count, 1.0, 0.1);
  EXPECT_GT(exact, count / 2);
  // Colours from a photo: ridge and fissure colours × their tints.
  look.colored = true;
  look.ridge_color = Eigen::Vector3f(0.4f, 0.3f, 0.2f);
  look.fissure_color = Eigen::Vector3f(0.2f, 0.1f, 0.1f);
  look.darkening = 0.5f;
  const CrackBarkSurface photo(c, look, 5);
  const BarkShade fissure = photo.shade({1, 1, 0.0f, 0}, kAnywhere);
  EXPECT_TRUE(fissure.replaces_albedo);
  EXPECT_TRUE(fissure.albedo.isApprox(Eigen::Vector3f(0.2f, 0.05f, 0.05f) * 0.5f));  // × (1 − darkening)
  const BarkShade ridge = photo.shade({0, 0, 0.0f, 0}, kAnywhere);
  const float k = ridge.albedo.x() / 0.4f;
  EXPECT_TRUE(ridge.albedo.isApprox(k * Eigen::Vector3f(0.4f, 0.3f, 0.2f)));
  EXPECT_GE(k, 0.5f - 1e-6f);
  EXPECT_LE(k, 1.5f + 1e-6f);
  // No tints: white, wherever and whatever the coordinates.
  const CrackBarkSurface plain(c, narrow_look(), 5);
  EXPECT_TRUE(plain.shade({0.3f, 0.5f, 0.9f, 0}, kAnywhere).tint.isApprox(Eigen::Vector3f::Ones()));
}

TEST(BarkTints, RoughnessNoiseFollowsThePlatesAndCracks) {
  CrackLook look = narrow_look();
  look.roughness.ridge = 0.8f;
  look.roughness.fissure = 0.5f;
  look.roughness.noise = 0.25f;
  const CrackBarkSurface s(two_cracks(), look, 5);
  EXPECT_NEAR(s.shade({0, 1, 0.5f, 0}, kAnywhere).roughness, 0.5f, 1e-6f);  // chain coordinate ½: no change
  EXPECT_NEAR(s.shade({0, 1, 0.0f, 0}, kAnywhere).roughness, 0.5f * 0.75f, 1e-6f);
  std::set<float> values;
  for (int i = 0; i < 100; ++i) {
    const float r = s.shade({0, 0, 0, 0}, Vec3f(0.011f * float(i), 0.5f, 0)).roughness;
    EXPECT_GE(r, 0.8f * 0.75f - 1e-6f);
    EXPECT_LE(r, 0.8f * 1.25f + 1e-6f);
    values.insert(r);
  }
  EXPECT_GT(values.size(), 10u);  // about 27 plates along the line
  look.roughness.noise = 0;
  const CrackBarkSurface flat(two_cracks(), look, 5);
  EXPECT_NEAR(flat.shade({0, 0, 0, 0}, kAnywhere).roughness, 0.8f, 1e-6f);
}

TEST(BarkTints, TheMaterialMultipliesItsBaseColourPerChannel) {
  Material m;
  m.type = MaterialType::Diffuse;
  m.base = Color(0.5f, 0.5f, 0.5f);
  TextureStore textures;
  ShadingInput in{{0, 0}, 0.0f};
  in.base_scale = Color(1.2f, 0.8f, 0.5f);
  const BSDF b = evaluate_bsdf(m, textures, in, nullptr);
  EXPECT_NEAR(b.base.x(), 0.6f, 1e-6f);
  EXPECT_NEAR(b.base.y(), 0.4f, 1e-6f);
  EXPECT_NEAR(b.base.z(), 0.25f, 1e-6f);
}
