// An image named by a scene (weakness maps, dressing samples, stress images): the file name
// resolved against the scene's folder and read as floats, every failure a UserError at the
// JSON value that named it.
#pragma once

#include <string>
#include <vector>

namespace phellem {

class JsonValue;

struct SceneImage {
  std::string path;
  int width = 0, height = 0, channels = 0;
  bool encoded = false;       // integer pixels (sRGB-encoded colours); false for float/half (EXR)
  std::vector<float> pixels;  // row-major, row 0 at the top, channels interleaved
};

SceneImage read_scene_image(const JsonValue& v, const std::string& base_dir);

}  // namespace phellem
