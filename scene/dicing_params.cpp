#include "scene/dicing_params.h"

#include <algorithm>
#include <cmath>

namespace phellem {

DicingParams dicing_params(const TessellationDesc& tess, const CameraDesc& camera, int height) {
  const CameraDesc& dc = tess.dicing_camera ? *tess.dicing_camera : camera;
  DicingParams dicing;
  dicing.screen_space = tess.mode == TessellationDesc::Mode::Screen;
  dicing.target = dicing.screen_space ? tess.pixels_per_edge : tess.edge_length;
  dicing.scale = tess.edge_length_scale;
  dicing.camera_position = dc.position;
  dicing.pixel_angle = 2.0f * std::tan(radians(dc.fov_deg) * 0.5f) / float(std::max(1, height));
  return dicing;
}

}  // namespace phellem
