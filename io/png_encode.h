// PNG bytes in memory (for data: URIs in the HTML report of `phellem compare`), written by
// OpenImageIO through an in-memory IOProxy: no temporary file.
#pragma once

#include <cstdint>
#include <vector>

namespace phellem {

// `pixels` is #h×#w×channels 8-bit code values, row 0 at the top, channels 1 (grey), 2 (grey,
// alpha), 3 (RGB) or 4 (RGBA), written as they are (no colour transform). Throws
// std::invalid_argument for a size ≤ 0 or another channel count, std::runtime_error when
// OpenImageIO fails.
std::vector<unsigned char> encode_png(int w, int h, int channels, const uint8_t* pixels);

}  // namespace phellem
