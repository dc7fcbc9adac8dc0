#include "scene/displacement_map.h"

#include <cmath>

#include "io/height_image.h"
#include "util/errors.h"

namespace phellem {

DisplacementMap read_displacement_map(const std::string& path) {
  HeightImage h = read_height_image(path);  // bounded, finite (io/height_image.h)
  if (h.width < 2 || h.height < 2)
    throw UserError(path, "header",
                    "a displacement map of " + std::to_string(h.width) + "×" + std::to_string(h.height) +
                        " px has nothing to interpolate; it needs at least 2×2 px (for a constant offset, move the object)");
  DisplacementMap m;
  m.width = h.width;
  m.height = h.height;
  m.value = std::move(h.z);
  return m;
}

namespace {

// Texel index and weight along one axis: the texel centres sit at (i + ½) / n.
struct Tap {
  int i0, i1;
  float t;
};

Tap tap(float x, int n, bool clamp) {
  const float f = x * float(n) - 0.5f;
  if (clamp) {
    if (f <= 0.0f) return {0, 0, 0.0f};
    if (f >= float(n - 1)) return {n - 1, n - 1, 0.0f};
    const int i = int(f);
    return {i, i + 1, f - float(i)};
  }
  const float fl = std::floor(f);
  const long i = long(fl);
  const int i0 = int(((i % n) + n) % n);
  return {i0, (i0 + 1) % n, f - fl};
}

}  // namespace

float sample_displacement_map(const DisplacementMap& m, const Vec2f& uv, bool clamp) {
  // Row 0 is the top of the image: v = 1 − (row + ½) / height.
  const Tap x = tap(uv.x(), m.width, clamp), y = tap(1.0f - uv.y(), m.height, clamp);
  auto at = [&](int i, int j) { return m.value[size_t(j) * size_t(m.width) + size_t(i)]; };
  const float top = at(x.i0, y.i0) + (at(x.i1, y.i0) - at(x.i0, y.i0)) * x.t;
  const float bottom = at(x.i0, y.i1) + (at(x.i1, y.i1) - at(x.i0, y.i1)) * x.t;
  return top + (bottom - top) * y.t;
}

}  // namespace phellem
