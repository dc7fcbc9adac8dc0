// compare/lit_statistics: exposure invariance, the near-black share, the octave spectrum of a
// sine grating, the edge orientation of stripes, the mask, every refusal, and the speed.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>

#include "compare/gaussian_blur.h"
#include "compare/lit_statistic_names.h"
#include "compare/lit_statistics.h"
#include "compare/percentile.h"
#include "tests/compare/lit_images.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

using test::expect_user_error;

void expect_same_statistics(const LitStatistics& a, const LitStatistics& b, double tol, const std::string& what) {
  const std::vector<NamedStatistic> na = named_lit_statistics(a), nb = named_lit_statistics(b);
  ASSERT_EQ(na.size(), nb.size()) << what;
  for (size_t i = 0; i < na.size(); ++i) {
    ASSERT_EQ(na[i].name, nb[i].name) << what;
    if (na[i].name == "median_luminance") continue;  // the exposure itself
    if (tol == 0)
      EXPECT_EQ(na[i].value, nb[i].value) << what << ": " << na[i].name;
    else
      EXPECT_NEAR(na[i].value, nb[i].value, tol * std::max(1.0, std::abs(na[i].value))) << what << ": " << na[i].name;
  }
}

TEST(LitStatistics, IndependentOfExposure) {
  const LitImage im = test::bark_picture(384, 10, 7);
  const LitStatistics s = lit_statistics(im, "bark");
  EXPECT_GT(s.near_black_share, 0.001);  // the test image has every kind of pixel
  EXPECT_GT(s.colour.chroma, 5);
  for (float k : {0.01f, 7.3f}) {
    const LitStatistics sk = lit_statistics(test::exposed(im, k), "bark·k");
    EXPECT_NEAR(sk.median_luminance, k * s.median_luminance, 1e-6 * k * s.median_luminance);
    expect_same_statistics(s, sk, 1e-6, "k = " + std::to_string(k));
  }
}

TEST(LitStatistics, NearBlackShareIsExact) {
  // 64×64 grey 0.5: 300 pixels at 2 % of the median (near-black), 200 at 4 % (not).
  LitImage im{64, 64, 10, std::vector<float>(3 * 64 * 64, 0.5f), {}};
  for (size_t i = 0; i < 500; ++i) {
    const float v = i < 300 ? 0.01f : 0.02f;
    for (int c = 0; c < 3; ++c) im.rgb[3 * (7 * i + 3) + size_t(c)] = v;
  }
  const LitStatistics s = lit_statistics(im, "grey");
  EXPECT_EQ(s.near_black_share, 300.0 / 4096);
  EXPECT_FLOAT_EQ(float(s.median_luminance), 0.5f);
  EXPECT_NEAR(s.log_luminance_percentiles[0], std::log(0.02), 1e-6);  // P1 (41 pixels) lies in the 300
  EXPECT_EQ(s.log_luminance_percentiles[7], 0);                       // P99: the median grey
}

TEST(LitStatistics, BlackPixelsAreFlooredRelativeToTheMedian) {
  LitImage im{64, 64, 10, std::vector<float>(3 * 64 * 64, 0.5f), {}};
  for (size_t i = 0; i < 3 * 200; ++i) im.rgb[i] = 0;  // 200 pixels of exact black
  const LitStatistics s = lit_statistics(im, "grey");
  EXPECT_NEAR(s.log_luminance_percentiles[0], std::log(kLitParams.luminance_floor_ratio), 1e-6);
  EXPECT_EQ(s.near_black_share, 200.0 / 4096);
}

size_t band_of(const std::vector<SpectrumBand>& bands, double f) {
  for (size_t b = 0; b < bands.size(); ++b)
    if (bands[b].lo_cycles_per_cm <= f && f < bands[b].hi_cycles_per_cm) return b;
  return bands.size();
}

TEST(LitStatistics, SineGratingPutsItsPowerInItsOctave) {
  // 512 px at 10 px/cm: octaves from 8/51.2 cm⁻¹ up to the Nyquist 5 cm⁻¹ → 1/4 … 4 cycles/cm.
  const std::vector<SpectrumBand> expect_bands = octave_bands(512, 512, 10);
  ASSERT_EQ(expect_bands.size(), 4u);
  EXPECT_EQ(expect_bands.front().lo_cycles_per_cm, 0.25);
  EXPECT_EQ(expect_bands.back().hi_cycles_per_cm, 4);
  struct Case {
    double cycles_per_cm, angle_deg;
  };
  for (const Case c : {Case{1.4, 90}, Case{0.35, 0}, Case{0.7, 30}, Case{2.9, 120}, Case{0.27, 45}}) {
    const LitStatistics s = lit_statistics(test::sine_stripes(512, 10, 10 / c.cycles_per_cm, c.angle_deg), "grating");
    const size_t b = band_of(s.bands, c.cycles_per_cm);
    ASSERT_LT(b, s.bands.size());
    EXPECT_GT(s.bands[b].share, 0.97) << c.cycles_per_cm << " cycles/cm at " << c.angle_deg << "°";
    double sum = 0;
    for (const SpectrumBand& x : s.bands) sum += x.share;
    EXPECT_NEAR(sum, 1, 1e-9);
  }
}

TEST(LitStatistics, StripesPeakInTheirDirectionsBin) {
  for (double angle : {0.0, 30.0, 90.0, 140.0}) {
    const LitStatistics s = lit_statistics(test::sine_stripes(256, 10, 17, angle), "stripes");
    const size_t peak =
        size_t(std::max_element(s.orientation_hist.begin(), s.orientation_hist.end()) - s.orientation_hist.begin());
    EXPECT_EQ(peak, size_t(std::lround(angle / 10)) % 18) << angle << "°";
    EXPECT_GT(s.orientation_hist[peak], 0.9) << angle << "°";
    EXPECT_GT(s.orientation_anisotropy, 0.95) << angle << "°";
    EXPECT_NEAR(std::remainder(s.orientation_mean_deg - angle, 180.0), 0, 1.0) << angle << "°";
  }
  const LitStatistics n = lit_statistics(test::noise_picture(256, 10, 3, 0.5, 4), "noise");
  EXPECT_LT(n.orientation_anisotropy, 0.1);
  EXPECT_LT(*std::max_element(n.orientation_hist.begin(), n.orientation_hist.end()), 0.1);
}

TEST(LitStatistics, LocalContrastFindsTheScaleOfTheDetail) {
  // Fine noise (σ 1 px = 0.1 cm) against coarse noise (σ 15 px = 1.5 cm) of the same amplitude.
  const LitStatistics fine = lit_statistics(test::noise_picture(512, 10, 1, 0.5, 1), "fine");
  const LitStatistics coarse = lit_statistics(test::noise_picture(512, 10, 15, 0.5, 1), "coarse");
  EXPECT_GT(fine.local_contrast[0], 3 * coarse.local_contrast[0]);
  EXPECT_GT(coarse.local_contrast[1], 3 * fine.local_contrast[1]);
  EXPECT_GT(coarse.local_contrast[2], fine.local_contrast[2]);
}

TEST(LitStatistics, DecimatedContrastMatchesTheFullResolutionBand) {
  // The 1 cm and 4 cm bands are measured on 2×2 and 8×8 box-decimated grids; against the band
  // computed at full resolution (plain G(σ) − G(2σ) of ℓ) they agree within a few %.
  const LitImage im = test::bark_picture(512, 10, 2);
  const LitStatistics s = lit_statistics(im, "bark");
  std::vector<float> l(size_t(512) * 512);
  for (size_t i = 0; i < l.size(); ++i)
    l[i] = float(std::log(
        std::max(0.2126 * im.rgb[3 * i] + 0.7152 * im.rgb[3 * i + 1] + 0.0722 * im.rgb[3 * i + 2], 1e-4 * s.median_luminance) /
        s.median_luminance));
  for (int k = 0; k < kLitContrastScales; ++k) {
    const double sigma = kLitParams.contrast_sigma_cm[size_t(k)] * 10;
    const std::vector<float> a = gaussian_blur(l, 512, 512, sigma), b = gaussian_blur(l, 512, 512, 2 * sigma);
    std::vector<double> band(l.size());
    for (size_t i = 0; i < l.size(); ++i) band[i] = double(a[i]) - b[i];
    const double direct = mean_std(band).std;
    std::printf("local contrast at %g px: %.5f decimated, %.5f full resolution\n", sigma, s.local_contrast[size_t(k)], direct);
    EXPECT_NEAR(s.local_contrast[size_t(k)], direct, 0.03 * direct) << sigma << " px";
  }
}

TEST(LitStatistics, MaskedPixelsAreNeverRead) {
  LitImage im = test::bark_picture(256, 10, 3);
  im.valid.assign(size_t(256) * 256, 1);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x)
      if (std::hypot(x - 90, y - 140) < 50 || x > 200) im.valid[size_t(y) * 256 + size_t(x)] = 0;
  const LitStatistics s = lit_statistics(im, "masked");
  EXPECT_LT(s.valid_pixels, 256 * 256 - 10000);
  for (float paint : {0.f, 1e6f, -3.f, std::numeric_limits<float>::quiet_NaN()}) {
    LitImage p = im;
    for (size_t i = 0; i < p.valid.size(); ++i)
      if (!p.valid[i])
        for (int c = 0; c < 3; ++c) p.rgb[3 * i + size_t(c)] = paint;
    expect_same_statistics(s, lit_statistics(p, "painted"), 0, "masked pixels painted " + std::to_string(paint));
  }
  // And the mask matters: the same image without it reads differently.
  LitImage unmasked = im;
  unmasked.valid.clear();
  for (size_t i = 0; i < im.valid.size(); ++i)
    if (!im.valid[i]) unmasked.rgb[3 * i] = unmasked.rgb[3 * i + 1] = unmasked.rgb[3 * i + 2] = 1e3f;
  EXPECT_NE(lit_statistics(unmasked, "unmasked").log_luminance_percentiles[7], s.log_luminance_percentiles[7]);
}

TEST(LitStatistics, RefusesBadInput) {
  const LitImage good = test::noise_picture(64, 10, 2, 0.5, 1);
  expect_user_error([] { lit_statistics(LitImage{}, "e.exr"); }, "empty", "e.exr", "", "the image is empty (0×0 px)");
  LitImage nan = good;
  nan.rgb[3 * (64 * 5 + 9) + 1] = std::numeric_limits<float>::quiet_NaN();
  expect_user_error([&] { lit_statistics(nan, "n.exr"); }, "NaN", "n.exr", "",
                    "pixel (9, 5) is nan in channel G; every valid pixel must be finite");
  LitImage inf = good;
  inf.rgb[0] = std::numeric_limits<float>::infinity();
  expect_user_error([&] { lit_statistics(inf, "i.exr"); }, "inf", "i.exr", "", "pixel (0, 0) is inf in channel R");
  LitImage few = good;
  few.valid.assign(64 * 64, 0);
  for (size_t i = 0; i < 1000; ++i) few.valid[i] = 1;
  expect_user_error([&] { lit_statistics(few, "m.exr"); }, "mask", "m.exr", "",
                    "the mask keeps 1000 of 4096 pixels; the lit statistics need at least 1024 valid pixels");
  LitImage mask_size = good;
  mask_size.valid.assign(100, 1);
  expect_user_error([&] { lit_statistics(mask_size, "m.exr"); }, "mask size", "m.exr", "",
                    "the mask has 100 pixels; the image has 4096");
  LitImage rgb_size = good;
  rgb_size.rgb.pop_back();
  expect_user_error([&] { lit_statistics(rgb_size, "s.exr"); }, "rgb size", "s.exr", "",
                    "the image has 12287 RGB floats; 64×64 px needs 12288");
  LitImage coarse = good;
  coarse.px_per_cm = 3;
  expect_user_error([&] { lit_statistics(coarse, "c.exr"); }, "scale", "c.exr", "",
                    "the scale is 3 px/cm; the lit statistics need at least 4 px/cm");
  const LitImage small = test::noise_picture(31, 10, 2, 0.5, 1);
  expect_user_error([&] { lit_statistics(small, "t.exr"); }, "small", "t.exr", "",
                    "the image is 31×31 px; the lit statistics need at least 32 px on each side");
  LitImage black = good;
  std::fill(black.rgb.begin(), black.rgb.begin() + 3 * 2100, 0.f);
  expect_user_error([&] { lit_statistics(black, "b.exr"); }, "black", "b.exr", "",
                    "the median luminance of the valid pixels is 0");
}

TEST(LitStatistics, MeasuresA1024ImageWellUnderASecond) {
  LitImage im = test::bark_picture(1024, 10, 11);
  lit_statistics(im, "warm-up");
  for (double scale : {10.0, 20.0}) {
    im.px_per_cm = scale;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    const LitStatistics s = lit_statistics(im, "bark 1024²");
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    RecordProperty("seconds_at_" + std::to_string(int(scale)), std::to_string(seconds));
    std::printf("lit_statistics 1024² at %g px/cm: %.3f s wall, %.3f s CPU (all threads)\n", scale, seconds, cpu);
    EXPECT_EQ(s.valid_pixels, 1024 * 1024);
    // The target is well under 1 s; the bound is loose for a loaded 2-core machine.
    EXPECT_LT(seconds, 2.0);
  }
}

}  // namespace
}  // namespace phellem
