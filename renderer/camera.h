// Thin-lens perspective camera (pinhole when aperture_radius = 0).
#pragma once

#include "scene/camera_model.h"
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
  const Vec3f& position() const { return model_.position(); }
  const Vec3f& forward() const { return model_.forward(); }
  float pixel_angle() const { return 2.0f * model_.tan_half_fov() / float(model_.height()); }
  const CameraModel& model() const { return model_; }
  // The same camera orbited by `degrees` about the vertical axis through look_at.
  static CameraDesc orbit(const CameraDesc& c, float degrees);

 private:
  CameraModel model_;  // the pinhole shared with the preview (scene/camera_model.h)
  float aperture_, focus_;
};

}  // namespace phellem
