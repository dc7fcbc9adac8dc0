// Thin-lens perspective camera (pinhole when aperture_radius = 0).
#pragma once

#include "scene/scene_desc.h"
#include "util/math.h"

namespace phellem {

struct Ray {
  Vec3f o, d;
};

class Camera {
 public:
  Camera(const CameraDesc& desc, int width, int height);
  // film: raster position in pixels (0,0 top-left); lens: [0,1)² sample for the aperture.
  Ray generate(const Vec2f& film, const Vec2f& lens) const;
  const Vec3f& position() const { return pos_; }
  const Vec3f& forward() const { return forward_; }
  float pixel_angle() const { return 2.0f * tan_half_fov_ / float(height_); }
  // The same camera orbited by `degrees` about the vertical axis through look_at.
  static CameraDesc orbit(const CameraDesc& c, float degrees);

 private:
  Vec3f pos_, forward_, right_, up_;
  float tan_half_fov_, aspect_, aperture_, focus_;
  int width_, height_;
};

}  // namespace phellem
