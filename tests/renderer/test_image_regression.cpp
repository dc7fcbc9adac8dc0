// Image regression: tiny scenes rendered at low spp against references rendered at high spp
// (scripts/make_reference_images.sh). Metric: |test − ref| / (ref + 0.05), per channel, on
// 4×4 block averages (noise averages out, structure does not); its mean over the image must
// stay under 0.06 and its mean over every 16×16-pixel region under 0.20, so one wrong tile
// cannot hide in the average. On failure a per-block error image is written to the test temp
// directory.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <vector>

#include "io/image_output.h"
#include "scene/scene_parser.h"
#include "tests/support/render_helpers.h"

namespace phellem {
namespace {

constexpr double kTolerance = 0.06;        // mean over the image
constexpr double kRegionTolerance = 0.20;  // mean over any 16×16 region
constexpr int kBlock = 4, kRegion = 16;

struct RegressionError {
  double mean = 0;               // over all 4×4 blocks and channels
  double worst_region = 0;       // the largest mean over one 16×16 region's blocks and channels
  std::vector<float> per_block;  // RGBA per pixel: its block's error (for the error image)
};

// `test` and `ref` are RGBA, w × h.
RegressionError regression_error(const std::vector<float>& test, const std::vector<float>& ref, int w, int h) {
  RegressionError r;
  r.per_block.assign(size_t(w) * h * 4, 0.0f);
  const int rx = (w + kRegion - 1) / kRegion, ry = (h + kRegion - 1) / kRegion;
  std::vector<double> region_sum(size_t(rx) * ry, 0.0);
  std::vector<int> region_n(size_t(rx) * ry, 0);
  int blocks = 0;
  for (int by = 0; by + kBlock <= h; by += kBlock)
    for (int bx = 0; bx + kBlock <= w; bx += kBlock)
      for (int c = 0; c < 3; ++c) {
        double a = 0, b = 0;
        for (int y = by; y < by + kBlock; ++y)
          for (int x = bx; x < bx + kBlock; ++x) {
            a += test[(size_t(y) * w + x) * 4 + c];
            b += ref[(size_t(y) * w + x) * 4 + c];
          }
        a /= kBlock * kBlock;
        b /= kBlock * kBlock;
        const double e = std::abs(a - b) / (b + 0.05);
        r.mean += e;
        ++blocks;
        const size_t region = size_t(by / kRegion) * rx + bx / kRegion;
        region_sum[region] += e;
        ++region_n[region];
        for (int y = by; y < by + kBlock; ++y)
          for (int x = bx; x < bx + kBlock; ++x) r.per_block[(size_t(y) * w + x) * 4 + c] = float(e);
      }
  r.mean /= std::max(1, blocks);
  for (size_t k = 0; k < region_sum.size(); ++k)
    if (region_n[k] > 0) r.worst_region = std::max(r.worst_region, region_sum[k] / region_n[k]);
  return r;
}

std::vector<float> read_beauty(const std::string& path, int* w, int* h) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return {};
  *w = in->spec().width;
  *h = in->spec().height;
  const auto& spec = in->spec();
  std::vector<float> all(size_t(*w) * *h * spec.nchannels), px(size_t(*w) * *h * 4);
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data());
  const int idx[4] = {spec.channelindex("beauty.R"), spec.channelindex("beauty.G"), spec.channelindex("beauty.B"),
                      spec.channelindex("beauty.A")};
  for (int k : idx)
    if (k < 0) return {};
  for (size_t p = 0; p < size_t(*w) * *h; ++p)
    for (int c = 0; c < 4; ++c) px[p * 4 + c] = all[p * spec.nchannels + idx[c]];
  return px;
}

class ImageRegression : public ::testing::TestWithParam<const char*> {};

TEST_P(ImageRegression, MatchesReference) {
  const std::string name = GetParam();
  const std::string scene = std::string(PHELLEM_SOURCE_DIR) + "/tests/scenes/" + name + ".json";
  const std::string ref_path = std::string(PHELLEM_SOURCE_DIR) + "/reference_images/" + name + ".exr";
  int w = 0, h = 0;
  const auto ref = read_beauty(ref_path, &w, &h);
  ASSERT_FALSE(ref.empty()) << "missing reference " << ref_path;
  const SceneDesc d = load_scene_file(scene);
  std::ifstream in(scene);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto r = test::render_json(text, 0, std::string(PHELLEM_SOURCE_DIR) + "/tests/scenes");
  ASSERT_EQ(r.film.width, w);
  ASSERT_EQ(r.film.height, h);
  const RegressionError e = regression_error(r.film.beauty, ref, w, h);
  std::printf(
      "image regression %s: mean block relative error %.4f (tolerance %.2f), worst 16x16 region %.4f (tolerance %.2f), "
      "%d spp vs reference\n",
      name.c_str(), e.mean, kTolerance, e.worst_region, kRegionTolerance, d.render.spp);
  if (e.mean >= kTolerance || e.worst_region >= kRegionTolerance) {
    Film diff(w, h);
    diff.beauty = e.per_block;
    const std::string diff_path = ::testing::TempDir() + "regression_error_" + name + ".exr";
    write_exr(diff, diff_path);
    std::printf("per-block error image written to %s\n", diff_path.c_str());
  }
  EXPECT_LT(e.mean, kTolerance);
  EXPECT_LT(e.worst_region, kRegionTolerance);
}

// The metric itself: one wrong 16×16 tile in a 256×256 image stays far under the mean's
// tolerance but fails the region maximum.
TEST(ImageRegressionMetric, AWrongTileCannotHideInTheMean) {
  const int w = 256, h = 256;
  std::vector<float> ref(size_t(w) * h * 4, 0.5f), test = ref;
  for (int y = 64; y < 80; ++y)
    for (int x = 128; x < 144; ++x)
      for (int c = 0; c < 3; ++c) test[(size_t(y) * w + x) * 4 + c] = 0.9f;
  const RegressionError e = regression_error(test, ref, w, h);
  EXPECT_LT(e.mean, kTolerance);                  // the average alone would pass it
  EXPECT_NEAR(e.worst_region, 0.4 / 0.55, 1e-5);  // |0.9 − 0.5| / (0.5 + 0.05)
  EXPECT_GT(e.worst_region, kRegionTolerance);
  // And an identical image has no error anywhere.
  const RegressionError same = regression_error(ref, ref, w, h);
  EXPECT_EQ(same.mean, 0.0);
  EXPECT_EQ(same.worst_region, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ImageRegression,
                         ::testing::Values("spheres_env", "box_area_light", "displaced_trunk", "strip_tree", "stress_trunk"));

}  // namespace
}  // namespace phellem
