#include "compare/common_scale.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace phellem {
namespace {

// `data` (height × width × channels) resized to out_w × out_h by ImageBufAlgo::resize with its
// default filter (lanczos3 when shrinking, sized in destination pixels, so anti-aliased).
std::vector<float> resize_pixels(const std::vector<float>& data, int width, int height, int channels, int out_w,
                                 int out_h) {
  if (out_w == width && out_h == height) return data;
  const OIIO::ImageSpec in_spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  const OIIO::ImageBuf src(in_spec, const_cast<float*>(data.data()));  // wraps, read only
  OIIO::ImageBuf dst(OIIO::ImageSpec(out_w, out_h, channels, OIIO::TypeDesc::FLOAT));
  if (!OIIO::ImageBufAlgo::resize(dst, src, "", 0, OIIO::ROI(0, out_w, 0, out_h, 0, 1, 0, channels)))
    throw std::runtime_error("resample: OpenImageIO resize failed: " + dst.geterror());
  std::vector<float> out(size_t(out_w) * size_t(out_h) * size_t(channels));
  if (!dst.get_pixels(OIIO::ROI(0, out_w, 0, out_h, 0, 1, 0, channels), OIIO::TypeDesc::FLOAT, out.data()))
    throw std::runtime_error("resample: OpenImageIO get_pixels failed: " + dst.geterror());
  return out;
}

struct AxisSize {
  int pixels = 0;
  double px_per_cm = 0;
};

// An axis of `pixels` at `own` px/cm brought to `target` (never enlarged). The size is rounded
// up, so the scale it gives is never below the target: rounded to the nearest, it fell up to
// half a pixel short, and two inputs declared at 2 and 4.1 px/cm were measured at 1.999 and
// refused for "the scale is 2 px/cm; compare needs at least 2 px/cm".
AxisSize shrunk(int pixels, double own, double target) {
  if (target >= own) return {pixels, own};
  const int n = std::max(1, int(std::ceil(pixels * (target / own) - 1e-9)));  // 1e-9: 128.0000001 stays 128
  // At least the target: n ≥ pixels·target/own up to the 1e-9 and the rounding of the product.
  return {n, std::max(target, own * n / pixels)};
}

}  // namespace

// Plan §3.0: both inputs are measured at the coarser scale; the finer one is shrunk, neither
// is ever enlarged (upsampling invents no detail but would change the statistics).
double common_scale(double px_per_cm_a, double px_per_cm_b) { return std::min(px_per_cm_a, px_per_cm_b); }

HeightField resample(const HeightField& field, double px_per_cm_x, double px_per_cm_y, double px_per_cm) {
  if (!(px_per_cm_x > 0) || !(px_per_cm_y > 0) || !(px_per_cm > 0))
    throw std::invalid_argument("resample: scales must be positive");
  // Each axis to the target on its own (a FractureField EXR has different scales across and
  // along); never upsample.
  const AxisSize x = shrunk(field.width, px_per_cm_x, px_per_cm), y = shrunk(field.height, px_per_cm_y, px_per_cm);
  HeightField out;
  out.width = x.pixels;
  out.height = y.pixels;
  out.z = resize_pixels(field.z, field.width, field.height, 1, out.width, out.height);
  // The true scale after rounding the size: the mean of the two axes' (they differ by at most
  // a pixel over the image).
  out.px_per_cm = 0.5 * (x.px_per_cm + y.px_per_cm);
  return out;
}

AlbedoField resample(const AlbedoField& albedo, int width, int height) {
  if (width > albedo.width || height > albedo.height || width <= 0 || height <= 0)
    throw std::invalid_argument("resample: albedo can only be shrunk");
  AlbedoField out;
  out.width = width;
  out.height = height;
  out.rgb = resize_pixels(albedo.rgb, albedo.width, albedo.height, 3, width, height);
  return out;
}

}  // namespace phellem
