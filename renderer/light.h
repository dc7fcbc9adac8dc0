// Lights: what next-event estimation samples and what escaped or emitter-hitting rays see.
// pdfs are solid-angle densities at the shading point.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "renderer/sampling.h"
#include "scene/sky_model.h"  // preetham_radiance, preetham_sky_image
#include "util/math.h"

namespace phellem {

struct LightSample {
  Color L;         // radiance arriving along -wi
  Vec3f wi;        // unit direction from the shading point towards the light
  float dist = 0;  // distance to the light point (infinity for infinite lights)
  float pdf = 0;   // solid angle (ignored for delta lights)
  bool delta = false;
};

class Light {
 public:
  virtual ~Light() = default;
  virtual bool infinite() const { return false; }
  virtual std::optional<LightSample> sample(const Vec3f& p, const Vec2f& u) const = 0;
  // Solid-angle pdf that sample() would produce direction wi (infinite lights only).
  virtual float pdf(const Vec3f& wi) const {
    (void)wi;
    return 0;
  }
  // Radiance seen along an escaped ray with direction `dir` (infinite lights only).
  virtual Color Le(const Vec3f& dir) const {
    (void)dir;
    return Color::Zero();
  }
  // Sampling that knows the receiving surface's normal `n` (pointing to the side that can
  // receive light; zero when both sides can, e.g. for transmissive surfaces). Lights that
  // can use it sample only that hemisphere; the default ignores it.
  virtual std::optional<LightSample> sample_at(const Vec3f& p, const Vec3f& n, const Vec2f& u) const {
    (void)n;
    return sample(p, u);
  }
  virtual float pdf_at(const Vec3f& wi, const Vec3f& n) const {
    (void)n;
    return pdf(wi);
  }
  // Le(dir) and pdf_at(dir, n) together (one direction lookup for lights that can share it).
  virtual Color Le_pdf(const Vec3f& dir, const Vec3f& n, float* pdf_out) const {
    *pdf_out = pdf_at(dir, n);
    return Le(dir);
  }
};

// Uniform environment: radiance `L` from every direction. With a receiver normal it samples
// the cosine-weighted hemisphere above it (the whole integrand when L is constant), else the
// sphere uniformly.
class UniformEnvironment final : public Light {
 public:
  explicit UniformEnvironment(const Color& L) : L_(L) {}
  bool infinite() const override { return true; }
  std::optional<LightSample> sample(const Vec3f& p, const Vec2f& u) const override;
  std::optional<LightSample> sample_at(const Vec3f& p, const Vec3f& n, const Vec2f& u) const override;
  float pdf(const Vec3f&) const override { return 1.0f / (4 * kPi); }
  float pdf_at(const Vec3f& wi, const Vec3f& n) const override {
    return n.squaredNorm() > 0 ? std::max(0.0f, wi.dot(n)) * kInvPi : pdf(wi);
  }
  Color Le(const Vec3f&) const override { return L_; }

 private:
  Color L_;
};

// Equirectangular environment map, importance-sampled by luminance × sinθ.
// Mapping: u = 0.5 + atan2(d.x, -d.z) / 2π, v = acos(d.y) / π (so -z is the image centre),
// rotated about +y by rotation_deg.
class EnvironmentMap final : public Light {
 public:
  EnvironmentMap(std::vector<float> rgb, int width, int height, float intensity, float rotation_deg);
  bool infinite() const override { return true; }
  std::optional<LightSample> sample(const Vec3f& p, const Vec2f& u) const override;
  float pdf(const Vec3f& wi) const override;
  Color Le(const Vec3f& dir) const override;
  Color Le_pdf(const Vec3f& dir, const Vec3f& n, float* pdf_out) const override;

  static Vec2f direction_to_uv(const Vec3f& d);
  static Vec3f uv_to_direction(const Vec2f& uv);

 private:
  Vec3f to_local(const Vec3f& w) const;
  Vec3f to_world(const Vec3f& w) const;
  Color texel(int x, int y) const;
  Color bilinear(const Vec2f& uv) const;
  std::vector<float> rgb_;
  int w_, h_;
  float intensity_;
  float cos_r_, sin_r_;
  float average_ = 0;
  Distribution2D dist_;
};

// A sun disk of angular diameter `angle_deg` seen in `direction` (towards the sun), scaled so
// that a surface facing it receives `irradiance`: L = E / (π sin²θmax). angle 0: delta light.
class SunLight final : public Light {
 public:
  SunLight(const Vec3f& direction, float irradiance, float angle_deg, const Color& color);
  bool infinite() const override { return true; }
  std::optional<LightSample> sample(const Vec3f& p, const Vec2f& u) const override;
  float pdf(const Vec3f& wi) const override;
  Color Le(const Vec3f& dir) const override;
  bool is_delta() const { return cos_max_ >= 1.0f; }

 private:
  Vec3f dir_;
  Frame frame_;
  float cos_max_;
  Color E_, L_;
};

// Preetham et al. 1999 analytic daylight sky, baked into an environment map.
// Radiance (scene units) = intensity × Y / 100 kcd m⁻², so that a sun of irradiance 1
// corresponds to about 100 klux; the lower hemisphere is ground_albedo × the horizon.
// 128 × 64 texels (2.8°) interpolated bilinearly resolve the sky's smooth gradients, and the
// whole map with its sampling tables stays in L2 cache: at 512 × 256 escaped rays spent
// more time in cache misses than in Embree (bench/run_throughput.sh: 6.1 -> 7.9 Mrays/s).
std::unique_ptr<EnvironmentMap> make_preetham_sky(const Vec3f& sun_direction, float turbidity, float intensity,
                                                  float ground_albedo, int width = 128);

// Emissive triangles in world space, sampled by area × luminance.
class AreaLights final : public Light {
 public:
  struct Triangle {
    Vec3f p0, p1, p2;
    Color L;
  };
  explicit AreaLights(std::vector<Triangle> tris);
  std::optional<LightSample> sample(const Vec3f& p, const Vec2f& u) const override;
  // pdf of reaching triangle `index` at point `hit` from p along wi.
  float pdf_hit(size_t index, const Vec3f& p, const Vec3f& hit, const Vec3f& wi) const;
  size_t size() const { return tris_.size(); }

 private:
  std::vector<Triangle> tris_;
  std::vector<float> area_;
  Distribution1D dist_;
};

}  // namespace phellem
