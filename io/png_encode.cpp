#include "io/png_encode.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>
#include <string>

namespace phellem {

std::vector<unsigned char> encode_png(int w, int h, int channels, const uint8_t* pixels) {
  if (w <= 0 || h <= 0 || channels < 1 || channels > 4 || !pixels)
    throw std::invalid_argument("encode_png: " + std::to_string(w) + "x" + std::to_string(h) + " with " +
                                std::to_string(channels) + " channels (expected a positive size and 1-4 channels)");
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  // The name only selects the format; the bytes go to `proxy` (PNG output supports IOProxy).
  auto out = OIIO::ImageOutput::create("memory.png");
  if (!out || !out->supports("ioproxy"))
    throw std::runtime_error("encode_png: no PNG writer with I/O proxies: " + OIIO::geterror());
  OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
  if (channels == 2 || channels == 4) spec.alpha_channel = channels - 1;
  void* ptr = &proxy;
  spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &ptr);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // the alpha is stored as given, not divided out
  if (!out->open("memory.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, pixels) || !out->close())
    throw std::runtime_error("encode_png: " + out->geterror());
  return bytes;
}

}  // namespace phellem
