#include "io/png_encode.h"

#include "io/image_file.h"

#include <stdexcept>
#include <string>

namespace phellem {

std::vector<unsigned char> encode_png(int w, int h, int channels, const uint8_t* pixels) {
  if (w <= 0 || h <= 0 || channels < 1 || channels > 4 || !pixels)
    throw std::invalid_argument("encode_png: " + std::to_string(w) + "x" + std::to_string(h) + " with " +
                                std::to_string(channels) + " channels (expected a positive size and 1-4 channels)");
  OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
  if (channels == 2 || channels == 4) spec.alpha_channel = channels - 1;
  spec.attribute("oiio:UnassociatedAlpha", 1);  // the alpha is stored as given, not divided out
  return encode_image("memory.png", spec, OIIO::TypeDesc::UINT8, pixels);
}

}  // namespace phellem
