#include "tests/support/synthetic_render.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace phellem::test {

SyntheticRender::SyntheticRender(int w, int h)
    : width(w),
      height(h),
      alpha(size_t(w) * size_t(h), 1.0f),
      object_id(size_t(w) * size_t(h), 1.0f),
      displacement(size_t(w) * size_t(h), 0.0f),
      normal(size_t(w) * size_t(h) * 3, 0.0f),
      position(size_t(w) * size_t(h) * 3, 0.0f),
      albedo(size_t(w) * size_t(h) * 3, 0.5f) {
  for (size_t p = 0; p < size_t(w) * size_t(h); ++p) normal[3 * p + 2] = 1.0f;
}

void SyntheticRender::set_normal(int x, int y, float nx, float ny, float nz) {
  const size_t p = at(x, y);
  normal[3 * p] = nx, normal[3 * p + 1] = ny, normal[3 * p + 2] = nz;
}

void SyntheticRender::set_position(int x, int y, float px, float py, float pz) {
  const size_t p = at(x, y);
  position[3 * p] = px, position[3 * p + 1] = py, position[3 * p + 2] = pz;
}

std::vector<std::string> render_channel_names() {
  return {"beauty.R",   "beauty.G",   "beauty.B",     "beauty.A",   "albedo.R",    "albedo.G",
          "albedo.B",   "normal.X",   "normal.Y",     "normal.Z",   "depth.Z",     "position.X",
          "position.Y", "position.Z", "object_id.id", "crack.mask", "crack.depth", "displacement.D"};
}

void write_synthetic_render(const std::string& path, const SyntheticRender& r) {
  const auto names = render_channel_names();
  const int nc = int(names.size());
  OIIO::ImageSpec spec(r.width, r.height, nc, OIIO::TypeDesc::FLOAT);
  spec.channelnames = names;
  spec.alpha_channel = 3;
  spec.z_channel = 10;
  if (r.camera_position) spec.attribute("phellem:camera_position", OIIO::TypeDesc::TypeVector, r.camera_position->data());
  if (r.world_to_camera) spec.attribute("worldToCamera", OIIO::TypeDesc::TypeMatrix44, r.world_to_camera->data());
  std::vector<float> px(size_t(r.width) * size_t(r.height) * size_t(nc), 0.0f);
  for (size_t p = 0; p < size_t(r.width) * size_t(r.height); ++p) {
    float* o = &px[p * size_t(nc)];
    for (int c = 0; c < 3; ++c) o[c] = 0.2f * r.alpha[p];
    o[3] = r.alpha[p];
    for (int c = 0; c < 3; ++c) o[4 + c] = r.albedo[3 * p + size_t(c)];
    for (int c = 0; c < 3; ++c) o[7 + c] = r.normal[3 * p + size_t(c)];
    o[10] = r.alpha[p] > 0 ? 2.0f : 0.0f;
    for (int c = 0; c < 3; ++c) o[11 + c] = r.position[3 * p + size_t(c)];
    o[14] = r.object_id[p];
    o[17] = r.displacement[p];
  }
  auto out = OIIO::ImageOutput::create(path);
  if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, px.data()) || !out->close())
    throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
}

}  // namespace phellem::test
