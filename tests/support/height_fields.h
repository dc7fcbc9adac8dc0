// Synthetic height maps for the compare tests, defined in centimetres so the same bark can be
// sampled at any scale: V-shaped fissures of random length and width on a noisy surface.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace phellem::test {

struct Heights {
  int width = 0, height = 0;
  std::vector<float> z;  // row 0 at the top, high = high
};

// `width_cm` × `height_cm` of fissured bark at `px_per_cm` (each pixel the mean of 3×3
// samples, so coarser samplings are anti-aliased like a photograph).
Heights fissured_bark(double width_cm, double height_cm, double px_per_cm, uint32_t seed);
// Isotropic smooth noise of about `feature_cm`.
Heights smooth_noise(double width_cm, double height_cm, double px_per_cm, double feature_cm, uint32_t seed);

// As a 16-bit greyscale PNG (heights stretched to the full code range).
void write_height_png16(const std::string& path, const Heights& h);
// An sRGB 8-bit albedo of the same size, from `fissure` at the lowest height to `ridge` at the
// highest (display values), with a slow warm/cool drift across it.
void write_albedo_png(const std::string& path, const Heights& h, const float ridge[3], const float fissure[3]);

}  // namespace phellem::test
