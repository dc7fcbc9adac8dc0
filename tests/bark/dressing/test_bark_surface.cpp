// BarkSurface (bark/dressing/bark_surface.h), the one interface both bark models render
// through: strip bark's dressed field and a cracked mesh's V-profiles each displace a point
// inwards by their depth, hand back the attributes the dicer keeps, and shade from them.
#include <gtest/gtest.h>

#include "tests/bark/dressing/cracked_square.h"

#include <memory>

#include "bark/dressing/crack_bark_surface.h"
#include "bark/dressing/field_bark_surface.h"

using namespace phellem;
using namespace phellem::bark;

namespace {

FractureField ramp_field() {
  FractureField f;
  f.width = 4;
  f.height = 2;
  f.length = 1;
  const size_t n = 8;
  f.opening.assign(n, 1.0f);
  f.depth.resize(n);
  f.color.assign(3 * n, 0.25f);
  for (size_t p = 0; p < n; ++p) f.depth[p] = 0.002f * float(p);
  return f;
}

using test::cracked_square;

}  // namespace

TEST(BarkSurface, StripBarkDisplacesInwardsByTheFieldDepthAndShadesFromItsOwnParameters) {
  const FractureField f = ramp_field();
  const std::unique_ptr<BarkSurface> s = std::make_unique<FieldBarkSurface>(f, 0.02);
  SurfacePoint p;
  p.param = Eigen::Vector2d(2.5 / 4, 1.5 / 2);  // texel (2, 1)'s centre
  const BarkDisplacement d = s->displace(p);
  EXPECT_FLOAT_EQ(d.offset, -f.depth[f.index(2, 1)]);
  EXPECT_FLOAT_EQ(d.attributes.x(), 2.5f / 4);
  EXPECT_FLOAT_EQ(d.attributes.y(), 1.5f / 2);
  const BarkShade sh = s->shade(d.attributes, p.position);
  EXPECT_TRUE(sh.replaces_albedo);
  EXPECT_FLOAT_EQ(sh.depth, f.depth[f.index(2, 1)] / 0.02f);
  EXPECT_FLOAT_EQ(sh.mask, 1.0f);
  EXPECT_FLOAT_EQ(sh.albedo.x(), 0.25f);
  EXPECT_FLOAT_EQ(sh.albedo_scale, 1.0f);
}

TEST(BarkSurface, CrackedMeshDisplacesByTheVProfileAndDarkensWithDepth) {
  CrackLook look;
  look.min_width = 0.002f;
  look.width_per_edge = 0.0f;
  look.max_width = 0.002f;  // half-width 2 mm
  look.depth_per_width = 2.0f;
  look.max_depth = 0.004f;  // depth 4 mm on the crack
  look.noise = 0;
  look.darkening = 0.5f;
  const CrackedMesh c = cracked_square();
  const std::unique_ptr<BarkSurface> s = std::make_unique<CrackBarkSurface>(c, look, 1);
  SurfacePoint on, half, off;
  on.position = Eigen::Vector3f(0, 0, 0);
  half.position = Eigen::Vector3f(0.001f, 0, 0);  // half-way across the half-width
  off.position = Eigen::Vector3f(0.02f, 0, 0);
  const BarkDisplacement d_on = s->displace(on), d_half = s->displace(half), d_off = s->displace(off);
  EXPECT_NEAR(d_on.offset, -0.004f, 1e-6f);
  EXPECT_NEAR(d_half.offset, -0.002f, 1e-5f);  // V-profile: linear in the distance
  EXPECT_EQ(d_off.offset, 0.0f);
  EXPECT_NEAR(d_on.attributes.x(), 1.0f, 1e-5f);  // normalized depth
  EXPECT_EQ(d_on.attributes.y(), 1.0f);           // inside the crack
  EXPECT_EQ(d_off.attributes.y(), 0.0f);
  const BarkShade sh = s->shade(Eigen::Vector4f(0.5f, 1.0f, 0.5f, 0.0f), Eigen::Vector3f::Zero());
  EXPECT_FALSE(sh.replaces_albedo);
  EXPECT_FLOAT_EQ(sh.depth, 0.5f);
  EXPECT_FLOAT_EQ(sh.mask, 1.0f);
  EXPECT_FLOAT_EQ(sh.albedo_scale, 1.0f - 0.5f * 0.5f);
  // The dicer refines only edges the cracks reach.
  EXPECT_TRUE(s->reaches(Eigen::Vector3f(-0.01f, 0, 0), Eigen::Vector3f(0.01f, 0, 0)));
  EXPECT_FALSE(s->reaches(Eigen::Vector3f(0.03f, -0.01f, 0), Eigen::Vector3f(0.03f, 0.01f, 0)));
}
