// The bark look of issue 22 at the BarkSurface: colours per ridge and fissure, per-fracture
// tints, roughness that varies with the surface (and reaches the BSDF), the stress bark's
// shoulder, and the defaults that leave every old output as it was.
#include <gtest/gtest.h>

#include "tests/bark/dressing/cracked_square.h"

#include <cmath>
#include <set>

#include "bark/dressing/crack_bark_surface.h"
#include "bark/dressing/field_bark_surface.h"
#include "bark/dressing/field_color.h"
#include "renderer/material.h"

using namespace phellem;
using namespace phellem::bark;

namespace {

// 64 × 16 pixels, two fractures (ids 1 and 2) of 8 columns each.
FractureField two_fractures() {
  FractureField f;
  f.width = 64;
  f.height = 16;
  f.circumference = 0.2;
  f.length = 0.05;
  const size_t n = size_t(f.width) * f.height;
  f.opening.assign(n, 0), f.depth.assign(n, 0), f.uv0.assign(2 * n, 0), f.interior.assign(n, 0);
  f.fracture_id.assign(n, 0), f.age.assign(n, 0), f.level.assign(n, 0), f.color.assign(3 * n, 0);
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const size_t p = f.index(x, y);
      f.uv0[2 * p] = float((x + 0.5) / f.width);
      f.uv0[2 * p + 1] = float((y + 0.5) / f.height);
      const int id = x >= 10 && x < 18 ? 1 : x >= 40 && x < 48 ? 2 : 0;
      if (id == 0) continue;
      f.opening[p] = 1;
      f.fracture_id[p] = float(id);
      f.depth[p] = 0.005f;
    }
  return f;
}

FieldColors red_ridges_blue_fissures() {
  FieldColors c;
  c.epidermis = ColorSample::procedural({0.6f, 0.0f, 0.0f}, 0.0f, 0.004, 1);
  c.hardened = c.epidermis;
  c.fracture = ColorSample::procedural({0.0f, 0.0f, 0.6f}, 0.0f, 0.004, 2);
  c.depth_darkening = 0;
  c.interior_darkening = 0;
  return c;
}

}  // namespace

TEST(BarkLook, RidgesTakeTheRidgeColourAndFissuresTheirOwn) {
  FractureField f = two_fractures();
  dress_colors(f, red_ridges_blue_fissures(), 0.01, f.circumference);
  const FieldBarkSurface s(f, 0.01);
  const BarkShade ridge = s.shade_at(30.5 / 64, 0.5), fissure = s.shade_at(13.5 / 64, 0.5);
  EXPECT_NEAR(ridge.albedo.x(), 0.6f, 1e-6f);
  EXPECT_NEAR(ridge.albedo.z(), 0.0f, 1e-6f);
  EXPECT_NEAR(fissure.albedo.z(), 0.6f, 1e-6f);
  EXPECT_NEAR(fissure.albedo.x(), 0.0f, 1e-6f);
}

TEST(BarkLook, EachFractureKeepsOneTintAndPlatesVary) {
  FractureField f = two_fractures();
  FieldColors c = red_ridges_blue_fissures();
  for (int i = 0; i < 16; ++i) {
    c.fissure_tints.push_back(Eigen::Vector3f::Constant(0.5f + 0.06f * float(i)));
    c.ridge_tints.push_back(Eigen::Vector3f::Constant(0.5f + 0.06f * float(i)));
  }
  c.tint_size = 0.02;
  dress_colors(f, c, 0.01, f.circumference);
  std::set<float> per_fracture[3], ridge;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const size_t p = f.index(x, y);
      if (f.opening[p] > 0)
        per_fracture[int(f.fracture_id[p])].insert(f.color[3 * p + 2]);
      else
        ridge.insert(f.color[3 * p]);
    }
  EXPECT_EQ(per_fracture[1].size(), 1u);  // one tint over the whole fracture
  EXPECT_EQ(per_fracture[2].size(), 1u);
  EXPECT_GT(ridge.size(), 4u);  // the plates' tints vary over their material coordinate
  for (float r : ridge) EXPECT_TRUE(r >= 0.6f * 0.5f - 1e-5f && r <= 0.6f * 1.4f + 1e-5f) << r;
}

TEST(BarkLook, RoughnessOfRidgesAndFissuresIsWhatIsAsked) {
  FractureField f = two_fractures();
  FieldColors c = red_ridges_blue_fissures();
  c.roughness.ridge = 0.85f;
  c.roughness.fissure = 0.4f;
  dress_colors(f, c, 0.01, f.circumference);
  const FieldBarkSurface s(f, 0.01);
  EXPECT_NEAR(s.shade_at(30.5 / 64, 0.5).roughness, 0.85f, 1e-6f);
  EXPECT_NEAR(s.shade_at(13.5 / 64, 0.5).roughness, 0.4f, 1e-6f);
  // With noise: within ± noise of the ridge value, and not constant.
  c.roughness.noise = 0.2f;
  c.roughness.noise_size = 0.005;
  FractureField g = two_fractures();
  dress_colors(g, c, 0.01, g.circumference);
  std::set<float> values;
  for (int x = 20; x < 38; ++x) {
    const float r = g.roughness[g.index(x, 8)];
    EXPECT_GE(r, 0.85f * 0.8f - 1e-6f);
    EXPECT_LE(r, 0.85f * 1.2f + 1e-6f);
    values.insert(r);
  }
  EXPECT_GT(values.size(), 3u);
  // The path tracer's BSDF takes it: α = roughness².
  Material m;
  m.type = MaterialType::Bark;
  m.roughness = 0.3f;
  TextureStore textures;
  ShadingInput in{{0, 0}, 0.0f};
  EXPECT_NEAR(evaluate_bsdf(m, textures, in, nullptr).alpha, 0.09f, 1e-6f);
  in.roughness_override = 0.85f;
  EXPECT_NEAR(evaluate_bsdf(m, textures, in, nullptr).alpha, 0.85f * 0.85f, 1e-6f);
}

TEST(BarkLook, DefaultsLeaveTheShadeAsBefore) {
  FractureField f = two_fractures();
  dress_colors(f, FieldColors{}, 0.01, f.circumference);
  EXPECT_TRUE(f.roughness.empty());
  const FieldBarkSurface s(f, 0.01);
  EXPECT_EQ(s.shade_at(0.3, 0.5).roughness, -1.0f);
  EXPECT_EQ(s.memory_bytes(), size_t(64 * 16) * 5 * sizeof(float));
}

using test::cracked_square;

TEST(BarkLook, StressBarkRoundsDownTowardsTheCrackAndShadesItsRoughness) {
  CrackLook look;
  look.noise = 0;
  const CrackBarkSurface plain(cracked_square(), look, 3);
  look.shoulder = 0.5f;
  look.shoulder_width = 0.01f;
  look.roughness.ridge = 0.9f;
  look.roughness.fissure = 0.5f;
  const CrackBarkSurface relief(cracked_square(), look, 3);
  const float w = look.min_width + look.width_per_edge;  // the crack's half-width
  float prev = 1e9f;
  for (int i = 1; i <= 12; ++i) {
    SurfacePoint p;
    p.position = Eigen::Vector3f(w + 0.001f * float(i), 0.01f, 0);
    const float depth = -relief.displace(p).offset;
    EXPECT_EQ(plain.displace(p).offset, 0.0f);
    if (i < 10) {
      EXPECT_LT(depth, prev) << i;  // rising away from the lip
    } else {
      EXPECT_NEAR(depth, 0.0f, 1e-7f) << i;
    }
    prev = depth;
  }
  // Inside the crack the shoulder's full drop adds to the V.
  SurfacePoint c;
  c.position = Eigen::Vector3f(0, 0.01f, 0);
  EXPECT_NEAR(-relief.displace(c).offset, -plain.displace(c).offset + 0.5f * look.max_depth, 1e-6f);
  EXPECT_NEAR(relief.shade({0.5f, 1.0f, 0.5f, 0.5f}, Eigen::Vector3f::Zero()).roughness, 0.5f, 1e-6f);
  EXPECT_NEAR(relief.shade({0.0f, 0.0f, 0.5f, 0.5f}, Eigen::Vector3f::Zero()).roughness, 0.9f, 1e-6f);
  EXPECT_EQ(plain.shade({0.5f, 1.0f, 0.5f, 0.5f}, Eigen::Vector3f::Zero()).roughness, -1.0f);
  EXPECT_FALSE(plain.shade({0.5f, 1.0f, 0.5f, 0.5f}, Eigen::Vector3f::Zero()).replaces_albedo);
}
