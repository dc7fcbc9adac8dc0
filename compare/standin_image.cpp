// STAND-IN until branch `io22` lands: read_height_image (channel 0, or a patch.exr's `Y` and
// `phellem:px_per_cm`) and read_albedo_image. Delete at the merge.
#include <OpenImageIO/imagebuf.h>

#include <algorithm>

#include "io/height_image.h"
#include "util/errors.h"

namespace phellem {

HeightImage read_height_image(const std::string& path) {
  OIIO::ImageBuf buf(path);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) throw UserError(path, "", "cannot read the image: " + buf.geterror());
  const OIIO::ImageSpec& spec = buf.spec();
  HeightImage h;
  h.width = spec.width;
  h.height = spec.height;
  if (const float s = spec.get_float_attribute("phellem:px_per_cm", 0.0f); s > 0) {
    h.kind = HeightImage::Kind::patch;
    h.px_per_cm_x = h.px_per_cm_y = s;
  }
  h.z.resize(size_t(h.width) * size_t(h.height));
  std::vector<float> px(size_t(spec.nchannels));
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      buf.getpixel(x, y, px.data(), int(px.size()));
      h.z[size_t(y) * size_t(h.width) + size_t(x)] = px[0];
    }
  return h;
}

RgbImage read_albedo_image(const std::string& path) {
  throw UserError(path, "--albedo", "stand-in: albedo images are not read yet");
}

}  // namespace phellem
