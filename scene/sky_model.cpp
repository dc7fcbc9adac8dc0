#include "scene/sky_model.h"

#include <algorithm>
#include <cmath>

#include "util/latlong.h"

namespace phellem {

namespace {

struct Perez {
  float A, B, C, D, E;
  float operator()(float cos_theta, float gamma) const {
    const float cg = std::cos(gamma);
    return (1 + A * std::exp(B / std::max(cos_theta, 0.01f))) * (1 + C * std::exp(D * gamma) + E * cg * cg);
  }
};

}  // namespace

Color preetham_radiance(const Vec3f& sun, float T, const Vec3f& d) {
  // Preetham, Shirley, Smits 1999, "A Practical Analytic Model for Daylight", appendix A.
  const float theta_s = std::acos(std::clamp(sun.y(), 0.0f, 1.0f));
  const float chi = (4.0f / 9.0f - T / 120.0f) * (kPi - 2 * theta_s);
  const float Yz = (4.0453f * T - 4.9710f) * std::tan(chi) - 0.2155f * T + 2.4192f;  // kcd/m²
  const float t2 = theta_s * theta_s, t3 = t2 * theta_s;
  const float xz = T * T * (0.00166f * t3 - 0.00375f * t2 + 0.00209f * theta_s) +
                   T * (-0.02903f * t3 + 0.06377f * t2 - 0.03202f * theta_s + 0.00394f) +
                   (0.11693f * t3 - 0.21196f * t2 + 0.06052f * theta_s + 0.25886f);
  const float yz = T * T * (0.00275f * t3 - 0.00610f * t2 + 0.00317f * theta_s) +
                   T * (-0.04214f * t3 + 0.08970f * t2 - 0.04153f * theta_s + 0.00516f) +
                   (0.15346f * t3 - 0.26756f * t2 + 0.06670f * theta_s + 0.26688f);
  const Perez pY{0.1787f * T - 1.4630f, -0.3554f * T + 0.4275f, -0.0227f * T + 5.3251f, 0.1206f * T - 2.5771f,
                 -0.0670f * T + 0.3703f};
  const Perez px{-0.0193f * T - 0.2592f, -0.0665f * T + 0.0008f, -0.0004f * T + 0.2125f, -0.0641f * T - 0.8989f,
                 -0.0033f * T + 0.0452f};
  const Perez py{-0.0167f * T - 0.2608f, -0.0950f * T + 0.0092f, -0.0079f * T + 0.2102f, -0.0441f * T - 1.6537f,
                 -0.0109f * T + 0.0529f};
  const Vec3f dd = Vec3f(d.x(), std::max(d.y(), 0.001f), d.z()).normalized();
  const float cos_t = dd.y();
  const float gamma = std::acos(std::clamp(dd.dot(sun), -1.0f, 1.0f));
  const float Y = Yz * pY(cos_t, gamma) / pY(1.0f, theta_s);
  const float x = xz * px(cos_t, gamma) / px(1.0f, theta_s);
  const float y = yz * py(cos_t, gamma) / py(1.0f, theta_s);
  // xyY -> XYZ -> linear Rec.709.
  const float X = x / y * Y, Z = (1 - x - y) / y * Y;
  Color rgb(3.2404542f * X - 1.5371385f * Y - 0.4985314f * Z, -0.9692660f * X + 1.8760108f * Y + 0.0415560f * Z,
            0.0556434f * X - 0.2040259f * Y + 1.0572252f * Z);
  return rgb.max(0.0f);
}

std::vector<float> preetham_sky_image(const Vec3f& sun_direction, float turbidity, float intensity, float ground_albedo,
                                      int width) {
  const int height = width / 2;
  std::vector<float> rgb(size_t(width) * height * 3);
  const Vec3f sun = sun_direction.normalized();
  const float scale = intensity / 100.0f;  // 1 scene unit of radiance = 100 kcd/m²
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Vec3f d = latlong_to_direction(Vec2f((x + 0.5f) / width, (y + 0.5f) / height));
      Color c;
      if (d.y() >= 0) {
        c = preetham_radiance(sun, turbidity, d) * scale;
      } else {
        c = preetham_radiance(sun, turbidity, Vec3f(d.x(), 0.0f, d.z())) * scale * ground_albedo;
      }
      std::copy(c.data(), c.data() + 3, &rgb[(size_t(y) * width + x) * 3]);
    }
  return rgb;
}

}  // namespace phellem
