// Small math vocabulary shared by the renderer: Eigen types, constants, an orthonormal frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace phellem {

using Vec2f = Eigen::Vector2f;
using Vec3f = Eigen::Vector3f;
using Vec4f = Eigen::Vector4f;
using Vec2i = Eigen::Vector2i;
using Vec3i = Eigen::Vector3i;
using Mat3f = Eigen::Matrix3f;
using Mat4f = Eigen::Matrix4f;
using Color = Eigen::Array3f;  // scene-linear Rec.709

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 1.0f / kPi;
inline constexpr float kTwoPi = 2.0f * kPi;
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

inline float sqr(float x) { return x * x; }
inline float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
inline float luminance(const Color& c) { return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2]; }
inline float radians(float deg) { return deg * (kPi / 180.0f); }

// Orthonormal basis around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited"): continuous everywhere but at one point, branch-free.
struct Frame {
  Vec3f s, t, n;
  Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
  explicit Frame(const Vec3f& normal) : n(normal) {
    const float sign = std::copysign(1.0f, n.z());
    const float a = -1.0f / (sign + n.z());
    const float b = n.x() * n.y() * a;
    s = Vec3f(1.0f + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
    t = Vec3f(b, sign + n.y() * n.y() * a, -n.y());
  }
  // Frame whose normal is n and whose first tangent is the projection of `tangent`.
  Frame(const Vec3f& normal, const Vec3f& tangent) : n(normal) {
    Vec3f tt = tangent - n * n.dot(tangent);
    if (tt.squaredNorm() < 1e-12f) {
      *this = Frame(normal);
      return;
    }
    s = tt.normalized();
    t = n.cross(s);
  }
  Vec3f to_local(const Vec3f& v) const { return Vec3f(v.dot(s), v.dot(t), v.dot(n)); }
  Vec3f to_world(const Vec3f& v) const { return s * v.x() + t * v.y() + n * v.z(); }
};

inline Vec3f transform_point(const Mat4f& m, const Vec3f& p) { return (m.topLeftCorner<3, 3>() * p + m.topRightCorner<3, 1>()); }
inline Vec3f transform_vector(const Mat4f& m, const Vec3f& v) { return m.topLeftCorner<3, 3>() * v; }

// Offset a ray origin off a surface so that the spawned ray does not re-hit it; the offset
// scales with the magnitude of the coordinates (float spacing grows with them).
inline Vec3f offset_ray_origin(const Vec3f& p, const Vec3f& ng, const Vec3f& dir) {
  const float scale = 1e-4f * std::max(1.0f, p.cwiseAbs().maxCoeff());
  return ng.dot(dir) >= 0.0f ? Vec3f(p + ng * scale) : Vec3f(p - ng * scale);
}

}  // namespace phellem
