// Chi-square tests of every sampling routine against the pdf it claims (STYLE.md, 7).
#include <gtest/gtest.h>

#include "renderer/bsdf.h"
#include "renderer/light.h"
#include "renderer/sampling.h"
#include "tests/support/chi2.h"

namespace phellem {
namespace {

using test::chi2_sphere;
// Bonferroni-corrected significance: ~14 chi-square tests in this file at 1% overall.
constexpr double kAlpha = 0.01 / 14;

TEST(Chi2, GammaQMatchesKnownValues) {
  // Q(1, x) = exp(-x); chi-square with 2 dof at 5.991 has p = 0.05.
  EXPECT_NEAR(test::gamma_q(1.0, 2.0), std::exp(-2.0), 1e-12);
  EXPECT_NEAR(test::gamma_q(1.0, 5.991 / 2), 0.05, 1e-4);
  EXPECT_NEAR(test::gamma_q(5.0, 5.0), 0.44049, 1e-5);
}

TEST(Chi2, DetectsAWrongPdf) {
  // Cosine samples tested against a uniform-hemisphere pdf must fail.
  auto r = chi2_sphere([](const Vec2f& u) { return std::optional<Vec3f>(sample_cosine_hemisphere(u)); },
                       [](const Vec3f& w) { return w.z() > 0 ? 1.0f / kTwoPi : 0.0f; }, 200000);
  EXPECT_LT(r.p_value, 1e-6) << r.summary();
}

TEST(Chi2, CosineHemisphere) {
  auto r = chi2_sphere([](const Vec2f& u) { return std::optional<Vec3f>(sample_cosine_hemisphere(u)); },
                       [](const Vec3f& w) { return cosine_hemisphere_pdf(w.z()); });
  EXPECT_GT(r.p_value, kAlpha) << r.summary();
  EXPECT_NEAR(r.pdf_integral, 1.0, 1e-3);
}

TEST(Chi2, UniformConeSunDisk) {
  // A wide cone so that bins resolve it; the same code samples the 0.53° sun. The cone's
  // edge (cos = 0.9) lies on a bin boundary so that bin integrals of the discontinuous pdf
  // are exact.
  const float cos_max = 0.9f;
  const float angle_deg = 2.0f * std::acos(cos_max) * 180.0f / kPi;
  const SunLight sun(Vec3f(0, 0, 1), 1.0f, angle_deg, Color::Ones());
  auto r = chi2_sphere([&](const Vec2f& u) -> std::optional<Vec3f> { return sun.sample(Vec3f::Zero(), u)->wi; },
                       [&](const Vec3f& w) { return sun.pdf(w); }, 1'000'000, 80, 160);
  EXPECT_GT(r.p_value, kAlpha) << r.summary();
  EXPECT_NEAR(r.pdf_integral, 1.0, 2e-3);
  // A tilted sun samples only inside its own disk, with the constant pdf 1 / (2π(1 - cos)).
  const Vec3f dir = Vec3f(0.3f, -0.2f, 0.9f).normalized();
  const SunLight tilted(dir, 1.0f, 0.53f, Color::Ones());
  const float cos_sun = std::cos(radians(0.265f));
  for (float a = 0.01f; a < 1.0f; a += 0.07f)
    for (float b = 0.01f; b < 1.0f; b += 0.07f) {
      auto s = tilted.sample(Vec3f::Zero(), Vec2f(a, b));
      EXPECT_GE(s->wi.dot(dir), cos_sun - 1e-6f);
      EXPECT_NEAR(s->pdf, uniform_cone_pdf(cos_sun), 1e-3f * s->pdf);
    }
}

TEST(Chi2, UniformEnvironmentAboveATiltedNormal) {
  const UniformEnvironment env(Color(0.5f, 0.6f, 0.7f));
  const Vec3f n = Vec3f(0.4f, -0.3f, 0.8f).normalized();
  auto r = chi2_sphere(
      [&](const Vec2f& u) -> std::optional<Vec3f> {
        auto s = env.sample_at(Vec3f::Zero(), n, u);
        if (!s) return std::nullopt;
        return s->wi;
      },
      [&](const Vec3f& wi) { return env.pdf_at(wi, n); });
  EXPECT_GT(r.p_value, kAlpha) << r.summary();
  EXPECT_NEAR(r.pdf_integral, 1.0, 2e-3);
  // Without a normal (transmissive receivers) the whole sphere, uniformly.
  auto r2 =
      chi2_sphere([&](const Vec2f& u) -> std::optional<Vec3f> { return env.sample_at(Vec3f::Zero(), Vec3f::Zero(), u)->wi; },
                  [&](const Vec3f& wi) { return env.pdf_at(wi, Vec3f::Zero()); });
  EXPECT_GT(r2.p_value, kAlpha) << r2.summary();
}

TEST(Chi2, EnvironmentMapImportanceSampling) {
  // A synthetic map with a bright patch, a gradient and a dark band.
  const int w = 64, h = 32;
  std::vector<float> rgb(w * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float v = 0.1f + float(x) / w;
      if (x > 40 && x < 48 && y > 6 && y < 12) v = 30.0f;
      if (y > 20 && y < 24) v = 0.0f;
      for (int c = 0; c < 3; ++c) rgb[(y * w + x) * 3 + c] = v * (c == 0 ? 1.0f : 0.8f);
    }
  const EnvironmentMap env(rgb, w, h, 1.0f, 30.0f);
  auto r = chi2_sphere(
      [&](const Vec2f& u) -> std::optional<Vec3f> {
        auto s = env.sample(Vec3f::Zero(), u);
        if (!s) return std::nullopt;
        return s->wi;
      },
      [&](const Vec3f& wi) { return env.pdf(wi); }, 2'000'000, 64, 128);
  EXPECT_GT(r.p_value, kAlpha) << r.summary();
  EXPECT_NEAR(r.pdf_integral, 1.0, 2e-2);
}

TEST(Chi2, EnvironmentMapSampleAgreesWithPdf) {
  std::vector<float> rgb(16 * 8 * 3, 1.0f);
  rgb[(3 * 16 + 5) * 3] = 50.0f;
  const EnvironmentMap env(rgb, 16, 8, 2.0f, 0.0f);
  for (float a = 0.05f; a < 1.0f; a += 0.1f)
    for (float b = 0.05f; b < 1.0f; b += 0.1f) {
      auto s = env.sample(Vec3f::Zero(), Vec2f(a, b));
      ASSERT_TRUE(s);
      EXPECT_NEAR(s->pdf, env.pdf(s->wi), 1e-3f * s->pdf);
      // uv <-> direction round trip
      const Vec2f uv = EnvironmentMap::direction_to_uv(s->wi);
      EXPECT_LT((EnvironmentMap::uv_to_direction(uv) - s->wi).norm(), 1e-4f);
    }
}

struct BsdfCase {
  const char* name;
  BSDF bsdf;
  Vec3f wo;
};

std::vector<BsdfCase> bsdf_cases() {
  std::vector<BsdfCase> c;
  BSDF d;
  d.type = BSDF::Type::Diffuse;
  c.push_back({"diffuse", d, Vec3f(0.3f, 0.2f, 0.9f).normalized()});
  BSDF k;
  k.type = BSDF::Type::Conductor;
  k.alpha = 0.3f;
  k.base = Color(0.9f, 0.6f, 0.3f);
  c.push_back({"ggx_conductor_a0.3", k, Vec3f(0.6f, 0.1f, 0.5f).normalized()});
  k.alpha = 0.08f;
  c.push_back({"ggx_conductor_a0.08_grazing", k, Vec3f(0.9f, 0.0f, 0.2f).normalized()});
  BSDF b;
  b.type = BSDF::Type::Bark;
  b.alpha = 0.25f;
  b.base = Color(0.4f, 0.3f, 0.2f);
  c.push_back({"bark", b, Vec3f(-0.4f, 0.3f, 0.7f).normalized()});
  BSDF g;
  g.type = BSDF::Type::Dielectric;
  g.alpha = 0.3f;
  g.eta = 1.5f;
  c.push_back({"rough_dielectric_outside", g, Vec3f(0.5f, 0.2f, 0.7f).normalized()});
  c.push_back({"rough_dielectric_inside", g, Vec3f(0.2f, -0.3f, -0.8f).normalized()});
  return c;
}

TEST(Chi2, BsdfSamplingMatchesPdf) {
  // GGX visible-normal sampling through each microfacet BSDF, and the mixtures around it.
  for (const auto& c : bsdf_cases()) {
    int k = 0;
    auto r = chi2_sphere(
        [&](const Vec2f& u) -> std::optional<Vec3f> {
          // A third, decorrelated number for the lobe choice.
          const double g = (k++) * 0.6180339887498949;
          const float uc = float(g - std::floor(g));
          auto s = c.bsdf.sample(c.wo, uc, u);
          if (!s) return std::nullopt;
          return s->wi;
        },
        [&](const Vec3f& wi) { return c.bsdf.pdf(c.wo, wi); }, 1'000'000, 40, 80, 7);
    EXPECT_GT(r.p_value, kAlpha) << c.name << ": " << r.summary();
  }
}

TEST(Sampling, Distribution1DPdfIntegratesToOne) {
  Distribution1D d({0.0f, 1.0f, 3.0f, 0.0f, 6.0f});
  double sum = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) sum += d.pdf((i + 0.5) / n);
  EXPECT_NEAR(sum / n, 1.0, 1e-6);
  float pdf;
  int bin;
  const float x = d.sample(0.5f, &pdf, &bin);  // the cdf reaches 0.4 after bin 2
  EXPECT_EQ(bin, 4);
  EXPECT_NEAR(pdf, 6.0f / 10.0f * 5.0f, 1e-5f);
  EXPECT_GE(x, 0.8f);
}

}  // namespace
}  // namespace phellem
