// io/png_encode: PNG bytes in memory decode back (from memory too) to the very same pixels.
#include <gtest/gtest.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>

#include "io/png_encode.h"
#include "util/hash.h"

namespace phellem {
namespace {

// Decodes PNG `bytes` with OpenImageIO from memory; fills w, h, channels.
std::vector<uint8_t> decode(const std::vector<unsigned char>& bytes, int* w, int* h, int* channels) {
  OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
  void* ptr = &reader;
  OIIO::ImageSpec config;
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &ptr);
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open("memory.png", &config);
  if (!in) throw std::runtime_error(OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  *w = spec.width;
  *h = spec.height;
  *channels = spec.nchannels;
  EXPECT_EQ(in->format_name(), std::string("png"));
  std::vector<uint8_t> px(size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, px.data())) throw std::runtime_error(in->geterror());
  return px;
}

TEST(PngEncode, RoundTripsEveryChannelCount) {
  const int w = 37, h = 23;  // odd sizes: no accidental row padding
  for (int channels = 1; channels <= 4; ++channels) {
    std::vector<uint8_t> px(size_t(w) * h * channels);
    for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(hash_u32(uint32_t(i * 4 + channels)) & 0xFF);
    if (channels == 2 || channels == 4) px[channels - 1] = 0;  // transparent pixel keeps its colour
    const std::vector<unsigned char> png = encode_png(w, h, channels, px.data());
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(std::string(png.begin(), png.begin() + 8), std::string("\x89PNG\r\n\x1a\n", 8)) << channels;
    int dw = 0, dh = 0, dc = 0;
    const std::vector<uint8_t> back = decode(png, &dw, &dh, &dc);
    EXPECT_EQ(dw, w);
    EXPECT_EQ(dh, h);
    EXPECT_EQ(dc, channels);
    EXPECT_EQ(back, px) << channels << " channels";
  }
}

TEST(PngEncode, RefusesBadArguments) {
  const uint8_t px[4] = {1, 2, 3, 4};
  EXPECT_THROW(encode_png(0, 1, 3, px), std::invalid_argument);
  EXPECT_THROW(encode_png(1, 1, 5, px), std::invalid_argument);
  EXPECT_THROW(encode_png(1, 1, 3, nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace phellem
