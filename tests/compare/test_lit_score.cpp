// compare/lit_score: zero against itself, near zero against an exposed or shifted copy, clearly
// higher against a different picture, and the artist's words name the defect in each direction.
#include <gtest/gtest.h>

#include <algorithm>

#include "compare/gaussian_blur.h"
#include "compare/lit_report_json.h"
#include "compare/lit_score.h"
#include "compare/percentile.h"
#include "tests/compare/lit_images.h"

namespace phellem {
namespace {

bool has(const std::vector<std::string>& words, const std::string& w) {
  return std::find(words.begin(), words.end(), w) != words.end();
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += "[" + w + "] ";
  return s;
}

// The `size`² crop at (x0, y0).
LitImage crop(const LitImage& im, int x0, int y0, int size) {
  LitImage o{size, size, im.px_per_cm, {}, {}};
  for (int y = y0; y < y0 + size; ++y)
    for (int x = x0; x < x0 + size; ++x)
      for (int c = 0; c < 3; ++c) o.rgb.push_back(im.rgb[3 * (size_t(y) * size_t(im.width) + size_t(x)) + size_t(c)]);
  return o;
}

void print_groups(const char* what, const LitComparison& c) {
  std::printf("lit score: %s %.4f:", what, c.score);
  for (const LitGroupScore& g : c.groups) std::printf(" %s %.3f", g.group.c_str(), g.score);
  std::printf("\n");
}

// The darkest `share` of the pixels (by luminance) painted black.
LitImage darker_fissures(const LitImage& im, double share) {
  std::vector<float> Y(im.rgb.size() / 3);
  for (size_t i = 0; i < Y.size(); ++i)
    Y[i] = 0.2126f * im.rgb[3 * i] + 0.7152f * im.rgb[3 * i + 1] + 0.0722f * im.rgb[3 * i + 2];
  const double t = percentile(Y, 100 * share);
  LitImage o = im;
  for (size_t i = 0; i < Y.size(); ++i)
    if (Y[i] <= t) o.rgb[3 * i] = o.rgb[3 * i + 1] = o.rgb[3 * i + 2] = 0;
  return o;
}

class LitScore : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    bark_ = new LitImage(test::bark_picture(384, 10, 5));
    ref_ = new LitStatistics(lit_statistics(*bark_, "reference"));
  }
  static void TearDownTestSuite() {
    delete bark_;
    delete ref_;
  }
  static LitImage* bark_;
  static LitStatistics* ref_;
};
LitImage* LitScore::bark_ = nullptr;
LitStatistics* LitScore::ref_ = nullptr;

TEST_F(LitScore, ZeroAgainstItself) {
  const LitComparison c = compare_lit(*ref_, *ref_);
  EXPECT_EQ(c.score, 0);
  EXPECT_EQ(c.verdict, "same look");
  EXPECT_TRUE(c.words.empty()) << joined(c.words);
  for (const LitDifference& d : c.differences) EXPECT_EQ(d.difference, 0) << d.name;
  EXPECT_EQ(c.groups.size(), 6u);
}

TEST_F(LitScore, NearZeroAgainstAnExposedOrShiftedCopy) {
  const LitComparison exposed = compare_lit(*ref_, lit_statistics(test::exposed(*bark_, 3.7f), "exposed"));
  EXPECT_LT(exposed.score, 1e-6);
  // The same bark moved: two 512² crops of one 576² picture, 64 and 32 px apart (and exposed
  // differently).
  const LitImage big = test::bark_picture(576, 10, 5);
  const LitComparison moved = compare_lit(lit_statistics(crop(big, 0, 0, 512), "crop"),
                                          lit_statistics(crop(test::exposed(big, 0.2f), 64, 32, 512), "moved crop"));
  print_groups("moved", moved);
  EXPECT_LT(moved.score, 0.05);  // measured 0.032 (other fissures enter the crop); different pictures score 0.3
  EXPECT_EQ(moved.verdict, "same look");
  EXPECT_TRUE(moved.words.empty()) << joined(moved.words);
  // Another picture of the same kind of bark (another seed) is close too.
  const LitComparison sibling = compare_lit(*ref_, lit_statistics(test::bark_picture(384, 10, 6), "sibling"));
  print_groups("another seed", sibling);
  EXPECT_LT(sibling.score, kLitThresholds.same_score);
  std::printf("lit score: exposed %.2g, shifted %.4f, another seed %.4f\n", exposed.score, moved.score, sibling.score);
}

TEST_F(LitScore, PaintedBlackFissuresAreTooDark) {
  const LitStatistics dark = lit_statistics(darker_fissures(*bark_, 0.12), "dark");
  const LitComparison c = compare_lit(*ref_, dark);
  const LitComparison sibling = compare_lit(*ref_, lit_statistics(test::bark_picture(384, 10, 6), "sibling"));
  std::printf("lit score: painted black %.3f (%s) vs another seed %.3f\n", c.score, joined(c.words).c_str(), sibling.score);
  EXPECT_GT(c.score, 2 * sibling.score);
  EXPECT_GT(dark.near_black_share, ref_->near_black_share + 0.05);
  EXPECT_TRUE(has(c.words, "fissures too dark")) << joined(c.words);
  EXPECT_FALSE(has(c.words, "fissures too light"));
  // The other way round the reference's fissures are the lighter ones.
  const LitComparison back = compare_lit(dark, *ref_);
  EXPECT_TRUE(has(back.words, "fissures too light")) << joined(back.words);
  EXPECT_FALSE(has(back.words, "fissures too dark"));
}

TEST_F(LitScore, StripesAgainstNoiseDiffer) {
  const LitStatistics stripes = lit_statistics(test::sine_stripes(384, 10, 20, 90, 0.6), "stripes");
  const LitStatistics noise = lit_statistics(test::noise_picture(384, 10, 4, 0.6, 9), "noise");
  const LitComparison c = compare_lit(stripes, noise);
  std::printf("lit score: stripes vs noise %.3f %s (%s)\n", c.score, c.verdict.c_str(), joined(c.words).c_str());
  EXPECT_GT(c.score, kLitThresholds.close_score);
  EXPECT_EQ(c.verdict, "different");
  EXPECT_TRUE(has(c.words, "grain direction differs")) << joined(c.words);
  EXPECT_GT(c.orientation_emd_deg, 30);
}

TEST_F(LitScore, BlurredCandidateHasRidgesTooSmooth) {
  // The candidate's fine detail removed: log-luminance blurred by 3 px (0.3 cm).
  LitImage soft = *bark_;
  for (int c = 0; c < 3; ++c) {
    std::vector<float> ch(soft.rgb.size() / 3);
    for (size_t i = 0; i < ch.size(); ++i) ch[i] = soft.rgb[3 * i + size_t(c)];
    ch = gaussian_blur(ch, soft.width, soft.height, 3.0);
    for (size_t i = 0; i < ch.size(); ++i) soft.rgb[3 * i + size_t(c)] = ch[i];
  }
  const LitComparison c = compare_lit(*ref_, lit_statistics(soft, "soft"));
  EXPECT_TRUE(has(c.words, "ridges too smooth")) << joined(c.words);
  const LitComparison back = compare_lit(lit_statistics(soft, "soft"), *ref_);
  EXPECT_TRUE(has(back.words, "too much fine detail")) << joined(back.words);
}

TEST_F(LitScore, StrongerReliefAndColourCastAreNamed) {
  // Relief: log-luminance doubled around the median (Y → Y²/median); colour: red up, blue down.
  LitImage strong = *bark_, warm = *bark_, varied = *bark_;
  const double M = ref_->median_luminance;
  for (size_t i = 0; i < strong.rgb.size() / 3; ++i) {
    const double Y = 0.2126 * bark_->rgb[3 * i] + 0.7152 * bark_->rgb[3 * i + 1] + 0.0722 * bark_->rgb[3 * i + 2];
    for (int c = 0; c < 3; ++c) strong.rgb[3 * i + size_t(c)] *= float(Y / M);
    warm.rgb[3 * i] *= 1.25f;
    warm.rgb[3 * i + 2] *= 0.7f;
    const float k = (i / 7) % 2 ? 1.3f : 0.75f;  // every other run of 7 pixels redder
    varied.rgb[3 * i] *= k;
  }
  const LitComparison s = compare_lit(*ref_, lit_statistics(strong, "strong"));
  EXPECT_TRUE(has(s.words, "relief too strong")) << joined(s.words);
  EXPECT_TRUE(has(compare_lit(lit_statistics(strong, "strong"), *ref_).words, "relief too weak"));
  const LitComparison w = compare_lit(*ref_, lit_statistics(warm, "warm"));
  EXPECT_TRUE(has(w.words, "too warm")) << joined(w.words);
  EXPECT_TRUE(has(compare_lit(lit_statistics(warm, "warm"), *ref_).words, "too cool"));
  const LitComparison v = compare_lit(*ref_, lit_statistics(varied, "varied"));
  EXPECT_TRUE(has(v.words, "colour too varied")) << joined(v.words);
  EXPECT_TRUE(has(compare_lit(lit_statistics(varied, "varied"), *ref_).words, "colour too uniform"));
}

TEST_F(LitScore, JsonListsEveryDifferenceAndBothSides) {
  const LitStatistics dark = lit_statistics(darker_fissures(*bark_, 0.12), "dark");
  const LitComparison c = compare_lit(*ref_, dark);
  const nlohmann::json j = lit_comparison_json(*ref_, dark, c);
  EXPECT_DOUBLE_EQ(j["score"].get<double>(), c.score);
  EXPECT_EQ(j["differences"].size(), c.differences.size());
  EXPECT_DOUBLE_EQ(j["differences"]["near_black_share"]["candidate"].get<double>(), dark.near_black_share);
  EXPECT_DOUBLE_EQ(j["reference"]["statistics"]["near_black_share"].get<double>(), ref_->near_black_share);
  EXPECT_EQ(j["candidate"]["orientation_histogram"].size(), 18u);
  EXPECT_EQ(j["words"], nlohmann::json(c.words));
  EXPECT_EQ(j["thresholds"]["same_score"].get<double>(), kLitThresholds.same_score);
}

}  // namespace
}  // namespace phellem
