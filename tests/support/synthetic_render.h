// A render EXR written by hand with the layers and channel names of io/image_output.h
// (write_exr), every channel 32-bit float, for the tests of what `compare` reads of renders.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace phellem::test {

struct SyntheticRender {
  int width = 0, height = 0;
  // Per pixel (#height×#width, row 0 at the top); vectors interleaved.
  std::vector<float> alpha, object_id, displacement;
  std::vector<float> normal, position, albedo;  // ×3
  std::optional<std::array<float, 3>> camera_position;   // phellem:camera_position
  std::optional<std::array<float, 16>> world_to_camera;  // worldToCamera, row-major (row vectors)

  SyntheticRender(int w, int h);
  size_t at(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }
  void set_normal(int x, int y, float nx, float ny, float nz);
  void set_position(int x, int y, float px, float py, float pz);
};

// The channel names in write_exr's order (the tests check them against exr_channel_names()).
std::vector<std::string> render_channel_names();
void write_synthetic_render(const std::string& path, const SyntheticRender& r);

}  // namespace phellem::test
