// Image regression: tiny scenes rendered at low spp against references rendered at high spp
// (scripts/make_reference_images.sh). Metric: mean over 4×4 blocks of
// |test − ref| / (ref + 0.05), per channel, on block averages (noise averages out, structure
// does not). Tolerance 0.06. On failure a per-block error image is written to the test temp directory.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <fstream>

#include "tests/support/render_helpers.h"
#include "io/image_output.h"
#include "scene/scene_parser.h"

namespace phellem {
namespace {

constexpr double kTolerance = 0.06;

std::vector<float> read_beauty(const std::string& path, int* w, int* h) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return {};
  *w = in->spec().width;
  *h = in->spec().height;
  const auto& spec = in->spec();
  std::vector<float> all(size_t(*w) * *h * spec.nchannels), px(size_t(*w) * *h * 4);
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data());
  const int idx[4] = {spec.channelindex("beauty.R"), spec.channelindex("beauty.G"), spec.channelindex("beauty.B"), spec.channelindex("beauty.A")};
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
  double err = 0;
  int blocks = 0;
  Film diff(w, h);
  for (int by = 0; by + 4 <= h; by += 4)
    for (int bx = 0; bx + 4 <= w; bx += 4)
      for (int c = 0; c < 3; ++c) {
        double a = 0, b = 0;
        for (int y = by; y < by + 4; ++y)
          for (int x = bx; x < bx + 4; ++x) {
            a += r.film.beauty[(size_t(y) * w + x) * 4 + c];
            b += ref[(size_t(y) * w + x) * 4 + c];
          }
        a /= 16;
        b /= 16;
        const double e = std::abs(a - b) / (b + 0.05);
        err += e;
        ++blocks;
        for (int y = by; y < by + 4; ++y)
          for (int x = bx; x < bx + 4; ++x) diff.beauty[(size_t(y) * w + x) * 4 + c] = float(e);
      }
  err /= blocks;
  std::printf("image regression %s: mean block relative error %.4f (tolerance %.2f, %d spp vs reference)\n", name.c_str(), err,
              kTolerance, d.render.spp);
  if (err >= kTolerance) {
    const std::string diff_path = ::testing::TempDir() + "regression_error_" + name + ".exr";
    write_exr(diff, diff_path);
    std::printf("per-block error image written to %s\n", diff_path.c_str());
  }
  EXPECT_LT(err, kTolerance);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ImageRegression, ::testing::Values("spheres_env", "box_area_light", "displaced_trunk", "strip_tree", "stress_trunk"));

}  // namespace
}  // namespace phellem
