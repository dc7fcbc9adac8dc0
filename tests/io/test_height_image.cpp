// io/height_image: every kind of height image `compare` and `fit` read (plain 8/16-bit and
// float images as raw code values, FractureField EXRs, render EXRs with the displacement AOV,
// patch.exr) and every way a file can be refused. Files are written here, in a temp folder.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "io/film.h"
#include "io/height_image.h"
#include "io/image_output.h"
#include "renderer/camera.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

using test::expect_user_error;
using test::lying_hdr;

struct Attr {
  std::string name;
  float value;
};

// Writes a w×h image of `type` from interleaved `pixels` (in `type`'s C type).
void write_image(const std::string& path, int w, int h, const std::vector<std::string>& names, OIIO::TypeDesc type,
                 const void* pixels, const std::vector<Attr>& attrs = {}, const std::string& colorspace = "") {
  OIIO::ImageSpec spec(w, h, int(names.size()), type);
  spec.channelnames = names;
  spec.alpha_channel = -1;
  for (const Attr& a : attrs) spec.attribute(a.name, a.value);
  if (!colorspace.empty()) spec.attribute("oiio:ColorSpace", colorspace);
  if (path.size() > 4 && path.substr(path.size() - 4) == ".jpg") spec.attribute("CompressionQuality", 100);
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out) << OIIO::geterror();
  ASSERT_TRUE(out->open(path, spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(type, pixels)) << out->geterror();
  ASSERT_TRUE(out->close()) << out->geterror();
}

std::string dir() {
  static const std::string d = test::temp_dir("height_image");
  return d;
}

TEST(HeightImage, SixteenBitPngAndTiffGiveRawCodeValues) {
  // Tagged sRGB: a linearizing reader would turn 32768 into about 0.216, not 0.5.
  const std::vector<uint16_t> codes = {0, 1000, 1637, 32768, 65029, 65535};
  for (const char* ext : {".png", ".tif"}) {
    const std::string path = dir() + "/grey16" + ext;
    write_image(path, 3, 2, {"Y"}, OIIO::TypeDesc::UINT16, codes.data(), {}, "sRGB");
    const HeightImage h = read_height_image(path);
    EXPECT_EQ(h.kind, HeightImage::Kind::plain);
    ASSERT_EQ(h.width, 3);
    ASSERT_EQ(h.height, 2);
    ASSERT_EQ(h.z.size(), 6u);
    for (size_t i = 0; i < codes.size(); ++i) EXPECT_EQ(h.z[i], float(codes[i]) / 65535.0f) << ext << " code " << codes[i];
    EXPECT_EQ(h.z[1], 1000.0f / 65535.0f);
    EXPECT_EQ(h.px_per_cm_x, 0);  // a plain image states no scale
    EXPECT_EQ(h.px_per_cm_y, 0);
  }
}

TEST(HeightImage, EightBitPngGivesCodeValuesAndColourTheMeanOfThree) {
  const std::vector<uint8_t> grey = {0, 1, 100, 128, 254, 255};
  write_image(dir() + "/grey8.png", 6, 1, {"Y"}, OIIO::TypeDesc::UINT8, grey.data(), {}, "sRGB");
  const HeightImage g = read_height_image(dir() + "/grey8.png");
  for (size_t i = 0; i < grey.size(); ++i) EXPECT_EQ(g.z[i], float(grey[i]) / 255.0f) << int(grey[i]);
  // RGB (10, 20, 60) and (255, 0, 0): the mean of the code values, 30 and 85.
  const std::vector<uint8_t> rgb = {10, 20, 60, 255, 0, 0};
  write_image(dir() + "/rgb8.png", 2, 1, {"R", "G", "B"}, OIIO::TypeDesc::UINT8, rgb.data(), {}, "sRGB");
  const HeightImage c = read_height_image(dir() + "/rgb8.png");
  EXPECT_NEAR(c.z[0], 30.0f / 255.0f, 1e-7f);
  EXPECT_NEAR(c.z[1], 85.0f / 255.0f, 1e-7f);
}

TEST(HeightImage, JpegGivesCodeValues) {
  // A uniform grey 16×16 JPEG at quality 100 decodes to its code within one step (DC only).
  const std::vector<uint8_t> grey(16 * 16, 100);
  write_image(dir() + "/grey.jpg", 16, 16, {"Y"}, OIIO::TypeDesc::UINT8, grey.data(), {}, "sRGB");
  const HeightImage h = read_height_image(dir() + "/grey.jpg");
  EXPECT_EQ(h.kind, HeightImage::Kind::plain);
  for (float z : h.z) {
    const float code = z * 255.0f;
    EXPECT_NEAR(code, 100.0f, 1.0f);
    EXPECT_NEAR(code, std::round(code), 1e-4f);  // a whole code value, not a linearized one
  }
}

TEST(HeightImage, FloatImagesKeepTheirValues) {
  const std::vector<float> z = {-0.25f, 0.0f, 3.5f, 1e-3f};
  for (const char* ext : {".exr", ".tif"}) {
    const std::string path = dir() + "/float" + ext;
    write_image(path, 2, 2, {"Y"}, OIIO::TypeDesc::FLOAT, z.data());
    const HeightImage h = read_height_image(path);
    EXPECT_EQ(h.kind, HeightImage::Kind::plain);
    EXPECT_EQ(h.z, z) << ext;
  }
}

TEST(HeightImage, FractureFieldGivesMinusDepthAndItsScale) {
  // 40×20 texels over a 0.5 m circumference and a 2 m length: 0.8 px/cm across, 0.1 along.
  const int w = 40, h = 20;
  std::vector<float> px(size_t(w) * h * 3);
  for (int p = 0; p < w * h; ++p) {
    px[3 * p] = 0.3f;                        // color.R
    px[3 * p + 1] = 0.001f * float(p % 17);  // depth
    px[3 * p + 2] = 1.0f;                    // opening
  }
  write_image(dir() + "/field.exr", w, h, {"color.R", kFieldDepthChannel, "opening"}, OIIO::TypeDesc::FLOAT, px.data(),
              {{kFieldLengthAttribute, 2.0f}, {kFieldCircumferenceAttribute, 0.5f}});
  const HeightImage f = read_height_image(dir() + "/field.exr");
  EXPECT_EQ(f.kind, HeightImage::Kind::fracture_field);
  EXPECT_NEAR(f.px_per_cm_x, 0.8, 1e-6);
  EXPECT_NEAR(f.px_per_cm_y, 0.1, 1e-6);
  ASSERT_EQ(f.z.size(), size_t(w) * h);
  for (int p = 0; p < w * h; ++p) ASSERT_EQ(f.z[p], -px[3 * p + 1]) << p;

  // A depth channel without the attributes is a FractureField missing its scale.
  write_image(dir() + "/field_bare.exr", w, h, {"color.R", kFieldDepthChannel, "opening"}, OIIO::TypeDesc::FLOAT, px.data());
  expect_user_error([] { read_height_image(dir() + "/field_bare.exr"); }, "bare field", dir() + "/field_bare.exr",
                    kFieldCircumferenceAttribute, "missing from the header");
  write_image(dir() + "/field_no_length.exr", w, h, {"color.R", kFieldDepthChannel, "opening"}, OIIO::TypeDesc::FLOAT, px.data(),
              {{kFieldCircumferenceAttribute, 0.5f}});
  expect_user_error([] { read_height_image(dir() + "/field_no_length.exr"); }, "no length", dir() + "/field_no_length.exr",
                    kFieldLengthAttribute, "missing from the header");
  write_image(dir() + "/field_zero.exr", w, h, {"color.R", kFieldDepthChannel, "opening"}, OIIO::TypeDesc::FLOAT, px.data(),
              {{kFieldLengthAttribute, 2.0f}, {kFieldCircumferenceAttribute, 0.0f}});
  expect_user_error([] { read_height_image(dir() + "/field_zero.exr"); }, "zero circumference", dir() + "/field_zero.exr",
                    kFieldCircumferenceAttribute, "must be a positive number");
  write_image(dir() + "/field_no_depth.exr", w, h, {"color.R", "color.G", "opening"}, OIIO::TypeDesc::FLOAT, px.data(),
              {{kFieldLengthAttribute, 2.0f}, {kFieldCircumferenceAttribute, 0.5f}});
  expect_user_error([] { read_height_image(dir() + "/field_no_depth.exr"); }, "no depth", dir() + "/field_no_depth.exr",
                    kFieldDepthChannel, "missing");
}

TEST(HeightImage, PatchStatesItsScale) {
  const std::vector<float> z = {0.5f, -1.0f, 2.0f, 0.0f, 1.0f, -0.5f};
  write_image(dir() + "/patch.exr", 3, 2, {kPatchHeightChannel}, OIIO::TypeDesc::FLOAT, z.data(), {{kPxPerCmAttribute, 7.5f}});
  const HeightImage p = read_height_image(dir() + "/patch.exr");
  EXPECT_EQ(p.kind, HeightImage::Kind::patch);
  EXPECT_EQ(p.px_per_cm_x, 7.5);
  EXPECT_EQ(p.px_per_cm_y, 7.5);
  EXPECT_EQ(p.z, z);
  write_image(dir() + "/patch_bad.exr", 3, 2, {kPatchHeightChannel}, OIIO::TypeDesc::FLOAT, z.data(),
              {{kPxPerCmAttribute, -2.0f}});
  expect_user_error([] { read_height_image(dir() + "/patch_bad.exr"); }, "negative scale", dir() + "/patch_bad.exr",
                    kPxPerCmAttribute, "must be a positive number");
  write_image(dir() + "/patch_no_y.exr", 3, 2, {"Z"}, OIIO::TypeDesc::FLOAT, z.data(), {{kPxPerCmAttribute, 7.5f}});
  expect_user_error([] { read_height_image(dir() + "/patch_no_y.exr"); }, "no Y", dir() + "/patch_no_y.exr", kPatchHeightChannel,
                    "missing");
}

// A render EXR as `phellem render` writes it (write_exr), from a hand-filled film.
Film displaced_film(int w, int h) {
  Film f(w, h);
  for (int p = 0; p < w * h; ++p) {
    f.displacement[size_t(p)] = 0.001f * float(p % 7) - 0.004f;
    f.object_id[size_t(p)] = 1;
  }
  return f;
}

TEST(HeightImage, RenderGivesTheDisplacementLayer) {
  const Film f = displaced_film(5, 4);
  write_exr(f, dir() + "/render.exr");
  const HeightImage r = read_height_image(dir() + "/render.exr");
  EXPECT_EQ(r.kind, HeightImage::Kind::render);
  EXPECT_EQ(r.px_per_cm_x, 0);  // --scale is required
  ASSERT_EQ(r.z.size(), f.displacement.size());
  for (size_t p = 0; p < r.z.size(); ++p) EXPECT_NEAR(r.z[p], f.displacement[p], 4e-6f) << p;  // half: 2^-11 relative

  // A render with background is read whole, its layers with it (before issue 44 it was
  // refused here; compare/render_pixels.h now chooses the bark pixels).
  Film bg = displaced_film(5, 4);
  bg.object_id[2 * 5 + 3] = 0;  // (3, 2)
  bg.object_id[3 * 5 + 4] = 0;
  for (int p = 0; p < 20; ++p) {
    bg.beauty[size_t(p) * 4 + 3] = p == 2 * 5 + 3 || p == 3 * 5 + 4 ? 0.0f : 1.0f;
    bg.position[size_t(p) * 3] = 1.0f + 0x1p-14f * float(p);  // float in the file: exact
    bg.normal[size_t(p) * 3 + 2] = 1.0f;
    bg.albedo[size_t(p) * 3 + 1] = 0.25f;
  }
  write_exr(bg, dir() + "/render_bg.exr");
  const HeightImage b = read_height_image(dir() + "/render_bg.exr");
  ASSERT_TRUE(b.render);
  EXPECT_EQ(b.render->object_id[2 * 5 + 3], 0.0f);
  EXPECT_EQ(b.render->object_id[0], 1.0f);
  EXPECT_EQ(b.render->alpha[3 * 5 + 4], 0.0f);
  EXPECT_EQ(b.render->alpha[0], 1.0f);
  for (int p = 0; p < 20; ++p) EXPECT_EQ(b.render->position[size_t(p) * 3], 1.0f + 0x1p-14f * float(p)) << p;
  EXPECT_EQ(b.render->normal[2], 1.0f);
  EXPECT_EQ(b.render->albedo[1], 0.25f);
  EXPECT_FALSE(b.render->camera);  // written without one
  // A render from before the displacement layer: refused, not read as a plain image.
  const std::vector<float> old(5 * 4 * 2, 1.0f);
  write_image(dir() + "/render_old.exr", 5, 4, {"beauty.R", kRenderObjectIdChannel}, OIIO::TypeDesc::FLOAT, old.data());
  expect_user_error([] { read_height_image(dir() + "/render_old.exr"); }, "old render", dir() + "/render_old.exr",
                    kRenderDisplacementChannel, "render it again");
}

// write_exr states the camera twice: phellem:camera_position, and the standard worldToCamera
// (from which a render whose phellem attribute was lost still gives it).
TEST(HeightImage, RenderStatesItsCamera) {
  const Film f = displaced_film(5, 4);
  CameraDesc desc;
  desc.position = Vec3f(0.3f, 1.7f, 2.2f);
  desc.look_at = Vec3f(0, 1.2f, 0);
  const Camera camera(desc, 5, 4);
  write_exr(f, dir() + "/render_camera.exr", ExrCamera{camera.position(), camera.model().view()});
  const HeightImage r = read_height_image(dir() + "/render_camera.exr");
  ASSERT_TRUE(r.render && r.render->camera);
  EXPECT_EQ(*r.render->camera, Eigen::Vector3d(0.3f, 1.7f, 2.2f));
  OIIO::ImageBuf buf(dir() + "/render_camera.exr");
  ASSERT_TRUE(buf.read()) << buf.geterror();
  buf.specmod().erase_attribute(kCameraPositionAttribute);
  ASSERT_TRUE(buf.write(dir() + "/render_matrix.exr")) << buf.geterror();
  const HeightImage m = read_height_image(dir() + "/render_matrix.exr");
  ASSERT_TRUE(m.render && m.render->camera);
  EXPECT_NEAR((*m.render->camera - Eigen::Vector3d(0.3, 1.7, 2.2)).norm(), 0, 1e-5);
}

TEST(HeightImage, BadFilesAreUserErrors) {
  const std::string missing = dir() + "/missing.png";
  expect_user_error([&] { read_height_image(missing); }, "missing", missing, "", "no such file");
  expect_user_error([&] { read_albedo_image(missing); }, "missing albedo", missing, "", "no such file");

  const std::string garbage = dir() + "/garbage.png";
  test::write_text(garbage, std::string("not an image at all, just text\n") + std::string(200, '\x7f'));
  expect_user_error([&] { read_height_image(garbage); }, "garbage", garbage, "header", "not a readable image");

  // A valid PNG cut in the middle of its pixel data: the header reads, the pixels do not.
  std::vector<uint16_t> ramp(64 * 64);
  for (size_t i = 0; i < ramp.size(); ++i) ramp[i] = uint16_t(i * 977 % 65536);
  write_image(dir() + "/full.png", 64, 64, {"Y"}, OIIO::TypeDesc::UINT16, ramp.data());
  const std::string bytes = test::read_text(dir() + "/full.png");
  ASSERT_GT(bytes.size(), 200u);
  const std::string cut = dir() + "/cut.png";
  test::write_text(cut, bytes.substr(0, bytes.size() / 2));
  expect_user_error([&] { read_height_image(cut); }, "truncated", cut, "pixels", "cannot decode the pixels");

  // Sizes the header claims: refused before anything is allocated.
  const std::string big = lying_hdr(dir() + "/big.hdr", 100000, 100000);
  expect_user_error([&] { read_height_image(big); }, "lying header", big, "header", "the image is 100000x100000");
  expect_user_error([&] { read_albedo_image(big); }, "lying header albedo", big, "header", "the image is 100000x100000");
  const std::string empty = lying_hdr(dir() + "/empty.hdr", 0, 5);
  try {
    read_height_image(empty);
    ADD_FAILURE() << "a 0-pixel image was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), empty);
    EXPECT_EQ(e.where(), "header") << e.what();
  }

  std::vector<float> z(4 * 3, 0.25f);
  z[1 * 4 + 2] = std::numeric_limits<float>::quiet_NaN();
  z[2 * 4 + 3] = std::numeric_limits<float>::infinity();
  write_image(dir() + "/nan.exr", 4, 3, {"Y"}, OIIO::TypeDesc::FLOAT, z.data());
  expect_user_error([] { read_height_image(dir() + "/nan.exr"); }, "NaN", dir() + "/nan.exr", "pixels",
                    "2 value(s) are not finite, the first NaN at pixel (2, 1)");
}

// The Poly Haven displacement scans in ../shared/reference (outside the repository: skipped
// where it is absent). The PNG's code values were decoded independently (zlib and the PNG row
// filters in Python): range 1637–65029, sum 44385639588, pixel (511, 300) = 45366.
TEST(HeightImage, ReferenceScansReadAsTheirCodeValues) {
  const std::string photos = std::string(PHELLEM_SOURCE_DIR) + "/../shared/reference/photos";
  if (!std::ifstream(photos + "/pine_bark_polyhaven_disp.png")) GTEST_SKIP() << "no reference scans in " << photos;
  const HeightImage pine = read_height_image(photos + "/pine_bark_polyhaven_disp.png");
  ASSERT_EQ(pine.width, 1024);
  ASSERT_EQ(pine.height, 1024);
  double sum = 0;
  float lo = 1, hi = 0;
  for (float z : pine.z) {
    const double code = std::round(double(z) * 65535.0);
    ASSERT_EQ(z, float(code) / 65535.0f);  // exactly a code value over 65535
    sum += code;
    lo = std::min(lo, z), hi = std::max(hi, z);
  }
  EXPECT_EQ(lo, 1637.0f / 65535.0f);
  EXPECT_EQ(hi, 65029.0f / 65535.0f);
  EXPECT_EQ(sum, 44385639588.0);
  EXPECT_EQ(pine.z[300 * 1024 + 511], 45366.0f / 65535.0f);
  // The 8-bit JPEG: whole code values 0–254 (a linearized read would not be whole).
  const HeightImage brown = read_height_image(photos + "/bark_brown_01_polyhaven_disp.jpg");
  lo = 1, hi = 0;
  for (float z : brown.z) {
    ASSERT_EQ(z, std::round(z * 255.0f) / 255.0f);
    lo = std::min(lo, z), hi = std::max(hi, z);
  }
  EXPECT_EQ(lo, 0.0f);
  EXPECT_EQ(hi, 254.0f / 255.0f);
}

// sRGB EOTF (IEC 61966-2-1), the reference for the OCIO texture transform.
float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

TEST(AlbedoImage, EightBitIsDecodedFromSrgbAndFloatKept) {
  const std::vector<uint8_t> rgb = {0, 128, 255, 10, 60, 200};
  write_image(dir() + "/albedo.png", 2, 1, {"R", "G", "B"}, OIIO::TypeDesc::UINT8, rgb.data(), {}, "sRGB");
  const RgbImage a = read_albedo_image(dir() + "/albedo.png");
  ASSERT_EQ(a.width, 2);
  ASSERT_EQ(a.rgb.size(), 6u);
  for (size_t i = 0; i < rgb.size(); ++i) EXPECT_NEAR(a.rgb[i], srgb_to_linear(rgb[i] / 255.0f), 2e-3f) << i;
  EXPECT_NEAR(a.rgb[1], 0.2158f, 2e-3f);  // 128: about a fifth, not a half

  const std::vector<uint8_t> grey = {128};
  write_image(dir() + "/albedo_grey.png", 1, 1, {"Y"}, OIIO::TypeDesc::UINT8, grey.data());
  const RgbImage g = read_albedo_image(dir() + "/albedo_grey.png");
  ASSERT_EQ(g.rgb.size(), 3u);
  for (float c : g.rgb) EXPECT_NEAR(c, srgb_to_linear(128 / 255.0f), 2e-3f);

  const std::vector<float> lin = {0.5f, 0.25f, 2.0f, 0.0f, 0.125f, 1.0f};
  write_image(dir() + "/albedo.exr", 2, 1, {"R", "G", "B"}, OIIO::TypeDesc::FLOAT, lin.data());
  EXPECT_EQ(read_albedo_image(dir() + "/albedo.exr").rgb, lin);
}

}  // namespace
}  // namespace phellem
