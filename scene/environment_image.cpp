#include "scene/environment_image.h"

#include <algorithm>
#include <cmath>

#include "io/builtin_files.h"
#include "io/image_decode.h"
#include "io/image_limits.h"
#include "util/errors.h"

namespace phellem {

std::vector<float> load_environment_image(const LightDesc& l, int* w, int* h) {
  std::string why;
  if (!read_image_header(l.file, &why))  // bounds the size before anything is decoded
    throw UserError(l.where.file, l.where.path + "/file", "cannot read environment map " + l.file + ": " + why);
  ImageSource src = open_image_source(l.file);  // a file or a "builtin:" file's bytes
  if (!src.in) throw UserError(l.where.file, l.where.path + "/file", "cannot read environment map " + l.file + ": " + src.why);
  const OIIO::ImageSpec spec = src.in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
    throw UserError(l.where.file, l.where.path + "/file", "environment map has no pixels");
  *w = spec.width;
  *h = spec.height;
  std::vector<float> px(size_t(spec.width) * spec.height * spec.nchannels);
  if (auto why = decode_image(*src.in, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
    throw UserError(l.where.file, l.where.path + "/file", "cannot read environment map " + l.file + ": " + *why);
  std::vector<float> rgb(size_t(spec.width) * spec.height * 3);
  for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i) {
    float* c = &rgb[i * 3];
    for (int k = 0; k < 3; ++k) {
      const float v = px[i * spec.nchannels + std::min(k, spec.nchannels - 1)];
      c[k] = std::isfinite(v) ? std::max(0.0f, v) : 0.0f;
    }
    // Scaled, not clipped per channel: a clamped texel keeps its hue.
    const float y = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
    if (l.clamp > 0 && y > l.clamp)
      for (int k = 0; k < 3; ++k) c[k] *= l.clamp / y;
  }
  return rgb;
}

}  // namespace phellem
