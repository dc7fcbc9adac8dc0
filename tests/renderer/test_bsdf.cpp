// BSDF invariants: reciprocity, energy conservation, known values of the building blocks.
#include <gtest/gtest.h>

#include <random>

#include "renderer/bsdf.h"
#include "renderer/sampling.h"

namespace phellem {
namespace {

Vec3f random_dir(std::mt19937& rng, bool upper) {
  std::uniform_real_distribution<float> u(0, 1);
  Vec3f w = sample_uniform_sphere(Vec2f(u(rng), u(rng)));
  if (upper) w.z() = std::abs(w.z()) + 1e-3f;
  return w.normalized();
}

std::vector<std::pair<const char*, BSDF>> reflective() {
  std::vector<std::pair<const char*, BSDF>> v;
  BSDF d;
  d.type = BSDF::Type::Diffuse;
  d.base = Color(0.8f, 0.5f, 0.2f);
  v.push_back({"diffuse", d});
  BSDF b;
  b.type = BSDF::Type::Bark;
  b.base = Color(0.5f, 0.4f, 0.3f);
  b.alpha = 0.2f;
  b.f0 = 0.04f;
  v.push_back({"bark", b});
  BSDF k;
  k.type = BSDF::Type::Conductor;
  k.base = Color(0.95f, 0.7f, 0.5f);
  k.alpha = 0.35f;
  v.push_back({"conductor", k});
  return v;
}

TEST(BSDF, ReflectionIsReciprocal) {
  std::mt19937 rng(3);
  for (auto& [name, b] : reflective())
    for (int i = 0; i < 2000; ++i) {
      const Vec3f wo = random_dir(rng, true), wi = random_dir(rng, true);
      const Color a = b.eval(wo, wi), c = b.eval(wi, wo);
      for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(a[ch], c[ch], 1e-4f * std::max(1.0f, a[ch])) << name;
    }
}

TEST(BSDF, DielectricTransmissionObeysGeneralizedReciprocity) {
  // f(wo, wi) / η_i² = f(wi, wo) / η_o² for radiance transport (Veach 1997, eq. 5.14).
  BSDF g;
  g.type = BSDF::Type::Dielectric;
  g.alpha = 0.3f;
  g.eta = 1.5f;
  std::mt19937 rng(5);
  int checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3f wo = random_dir(rng, true);
    Vec3f wi = random_dir(rng, true);
    wi.z() = -wi.z();
    const float a = g.eval(wo, wi)[0], c = g.eval(wi, wo)[0];
    if (a < 1e-4f) continue;
    // wo outside (η=1), wi inside (η=1.5).
    EXPECT_NEAR(a * 1.5f * 1.5f, c, 2e-3f * std::max(1.0f, c));
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

// Directional albedo ∫ f cos dωi by importance sampling.
// With `undo_radiance_scaling`, transmitted samples are multiplied back by η² so the sum is
// the fraction of energy reflected plus transmitted.
Color albedo(const BSDF& b, const Vec3f& wo, int n = 200000, bool undo_radiance_scaling = false) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0, 1);
  Color sum = Color::Zero();
  for (int i = 0; i < n; ++i) {
    auto s = b.sample(wo, u(rng), Vec2f(u(rng), u(rng)));
    if (!s || !(s->pdf > 0)) continue;
    const float k = undo_radiance_scaling && s->wi.z() * wo.z() < 0 ? s->eta * s->eta : 1.0f;
    sum += s->f * std::abs(s->wi.z()) / s->pdf * k;
  }
  return sum / float(n);
}

TEST(BSDF, EnergyNeverExceedsOne) {
  for (float cos_o : {1.0f, 0.7f, 0.3f, 0.08f}) {
    const Vec3f wo(std::sqrt(1 - cos_o * cos_o), 0, cos_o);
    BSDF white;
    white.type = BSDF::Type::Bark;
    white.base = Color::Ones();
    white.alpha = 0.1f;
    white.f0 = 0.08f;
    EXPECT_LE(albedo(white, wo).maxCoeff(), 1.0f + 5e-3f) << "bark cos " << cos_o;
    BSDF mirror;
    mirror.type = BSDF::Type::Conductor;
    mirror.base = Color::Ones();
    for (float a : {0.0f, 0.05f, 0.5f, 1.0f}) {
      mirror.alpha = a;
      const Color e = albedo(mirror, wo);
      EXPECT_LE(e.maxCoeff(), 1.0f + 5e-3f) << "conductor α " << a << " cos " << cos_o;
      if (a == 0.0f) {
        EXPECT_NEAR(e[0], 1.0f, 1e-4f);
      }
    }
    BSDF glass;
    glass.type = BSDF::Type::Dielectric;
    glass.eta = 1.5f;
    for (float a : {0.0f, 0.1f, 0.6f}) {
      glass.alpha = a;
      const float e = albedo(glass, wo, 200000, true)[0];
      EXPECT_LE(e, 1.0f + 5e-3f) << "dielectric α " << a;
      EXPECT_GT(e, a == 0.0f ? 0.999f : 0.8f) << "dielectric α " << a;  // single scattering loses a little
    }
  }
}

// Bark with specular 0 (F0 = F90 = 0) must be exactly Lambertian: no grazing coat, no
// darkening of the base by (1 − F) — the glTF KHR_materials_specular specularFactor 0 case.
TEST(BSDF, BarkWithoutSpecularIsLambertian) {
  BSDF b;
  b.type = BSDF::Type::Bark;
  b.base = Color(0.6f, 0.4f, 0.2f);
  b.alpha = 0.3f;
  b.f0 = 0.0f;
  b.f90 = 0.0f;
  for (float co : {1.0f, 0.7f, 0.2f, 0.02f})
    for (float ci : {1.0f, 0.5f, 0.05f}) {
      const Vec3f wo(std::sqrt(1 - co * co), 0, co), wi(-0.3f * std::sqrt(1 - ci * ci), 0.95f * std::sqrt(1 - ci * ci), ci);
      const Vec3f win = wi.normalized();
      const Color f = b.eval(wo, win);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], b.base[c] * kInvPi, 1e-6f) << "cos_o " << co << " cos_i " << ci;
      EXPECT_NEAR(b.pdf(wo, win), win.z() * kInvPi, 1e-6f);
    }
  // With the default specular 0.5 (F0 0.04, F90 1) grazing light is partly reflected by the coat.
  b.f0 = 0.04f;
  b.f90 = 1.0f;
  const Vec3f wo(std::sqrt(1 - 0.05f * 0.05f), 0, 0.05f), wi(-std::sqrt(1 - 0.05f * 0.05f), 0, 0.05f);
  EXPECT_LT(b.eval(wo, Vec3f(0, 0, 1))[0], b.base[0] * kInvPi * 0.9f);
  EXPECT_GT(b.eval(wo, wi)[0], 0.0f);
}

TEST(BSDF, SmoothDielectricSplitsByFresnel) {
  BSDF g;
  g.type = BSDF::Type::Dielectric;
  g.alpha = 0;
  g.eta = 1.5f;
  // Normal incidence: R = ((1.5-1)/(1.5+1))² = 0.04.
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(fresnel_dielectric(-1.0f, 1.5f), 0.04f, 1e-6f);
  // Beyond the critical angle from inside: total internal reflection.
  EXPECT_EQ(fresnel_dielectric(-0.3f, 1.5f), 1.0f);
  auto r = g.sample(Vec3f(0, 0, 1), 0.01f, Vec2f(0.5f, 0.5f));
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->delta);
  EXPECT_GT(r->wi.z(), 0.99f);
  auto t = g.sample(Vec3f(0, 0, 1), 0.5f, Vec2f(0.5f, 0.5f));
  ASSERT_TRUE(t);
  EXPECT_LT(t->wi.z(), -0.99f);
}

TEST(GGX, DistributionIsNormalized) {
  // ∫ D(m) cos θm dωm = 1 over the hemisphere.
  for (float alpha : {0.05f, 0.3f, 0.9f}) {
    const GGX ggx(alpha);
    double sum = 0;
    const int nt = 4000;
    for (int i = 0; i < nt; ++i) {
      const double theta = (i + 0.5) / nt * M_PI / 2;
      const Vec3f m(float(std::sin(theta)), 0, float(std::cos(theta)));
      sum += ggx.D(m) * std::cos(theta) * std::sin(theta) * (M_PI / 2 / nt) * 2 * M_PI;
    }
    EXPECT_NEAR(sum, 1.0, 2e-3) << alpha;
  }
}

TEST(GGX, VisibleNormalsIntegrateToOne) {
  // ∫ D_wo(m) dm = 1 (Heitz 2014, eq. 16) for several view directions.
  const GGX ggx(0.4f);
  for (float cos_o : {0.95f, 0.5f, 0.1f}) {
    const Vec3f wo(std::sqrt(1 - cos_o * cos_o), 0, cos_o);
    double sum = 0;
    const int n = 400;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < 2 * n; ++j) {
        const double z = (i + 0.5) / n, phi = (j + 0.5) / (2 * n) * 2 * M_PI;
        const double s = std::sqrt(1 - z * z);
        const Vec3f m(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z));
        if (wo.dot(m) > 0) sum += ggx.visible_pdf(wo, m) * (1.0 / n) * (2 * M_PI / (2 * n));
      }
    EXPECT_NEAR(sum, 1.0, 5e-3) << cos_o;
  }
}

}  // namespace
}  // namespace phellem
