// The interactive preview's camera: an orbit around a target (yaw, pitch, distance) that
// starts as the scene's camera and turns back into a CameraDesc, so the path tracer can
// render exactly the view on screen (the camera key writes it into a scene file).
#pragma once

#include "scene/scene_desc.h"
#include "util/math.h"

namespace phellem::preview {

class OrbitCamera {
 public:
  explicit OrbitCamera(const CameraDesc& start);
  // Mouse motion in pixels of a window `height` pixels tall.
  void orbit(float dx, float dy);             // left drag: around the target
  void pan(float dx, float dy, int height);   // right or middle drag: the target moves with the view
  void zoom(float steps);                     // wheel: × 0.9 per step towards the target
  CameraDesc desc() const;

 private:
  CameraDesc base_;
  Vec3f target_;
  float yaw_, pitch_, distance_;
};

}  // namespace phellem::preview
