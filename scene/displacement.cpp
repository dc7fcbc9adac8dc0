#include "scene/displacement.h"

#include "scene/displacement_map.h"
#include "util/hash.h"
#include "util/noise.h"

namespace phellem {

DisplacementFn zero_displacement() {
  return [](const Vec2f&, const Vec3f&) { return 0.0f; };
}

DisplacementFn make_displacement(const DisplacementDesc& d) {
  const uint32_t seed = fold_seed(d.seed);  // the noise takes 32 bits; identity below 2^32
  if (d.type == DisplacementDesc::Type::Image && d.map) {
    return [map = d.map, scale = d.scale, mid = d.midlevel, repeat = d.uv_repeat, clamp = d.clamp](const Vec2f& uv, const Vec3f&) {
      return scale * (sample_displacement_map(*map, uv * repeat, clamp) - mid);
    };
  }
  if (d.type != DisplacementDesc::Type::Grooves && d.type != DisplacementDesc::Type::Noise) return zero_displacement();
  if (d.amplitude == 0.0f) return zero_displacement();
  if (d.type == DisplacementDesc::Type::Noise) {
    return [d, seed](const Vec2f&, const Vec3f& p) { return d.amplitude * fbm(p * d.frequency, seed, 4); };
  }
  // Grooves: furrows running along v, `frequency` of them around u ∈ [0, 1), wandering
  // sideways and fading in and out so that plates interlace. Noise is sampled on a circle in
  // u so that the pattern closes without a seam at u = 0 = 1.
  return [d, seed](const Vec2f& uv, const Vec3f&) {
    const float a = kTwoPi * uv.x();
    const float ring = d.frequency / kTwoPi;
    const Vec3f q(std::cos(a) * ring * 0.35f, std::sin(a) * ring * 0.35f, uv.y() * 1.3f);
    const float wander = d.waviness * fbm(q, seed, 3) * 2.0f;
    const float w = uv.x() * d.frequency + wander;
    const float plate = std::abs(std::sin(kPi * w));  // 0 in a furrow, 1 mid-plate
    const float fade = std::clamp(0.55f + 1.6f * fbm(Vec3f(q.x() * 2.1f, q.y() * 2.1f, uv.y() * 3.0f), seed + 17, 2), 0.0f, 1.0f);
    const float furrow = std::pow(1.0f - plate, d.sharpness) * fade;
    const float texture = 0.08f * fbm(Vec3f(q.x() * 9, q.y() * 9, uv.y() * 22), seed + 5, 3);
    return -d.amplitude * std::clamp(furrow + texture, 0.0f, 1.0f);
  };
}

}  // namespace phellem
