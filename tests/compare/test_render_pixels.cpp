// compare/render_pixels: which pixels of a render `compare` measures. Synthetic render EXRs
// (written with OIIO, the channel names of write_exr) with background, a second object,
// partly covered pixels and surfaces facing away, whose largest rectangle of bark is known.
#include <gtest/gtest.h>

#include <cmath>

#include "compare/compare_inputs.h"
#include "compare/render_pixels.h"
#include "io/height_image.h"
#include "io/image_output.h"
#include "tests/support/synthetic_render.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

std::string dir() {
  static const std::string d = test::temp_dir("render_pixels");
  return d;
}

// 48×36 px of a plane z = 0 seen from z = 5 m; pixels 2^-5 m apart across (0.32 px/cm) and
// 2^-6 m down (0.64 px/cm), so the facing test's ±1 cm box is 0 px across and ±1 px down.
//   background: rows 0–1, columns 0–1 and 46–47, and the pixel (30, 12);
//   object 2: columns 40–45; object 1: columns 2–39 (1290 fully covered pixels);
//   pixel (10, 20) half covered (beauty.A 0.5);
//   columns 20–22 of object 1 turned 50° away from the camera (past the 30° default).
// The largest rectangle of object 1 facing the camera is then columns 23–39, rows 13–35.
constexpr double kStepX = 0x1p-5, kStepY = 0x1p-6;
test::SyntheticRender scene() {
  test::SyntheticRender r(48, 36);
  const float s50 = std::sin(50.0f * 3.14159265f / 180), c50 = std::cos(50.0f * 3.14159265f / 180);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const size_t p = r.at(x, y);
      r.set_position(x, y, float(x * kStepX), float(-y * kStepY), 0);
      r.displacement[p] = 0.001f * float((x * 7 + y * 3) % 5);
      const bool background = y < 2 || x < 2 || x > 45 || (x == 30 && y == 12);
      r.alpha[p] = background ? 0.0f : 1.0f;
      r.object_id[p] = background ? 0.0f : x >= 40 ? 2.0f : 1.0f;
      if (background) r.set_position(x, y, 0, 0, 0);
      if (x >= 20 && x <= 22) r.set_normal(x, y, s50, 0, c50);
    }
  r.alpha[r.at(10, 20)] = 0.5f;
  r.camera_position = std::array<float, 3>{0.75f, -0.28f, 5.0f};
  return r;
}

HeightImage read_scene(const std::string& name, const test::SyntheticRender& r) {
  const std::string path = dir() + "/" + name + ".exr";
  test::write_synthetic_render(path, r);
  return read_height_image(path);
}

TEST(RenderPixels, TheSyntheticRenderHasWriteExrsChannels) { EXPECT_EQ(test::render_channel_names(), exr_channel_names()); }

TEST(RenderPixels, ChoosesExactlyTheBarkPixelsAndTheirScale) {
  const HeightImage h = read_scene("scene", scene());
  ASSERT_EQ(h.kind, HeightImage::Kind::render);
  ASSERT_TRUE(h.render && h.render->camera);
  const RenderSelection s = render_selection(h, {}, "scene.exr", "A");
  EXPECT_EQ(s.object_id, 1);  // the object covering most pixels
  EXPECT_FALSE(s.object_chosen);
  EXPECT_EQ(s.object_pixels, 38 * 34 - 2);
  EXPECT_EQ(s.mask_pixels, 38 * 34 - 2 - 3 * 34);
  EXPECT_EQ(s.rect, (PixelRect{23, 13, 17, 23}));
  EXPECT_EQ(s.position_px_per_cm_x, 1 / (100 * kStepX));  // 0.32
  EXPECT_EQ(s.position_px_per_cm_y, 1 / (100 * kStepY));  // 0.64
  EXPECT_EQ(s.render_width, 48);
  EXPECT_EQ(s.render_height, 36);
}

TEST(RenderPixels, EachExclusionMatters) {
  // Facing ignored (180°): the turned columns are bark again, and no camera is needed.
  test::SyntheticRender r = scene();
  r.camera_position.reset();
  const HeightImage any_way = read_scene("no_camera", r);
  EXPECT_EQ(render_selection(any_way, {std::nullopt, 180}, "f", "A").rect, (PixelRect{11, 13, 29, 23}));
  // Below 180° the camera is needed.
  test::expect_user_error([&] { render_selection(any_way, {}, "no_camera.exr", "A"); }, "no camera", "no_camera.exr",
                          "--facing-deg A", "--facing-deg A=180");
  // A wider angle takes the turned columns too.
  const HeightImage h = read_scene("scene2", scene());
  EXPECT_EQ(render_selection(h, {std::nullopt, 55}, "f", "A").rect, (PixelRect{11, 13, 29, 23}));
  // The other object, chosen.
  const RenderSelection two = render_selection(h, {2, 30}, "f", "A");
  EXPECT_EQ(two.object_id, 2);
  EXPECT_TRUE(two.object_chosen);
  EXPECT_EQ(two.rect, (PixelRect{40, 2, 6, 34}));
  test::expect_user_error([&] { render_selection(h, {7, 30}, "scene.exr", "B"); }, "absent object", "scene.exr", "--object B",
                          "object 7 covers no pixel of this render; the objects it shows: 1 (1290 px), 2 (204 px)");
  // The half-covered pixel counts as background: covered (and the columns facing), the left
  // block is whole and wins.
  test::SyntheticRender full = scene();
  full.alpha[full.at(10, 20)] = 1.0f;
  for (int y = 0; y < 36; ++y)
    for (int x = 20; x <= 22; ++x) full.set_normal(x, y, 0, 0, 1);
  EXPECT_EQ(render_selection(read_scene("full", full), {}, "f", "A").rect, (PixelRect{2, 2, 28, 34}));
}

TEST(RenderPixels, TheStandardWorldToCameraMatrixGivesTheCamera) {
  test::SyntheticRender r = scene();
  r.camera_position.reset();
  // Row vectors (Imath): p_camera = p_world · M, M = [I 0; −c 1] for a camera at c looking down −z.
  r.world_to_camera = std::array<float, 16>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -0.75f, 0.28f, -5.0f, 1};
  const HeightImage h = read_scene("matrix", r);
  ASSERT_TRUE(h.render->camera);
  EXPECT_NEAR((*h.render->camera - Eigen::Vector3d(0.75, -0.28, 5)).norm(), 0, 1e-6);
  EXPECT_EQ(render_selection(h, {}, "f", "A").rect, (PixelRect{23, 13, 17, 23}));
}

// The walls of a fissure face sideways; the facing test reads the normal averaged over ±1 cm,
// so a narrow wall stays in the bark while a wide surface turned away does not.
TEST(RenderPixels, FissureWallsDoNotCutTheBark) {
  test::SyntheticRender r(60, 40);  // 2^-10 m apart: 10.24 px/cm, a ±10 px box
  const float s60 = std::sin(60.0f * 3.14159265f / 180), c60 = std::cos(60.0f * 3.14159265f / 180);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      r.set_position(x, y, float(x * 0x1p-10), float(-y * 0x1p-10), 0);
      if ((x >= 30 && x <= 32) || x >= 45) r.set_normal(x, y, s60, 0, c60);
    }
  r.camera_position = std::array<float, 3>{float(30 * 0x1p-10), float(-20 * 0x1p-10), 100.0f};
  const RenderSelection s = render_selection(read_scene("walls", r), {}, "f", "A");
  // Column 44's box holds 10 turned columns and 11 flat ones (28° off), column 45's 11 and 10 (32°).
  EXPECT_EQ(s.rect, (PixelRect{0, 0, 45, 40}));
  EXPECT_NEAR(s.position_px_per_cm_x, 10.24, 1e-9);
}

TEST(RenderPixels, TooSmallARectangleIsRefusedNamingIt) {
  const HeightImage h = read_scene("small", scene());
  test::expect_user_error([&] { select_render_pixels(h, {}, "small.exr", "A"); }, "small", "small.exr", "render",
                          "the largest rectangle of bark pixels (fully covered by object 1, facing the camera within 30°) is "
                          "17×23 px at (23, 13), 53.1×35.9 cm at 0.32×0.64 px/cm (of 1188 such pixels); compare needs at least "
                          "128 px and 20 cm on each side");
}

TEST(RenderPixels, LoadInputCropsTheRenderAndTakesItsAlbedo) {
  // 300×260 px at 10.24 px/cm with a background border of 10 px: 280×240 px (27.3×23.4 cm) of bark.
  test::SyntheticRender r(300, 260);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const size_t p = r.at(x, y);
      r.set_position(x, y, float(x * 0x1p-10), float(-y * 0x1p-10), 0);
      r.displacement[p] = float(x + 1000 * y);
      r.albedo[3 * p] = float(x), r.albedo[3 * p + 1] = float(y), r.albedo[3 * p + 2] = 0.25f;
      const bool background = x < 10 || y < 10 || x >= 290 || y >= 250;
      r.alpha[p] = background ? 0.0f : 1.0f;
      r.object_id[p] = background ? 0.0f : 3.0f;
    }
  r.camera_position = std::array<float, 3>{0.15f, -0.13f, 3.0f};
  const std::string path = dir() + "/crop.exr";
  test::write_synthetic_render(path, r);
  const LoadedInput in = load_input(CompareSource{"A", path, std::nullopt, ""});
  ASSERT_TRUE(in.render);
  EXPECT_EQ(in.render->rect, (PixelRect{10, 10, 280, 240}));
  EXPECT_EQ(in.render->object_id, 3);
  EXPECT_EQ(in.scale_origin, ScaleOrigin::render_positions);
  EXPECT_NEAR(in.px_per_cm_x, 10.24, 1e-9);
  EXPECT_NEAR(in.px_per_cm_y, 10.24, 1e-9);
  ASSERT_EQ(in.image.width, 280);
  ASSERT_EQ(in.image.height, 240);
  EXPECT_EQ(in.image.z[0], float(10 + 1000 * 10));
  EXPECT_EQ(in.image.z[size_t(239) * 280 + 279], float(289 + 1000 * 249));
  ASSERT_TRUE(in.albedo && in.albedo_from_render);
  EXPECT_EQ(in.albedo->rgb[0], 10.0f);
  EXPECT_EQ(in.albedo->rgb[1], 10.0f);
  EXPECT_EQ(in.albedo->rgb[3 * (size_t(239) * 280 + 279)], 289.0f);
  // --scale overrides the positions' scale.
  const LoadedInput given = load_input(CompareSource{"A", path, 5.0, ""});
  EXPECT_EQ(given.px_per_cm_x, 5.0);
  EXPECT_EQ(given.scale_origin, ScaleOrigin::option);
}

}  // namespace
}  // namespace phellem
