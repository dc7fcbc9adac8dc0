// The Owen-scrambled Sobol sampler (Burley 2020): the fast reversed-domain evaluation equals
// the paper's formula, and the points keep the stratification that makes them worth using.
#include <gtest/gtest.h>

#include <set>

#include "renderer/sampler.h"
#include "util/hash.h"

namespace phellem {
namespace {

// Burley 2020, listing 3, written the slow way round.
Vec4f reference_get4d(uint32_t px, uint32_t py, uint32_t index, uint32_t seed, uint32_t dimension_set) {
  const uint32_t set_seed = hash_combine(Sampler::hash_pixel(px, py, seed), dimension_set);
  const uint32_t shuffled = nested_uniform_scramble(index, set_seed);
  Vec4f out;
  for (int d = 0; d < 4; ++d) {
    const uint32_t x = nested_uniform_scramble(sobol_u32(shuffled, d), hash_combine(set_seed, uint32_t(d) + 1));
    out[d] = std::min(u32_to_unit_float(x), kOneMinusEpsilon);
  }
  return out;
}

TEST(Sampler, FastPathEqualsPaperFormula) {
  for (uint32_t index : {0u, 1u, 2u, 3u, 17u, 255u, 1000u, 65537u, 0x00ABCDEFu, 0x7FFFFFFFu})
    for (uint32_t px : {0u, 5u, 1919u}) {
      Sampler s(px, 7u, index, 42u);
      for (uint32_t set = 0; set < 5; ++set) {
        const Vec4f fast = s.get4d(), ref = reference_get4d(px, 7u, index, 42u, set);
        for (int d = 0; d < 4; ++d) ASSERT_EQ(fast[d], ref[d]) << "index " << index << " set " << set << " dim " << d;
      }
    }
}

TEST(Sampler, PixelSeedConstructorMatches) {
  Sampler a(12u, 34u, 9u, 3u), b(Sampler::hash_pixel(12u, 34u, 3u), 9u);
  for (int k = 0; k < 4; ++k) ASSERT_EQ(a.get4d(), b.get4d());
}

// The first 2^m samples of a pixel: every dimension is stratified into 2^m equal intervals
// with one point each, and dimensions 0-1 form a (0,m,2)-net (one point in every elementary
// interval of area 2^-m, whatever its aspect ratio).
TEST(Sampler, FirstPowerOfTwoSamplesAreStratified) {
  constexpr int m = 8, n = 1 << m;
  for (uint32_t set = 0; set < 3; ++set) {
    std::vector<Vec4f> pts;
    for (int i = 0; i < n; ++i) {
      Sampler s(Sampler::hash_pixel(31u, 17u, 5u), uint32_t(i));
      Vec4f v;
      for (uint32_t k = 0; k <= set; ++k) v = s.get4d();
      pts.push_back(v);
    }
    for (int d = 0; d < 4; ++d) {
      std::set<int> cells;
      for (const auto& p : pts) cells.insert(int(p[d] * n));
      EXPECT_EQ(int(cells.size()), n) << "dimension " << d << " set " << set;
    }
    for (int a = 0; a <= m; ++a) {
      const int nx = 1 << a, ny = 1 << (m - a);
      std::set<int> cells;
      for (const auto& p : pts) cells.insert(int(p[0] * nx) * ny + int(p[1] * ny));
      EXPECT_EQ(int(cells.size()), n) << "elementary intervals " << nx << "x" << ny << " set " << set;
    }
  }
}

// Neighbouring pixels draw decorrelated sequences (no visible structure across the image).
TEST(Sampler, PixelsAreDecorrelated) {
  constexpr int n = 4096;
  double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
  // Correlation of dimension 0 between pixel pairs at equal sample index.
  for (int i = 0; i < n; ++i) {
    const uint32_t px = uint32_t(i % 64), py = uint32_t(i / 64);
    const float a = Sampler(px, py, 3u, 1u).get4d()[0], b = Sampler(px + 1, py, 3u, 1u).get4d()[0];
    sa += a;
    sb += b;
    sab += a * b;
    saa += a * a;
    sbb += b * b;
  }
  const double cov = sab / n - (sa / n) * (sb / n);
  const double corr = cov / std::sqrt((saa / n - sa * sa / n / n) * (sbb / n - sb * sb / n / n));
  EXPECT_LT(std::abs(corr), 4.0 / std::sqrt(double(n))) << "correlation " << corr;
}

}  // namespace
}  // namespace phellem
