// Image size limits, checked from the header alone before any image is decoded: a file whose
// header claims 100000 × 100000 pixels must be refused, not allocated (or handed to
// OpenImageIO's texture set-up, which crashes on it).
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <optional>
#include <string>

namespace phellem {

// At most 2^28 pixels (16384 × 16384) per image, ...
constexpr uint64_t kMaxImagePixels = uint64_t(1) << 28;
// ... and never more than this fraction of physical memory for the pixels as 32-bit floats
// (the form every reader decodes to).
constexpr double kMaxImageMemoryFraction = 0.25;

// Why a width × height × depth image of `channels` channels cannot be decoded (no pixels, too
// many pixels, too much memory), or nullopt when it can. `physical_bytes` 0: this machine's.
std::optional<std::string> image_size_problem(int64_t width, int64_t height, int64_t depth, int64_t channels,
                                              double physical_bytes = 0);

// Opens `file` (or a "builtin:" file, io/builtin_files.h) and reads only its header. Returns the spec of its first subimage, or nullopt
// with `*why` saying what is wrong: unreadable, or too large to decode (image_size_problem).
std::optional<OIIO::ImageSpec> read_image_header(const std::string& file, std::string* why);

}  // namespace phellem
