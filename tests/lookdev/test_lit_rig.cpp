// The light rig of `compare --lit` (lookdev/lit_rig.h) against closed forms, and the lit score's
// calibration cases on synthetic bark made in code: two halves of one bark look the same, two
// kinds of bark differ, and each deliberate defect (relief × 3, albedo replaced by its mean,
// fissure floors painted black) is detected and named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "compare/compare_inputs.h"
#include "compare/lit_score.h"
#include "lookdev/lit_rig.h"
#include "lookdev/lit_variants.h"
#include "tests/support/height_fields.h"

namespace phellem {
namespace {


bool has(const std::vector<std::string>& words, const std::string& w) { return std::find(words.begin(), words.end(), w) != words.end(); }
std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += "\"" + w + "\" ";
  return s;
}

// Vertical V-grooves under the rig's sun alone (no sky, direct light only), seen from straight
// above. The sun comes from +x at elevation e, so with t = tan e, a groove of half-width h and
// depth d > h·t has its wall facing away from the sun (x > centre) in its own shadow, and the rim
// at x = centre + h shades the sunward wall from the centre out to ξ* = (d − h·t) / (t + d/h).
// Everything else is lit, so a dark run of (h + ξ*)·s pixels per period P. In pixels, the two
// pixels at a run's ends are partly lit and count as near-black only when under 3 % of the
// median, i.e. when at least 97 % of them is in shadow: a run of L px gives L − 1 + 2 × 0.03
// near-black pixels on average, and the share is ((h + ξ*)·s − 0.94) / (P·s).
double v_groove_share(double elevation_deg, double period, double h, double d, double s) {
  const double t = std::tan(elevation_deg * M_PI / 180), xi = (d - h * t) / (t + d / h);
  return ((h + xi) * s - (1 - 2 * 0.03)) / (period * s);
}

TEST(LitRig, NearBlackShareOfVGroovesMatchesTheClosedForm) {
  const double s = 10, period = 4, h = 1, d = 1;  // px/cm, cm
  const int w = 402, ht = 202;
  LitSubject sub;
  sub.label = "grooves";
  sub.height.width = w;
  sub.height.height = ht;
  sub.height.px_per_cm = s;
  for (int y = 0; y < ht; ++y)
    for (int x = 0; x < w; ++x) {
      const double xc = (x + 0.5) / s, q = std::fmod(xc, period) - period / 2;  // q ∈ [−2, 2): groove centre at 0
      const double depth_cm = std::abs(q) < h ? d * (1 - std::abs(q) / h) : 0.0;
      sub.height.z.push_back(float(-depth_cm * 0.01));
    }
  LitRig rig;
  rig.sky = false;
  rig.max_depth = 1;
  rig.spp = 4;
  EXPECT_NEAR(v_groove_share(30, period, h, d, s), (1.26795 * 10 - 0.94) / 40, 1e-5);  // ξ* = 0.268 cm at 30°
  for (const double e : {30.0, 20.0}) {
    rig.sun_elevation_deg = e;
    const LitStatistics st = lit_statistics(render_lit(sub, rig).image, "grooves");
    // Measured 0.2954 (30°, form 0.2935) and 0.3502 (20°, form 0.3431): within 0.3 px per groove, the
    // dicing's rounding of the rims; the form without its pixel term (0.317 at 30°) is outside.
    EXPECT_NEAR(st.near_black_share, v_groove_share(e, period, h, d, s), 0.01) << "sun at " << e << "°";
  }
  // A sun steeper than the walls (d < h·tan 60°) lights both walls: nothing is near-black.
  rig.sun_elevation_deg = 60;
  EXPECT_LT(lit_statistics(render_lit(sub, rig).image, "grooves").near_black_share, 0.005);
}

// Synthetic fissured bark with an albedo that follows the height (dark in the fissures) and a slow
// colour drift, as a scan's is. Heights in metres (fissures 8 mm deep).
LitSubject synthetic_bark(uint32_t seed, double width_cm = 40, double height_cm = 40, double s = 4) {
  const test::Heights hf = seed == 0 ? test::smooth_noise(width_cm, height_cm, s, 3.0, 11) : test::fissured_bark(width_cm, height_cm, s, seed);
  LitSubject b;
  b.label = "bark " + std::to_string(seed);
  b.height.width = hf.width;
  b.height.height = hf.height;
  b.height.px_per_cm = s;
  const auto [lo, hi] = std::minmax_element(hf.z.begin(), hf.z.end());
  AlbedoField a;
  a.width = hf.width;
  a.height = hf.height;
  const float ridge[3] = {0.30f, 0.22f, 0.15f}, fissure[3] = {0.08f, 0.06f, 0.045f};
  for (size_t i = 0; i < hf.z.size(); ++i) {
    b.height.z.push_back(hf.z[i] * 0.008f);
    const float k = (hf.z[i] - *lo) / (*hi - *lo);
    const int x = int(i % size_t(hf.width)), y = int(i / size_t(hf.width));
    const float drift = 0.04f * std::sin(0.05f * float(x)) * std::cos(0.07f * float(y));
    for (int c = 0; c < 3; ++c) a.rgb.push_back(std::max(0.01f, fissure[c] + (ridge[c] - fissure[c]) * k + (c == 0 ? drift : c == 2 ? -drift : 0.0f)));
  }
  b.albedo = std::move(a);
  return b;
}

class LitCalibration : public ::testing::Test {
 protected:
  static LitRig rig() {
    LitRig r;
    r.spp = 8;
    return r;
  }
  static LitStatistics measure(const LitSubject& s) { return lit_statistics(render_lit(s, rig()).image, s.label); }
  static void SetUpTestSuite() {
    bark_ = new LitSubject(synthetic_bark(3));
    reference_ = new LitStatistics(measure(*bark_));
  }
  static void TearDownTestSuite() {
    delete bark_;
    delete reference_;
  }
  static LitSubject* bark_;
  static LitStatistics* reference_;
};
LitSubject* LitCalibration::bark_ = nullptr;
LitStatistics* LitCalibration::reference_ = nullptr;

TEST_F(LitCalibration, HalvesOfOneBarkLookTheSame) {
  for (bool vertical : {true, false}) {
    const LitComparison c = compare_lit(measure(half_of(*bark_, vertical, false)), measure(half_of(*bark_, vertical, true)));
    EXPECT_EQ(c.verdict, "same look") << (vertical ? "left/right " : "top/bottom ") << c.score << " " << joined(c.words);
    EXPECT_TRUE(c.words.empty()) << joined(c.words);
  }
}

TEST_F(LitCalibration, FissuredBarkAgainstSmoothNoiseDiffers) {
  const LitComparison c = compare_lit(*reference_, measure(synthetic_bark(0)));
  EXPECT_EQ(c.verdict, "different") << c.score;
  EXPECT_GT(c.score, kLitThresholds.close_score);
}

TEST_F(LitCalibration, ReliefTimesThreeIsTooStrong) {
  const LitComparison c = compare_lit(*reference_, measure(with_relief_scaled(*bark_, 3.0)));
  EXPECT_NE(c.verdict, "same look") << c.score;
  EXPECT_TRUE(has(c.words, "relief too strong")) << joined(c.words);
  EXPECT_FALSE(has(c.words, "relief too weak"));
}

TEST_F(LitCalibration, MeanAlbedoIsTooUniform) {
  const LitComparison c = compare_lit(*reference_, measure(with_mean_albedo(*bark_)));
  EXPECT_NE(c.verdict, "same look") << c.score;
  EXPECT_TRUE(has(c.words, "colour too uniform")) << joined(c.words);
}

TEST_F(LitCalibration, BlackFissureFloorsAreTooDark) {
  const LitComparison c = compare_lit(*reference_, measure(with_black_fissure_floors(*bark_)));
  EXPECT_NE(c.verdict, "same look") << c.score;
  EXPECT_TRUE(has(c.words, "fissures too dark")) << joined(c.words);
  EXPECT_FALSE(has(c.words, "fissures too light"));
}

}  // namespace
}  // namespace phellem

namespace phellem {
namespace {

// The calibration cases on the two CC0 scans the repository carries (data/photos, from
// ../shared/reference), at 4 px/cm and 4 spp to stay quick; bench/lit_calibration.cpp runs them
// at 5 and 10 px/cm, 16 spp (docs/compare.md).
class LitScans : public ::testing::Test {
 protected:
  static LitSubject scan(const std::string& height, const std::string& albedo, const std::string& label) {
    const std::string dir = std::string(PHELLEM_SOURCE_DIR) + "/data/photos/";
    const PreparedInput in = at_scale(load_input(CompareSource{label, dir + height, 10.0, dir + albedo}), 4.0);
    LitSubject s;
    s.label = label;
    s.height = in.field;
    for (float& z : s.height.z) z *= 0.03f;  // the full code range as 3 cm
    s.albedo = in.albedo;
    return s;
  }
  static LitStatistics measure(const LitSubject& s) {
    LitRig r;
    r.spp = 4;
    return lit_statistics(render_lit(s, r).image, s.label);
  }
};

TEST_F(LitScans, HalvesLookTheSameDefectsAreNamedAndTheTwoScansDiffer) {
  const LitSubject brown = scan("bark_brown_01_polyhaven_disp.jpg", "bark_brown_01_polyhaven.jpg", "brown");
  const LitSubject pine = scan("pine_bark_polyhaven_disp.png", "pine_bark_polyhaven.jpg", "pine");
  LitStatistics full[2];
  int k = 0;
  for (const LitSubject* s : {&brown, &pine}) {
    SCOPED_TRACE(s->label);
    full[k] = measure(*s);
    for (bool vertical : {true, false}) {
      const LitComparison c = compare_lit(measure(half_of(*s, vertical, false)), measure(half_of(*s, vertical, true)));
      EXPECT_EQ(c.verdict, "same look") << (vertical ? "left/right " : "top/bottom ") << c.score;
      EXPECT_TRUE(c.words.empty()) << joined(c.words);
    }
    const LitComparison relief = compare_lit(full[k], measure(with_relief_scaled(*s, 3.0)));
    EXPECT_EQ(relief.verdict, "different") << relief.score;
    EXPECT_TRUE(has(relief.words, "relief too strong")) << joined(relief.words);
    const LitComparison flat = compare_lit(full[k], measure(with_mean_albedo(*s)));
    EXPECT_NE(flat.verdict, "same look") << flat.score;
    EXPECT_TRUE(has(flat.words, "colour too uniform")) << joined(flat.words);
    const LitComparison black = compare_lit(full[k], measure(with_black_fissure_floors(*s)));
    EXPECT_EQ(black.verdict, "different") << black.score;
    EXPECT_TRUE(has(black.words, "fissures too dark")) << joined(black.words);
    ++k;
  }
  const LitComparison c = compare_lit(full[0], full[1]);
  EXPECT_EQ(c.verdict, "different") << c.score;
}

}  // namespace
}  // namespace phellem
