// The camera both renderers share (scene/camera_model.h): a point on the ray through a pixel
// centre, projected with the OpenGL matrices, lands on that pixel centre (rows flipped to
// GL's bottom-up windows), and its eye-space depth comes back through the depth buffer.
#include <gtest/gtest.h>

#include "scene/camera_model.h"

using namespace phellem;

TEST(CameraModel, GlMatricesProjectThePathTracersPixelCentresOntoThemselves) {
  CameraDesc d;
  d.position = Vec3f(0.3f, 1.2f, 2.0f);
  d.look_at = Vec3f(-0.1f, 0.9f, 0.1f);
  d.up = Vec3f(0.05f, 1, 0);
  d.fov_deg = 37;
  const int w = 320, h = 200;
  const CameraModel cam(d, w, h);
  const float near = 0.01f, far = 50.0f;
  const Eigen::Matrix4f vp = cam.projection(near, far) * cam.view();
  for (const Vec2f& film : {Vec2f(0.5f, 0.5f), Vec2f(160.5f, 100.5f), Vec2f(319.5f, 12.5f), Vec2f(7.5f, 199.5f)})
    for (float t : {0.5f, 3.0f, 20.0f}) {
      const Vec3f p = cam.position() + t * cam.direction(film).normalized();
      const Eigen::Vector4f c = vp * p.homogeneous();
      const float wx = (c.x() / c.w() * 0.5f + 0.5f) * w, wy = (c.y() / c.w() * 0.5f + 0.5f) * h;
      EXPECT_NEAR(wx, film.x(), 2e-3f);
      EXPECT_NEAR(wy, float(h) - film.y(), 2e-3f);  // GL's window rows run bottom-up
      EXPECT_NEAR(c.w(), (p - cam.position()).dot(cam.forward()), 1e-4f * t);  // eye-space depth
    }
  // The basis is orthonormal and looks at look_at.
  EXPECT_NEAR(cam.forward().dot(cam.right()), 0, 1e-6f);
  EXPECT_NEAR(cam.up().norm(), 1, 1e-6f);
  EXPECT_TRUE(cam.forward().isApprox((d.look_at - d.position).normalized()));
}
