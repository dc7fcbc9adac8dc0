// How coloured an image is: what tells a colour photograph from a grey height map saved with
// three channels (docs/compare.md, "Colour photos are not height maps").
#pragma once

#include <cstddef>

namespace phellem {

// The median over the image's 8×8 blocks (whole blocks only; single pixels when a side is
// under 8) of max − min of the block's mean R, G and B, on the code values as read (integer
// codes over the largest code, not linearized). `rgb` is #height×#width×`channels`, channels
// ≥ 3 (the first three are R, G, B). Averaging a block first removes zero-mean chroma noise
// (JPEG, sensor) while the hue of a photograph stays: grey gives 0, the brown bark photo 0.24.
double colour_chroma(const float* rgb, int width, int height, int channels);

// Above this, an image given as a height map is refused as a colour photo.
inline constexpr double kColourPhotoChroma = 0.02;

}  // namespace phellem
