// A colour photograph given as a height map is refused (docs/compare.md, "Colour photos are
// not height maps"), while a grey height map saved with three channels, JPEG noise and all,
// is read.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <random>

#include "compare/compare_inputs.h"
#include "io/image_chroma.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

void write_rgb8(const std::string& path, int w, int h, const std::vector<uint8_t>& px, int quality = 0) {
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  if (quality > 0) {
    spec.attribute("Compression", "jpeg:" + std::to_string(quality));
    spec.attribute("jpeg:subsampling", "4:2:0");
  }
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data()) && out->close())
      << OIIO::geterror();
}

// Bark-like relief in grey (R = G = B), plus, per channel, independent noise of `noise` codes,
// and a hue: the brown of a bark photo scaled by `tint` (0 = grey).
std::vector<uint8_t> bark_pixels(int w, int h, double noise, double tint, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0, noise);
  std::vector<uint8_t> px(size_t(w) * size_t(h) * 3);
  const double brown[3] = {1.25, 1.0, 0.78};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double v = 110 + 60 * std::sin(0.3 * x + 0.05 * y) * std::cos(0.02 * y) + 20 * std::sin(1.7 * x);
      for (int c = 0; c < 3; ++c)
        px[(size_t(y) * size_t(w) + size_t(x)) * 3 + size_t(c)] =
            uint8_t(std::clamp(std::lround(v * (1 + tint * (brown[c] - 1)) + n(rng)), 0L, 255L));
    }
  return px;
}

double chroma_of(const std::string& path) {
  const HeightImage h = read_height_image(path);
  return h.chroma;
}

TEST(ColourPhoto, ChromaTellsAColourPhotoFromAGreyMapWithNoise) {
  const std::string d = test::temp_dir("colour_photo");
  // Grey with ±6 codes of independent noise per channel, through JPEG at quality 60, 4:2:0.
  write_rgb8(d + "/grey_noisy.jpg", 256, 256, bark_pixels(256, 256, 6, 0, 1), 60);
  const double grey = chroma_of(d + "/grey_noisy.jpg");
  EXPECT_LT(grey, kColourPhotoChroma / 4) << grey;
  // A faint brown (a fifth of the reference photo's hue) is a colour photo.
  write_rgb8(d + "/faint_brown.png", 256, 256, bark_pixels(256, 256, 6, 0.2, 2));
  const double faint = chroma_of(d + "/faint_brown.png");
  EXPECT_GT(faint, kColourPhotoChroma) << faint;
  // Per pixel the noise alone reads as colour: the block means are what tell them apart.
  std::vector<float> noisy(256 * 256 * 3);
  const auto px = bark_pixels(256, 256, 6, 0, 1);
  for (size_t i = 0; i < px.size(); ++i) noisy[i] = float(px[i]) / 255.0f;
  EXPECT_LT(colour_chroma(noisy.data(), 256, 256, 3), kColourPhotoChroma / 4);
  EXPECT_GT(colour_chroma(noisy.data(), 7, 7, 3), kColourPhotoChroma);  // under 8 px: single pixels
}

TEST(ColourPhoto, GivenAsAHeightMapItIsRefusedNamingAlbedo) {
  const std::string d = test::temp_dir("colour_photo_refused");
  const std::string photo = d + "/photo.png";
  write_rgb8(photo, 256, 256, bark_pixels(256, 256, 3, 1, 3));
  test::expect_user_error([&] { load_input(CompareSource{"B", photo, 10.0, ""}); }, "colour photo", photo, "",
                          "is a colour photograph (chroma ");
  test::expect_user_error([&] { load_input(CompareSource{"B", photo, 10.0, ""}); }, "colour photo", photo, "",
                          "with --albedo B=" + photo + " (there is no --height option: the height map is the input itself)");
  // The same relief in grey, three channels: read.
  const std::string grey = d + "/grey.png";
  write_rgb8(grey, 256, 256, bark_pixels(256, 256, 3, 0, 3));
  EXPECT_NO_THROW(load_input(CompareSource{"B", grey, 10.0, ""}));
}

}  // namespace
}  // namespace phellem
