// A grown surface's texture cell levels in the renderer's texture lookups (renderer/material.h;
// Kratt et al., Woodification, sec. 4.6): level L along an axis repeats the texture 2^L times
// over the same texture coordinates; fractional levels blend the two around them.
#include <gtest/gtest.h>

#include "renderer/material.h"

namespace phellem {
namespace {

Color base_at(const Material& m, const TextureStore& t, const Vec2f& uv, const Vec2f& levels) {
  ShadingInput in{uv, 0.0f};
  in.texture_levels = levels;
  return evaluate_bsdf(m, t, in, nullptr).base;
}

TEST(TextureLevels, WholeLevelsRepeatTheTextureAndFractionalOnesBlendTheTwoAroundThem) {
  TextureStore textures;
  TextureDesc d;
  d.procedural = "bark";
  d.color_a = Color(0.9f, 0.6f, 0.3f);
  d.color_b = Color(0.05f, 0.1f, 0.2f);
  d.scale = Vec2f(3, 5);
  Material m;
  m.base = Color::Ones();
  m.base_tex = textures.add(d, {"scene.json", "/materials/bark/base_color_texture"});
  ASSERT_GE(m.base_tex, 0);
  const auto tex = [&](float u, float v) { return Color(textures.rgb(m.base_tex, Vec2f(u, v), 0.0f).min(1.0f)); };
  const Vec2f uv(0.3125f, 0.4375f);
  // Level 0 is the texture as it is; the pattern is not constant (else nothing here could fail).
  EXPECT_TRUE(base_at(m, textures, uv, {0, 0}).isApprox(tex(uv.x(), uv.y()), 1e-6f));
  ASSERT_GT((tex(uv.x(), uv.y()) - tex(2 * uv.x(), uv.y())).abs().maxCoeff(), 0.02f);
  // Whole levels: the texture at 2^L times the coordinates, per axis.
  EXPECT_TRUE(base_at(m, textures, uv, {1, 0}).isApprox(tex(2 * uv.x(), uv.y()), 1e-5f));
  EXPECT_TRUE(base_at(m, textures, uv, {0, 2}).isApprox(tex(uv.x(), 4 * uv.y()), 1e-5f));
  EXPECT_TRUE(base_at(m, textures, uv, {3, 1}).isApprox(tex(8 * uv.x(), 2 * uv.y()), 1e-5f));
  // A fractional level: the two levels around it, weighted by the fraction, along each axis.
  const Color quarter = 0.75f * tex(uv.x(), uv.y()) + 0.25f * tex(2 * uv.x(), uv.y());
  EXPECT_TRUE(base_at(m, textures, uv, {0.25f, 0}).isApprox(quarter, 1e-5f));
  const Color both = 0.5f * 0.8f * tex(2 * uv.x(), uv.y()) + 0.5f * 0.2f * tex(2 * uv.x(), 2 * uv.y()) +
                     0.5f * 0.8f * tex(4 * uv.x(), uv.y()) + 0.5f * 0.2f * tex(4 * uv.x(), 2 * uv.y());
  EXPECT_TRUE(base_at(m, textures, uv, {1.5f, 0.2f}).isApprox(both, 1e-5f));
  // Continuous across a whole level: just below level 1 is (almost) level 1.
  EXPECT_TRUE(base_at(m, textures, uv, {0.99999f, 0}).isApprox(base_at(m, textures, uv, {1, 0}), 1e-3f));
}

}  // namespace
}  // namespace phellem
