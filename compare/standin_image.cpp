// STAND-IN until branches `io22` and `stats` land: read_height_image (channel 0, or a
// patch.exr's `Y` and `phellem:px_per_cm`) and resample (OIIO resize). Delete at the merge.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>

#include "compare/common_scale.h"
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

double common_scale(double a, double b) { return std::min(a, b); }

HeightField resample(const HeightField& f, double sx, double sy, double s) {
  const int W = std::max(1, int(std::lround(f.width * s / sx))), H = std::max(1, int(std::lround(f.height * s / sy)));
  OIIO::ImageSpec spec(f.width, f.height, 1, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf src(spec, const_cast<float*>(f.z.data()));
  OIIO::ImageBuf dst = OIIO::ImageBufAlgo::resize(src, "", 0, OIIO::ROI(0, W, 0, H, 0, 1, 0, 1));
  HeightField out;
  out.width = W;
  out.height = H;
  out.px_per_cm = sx * W / f.width;
  out.z.resize(size_t(W) * size_t(H));
  dst.get_pixels(OIIO::ROI(0, W, 0, H, 0, 1, 0, 1), OIIO::TypeDesc::FLOAT, out.z.data());
  return out;
}

}  // namespace phellem
