#include "io/image_limits.h"

#include <unistd.h>

#include <cstdio>

#include "io/builtin_files.h"
#include "util/memory.h"

namespace phellem {

namespace {

std::string gib(double bytes) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f GiB", bytes / 1073741824.0);
  return s;
}

}  // namespace

std::optional<std::string> image_size_problem(int64_t width, int64_t height, int64_t depth, int64_t channels,
                                              double physical_bytes) {
  std::string dims = std::to_string(width) + "x" + std::to_string(height);
  if (depth > 1) {
    dims += 'x';
    dims += std::to_string(depth);
  }
  if (width < 1 || height < 1 || depth < 1 || channels < 1)
    return "the image has no pixels (" + dims + ", " + std::to_string(channels) + " channels)";
  // Doubles: the product of three int32 sizes does not overflow them, and the limit is far
  // below 2^53, so comparisons are exact where they matter.
  const double pixels = double(width) * double(height) * double(depth);
  if (pixels > double(kMaxImagePixels))
    return "the image is " + dims + " = " + std::to_string(uint64_t(pixels)) + " pixels; at most " +
           std::to_string(kMaxImagePixels) + " (2^28, e.g. 16384x16384) are read";
  const double bytes = pixels * double(channels) * 4.0;
  if (physical_bytes <= 0) physical_bytes = physical_memory();
  if (physical_bytes > 0 && bytes > kMaxImageMemoryFraction * physical_bytes)
    return "the image is " + dims + " with " + std::to_string(channels) + " channels: " + gib(bytes) +
           " as floats, more than a quarter of this machine's " + gib(physical_bytes) + " of memory";
  return std::nullopt;
}

std::optional<OIIO::ImageSpec> read_image_header(const std::string& file, std::string* why) {
  ImageSource src = open_image_source(file);
  auto& in = src.in;
  if (!in) {
    *why = "cannot read image " + file + ": " + src.why;
    return std::nullopt;
  }
  OIIO::ImageSpec spec = in->spec();
  in->close();
  if (auto p = image_size_problem(spec.width, spec.height, spec.depth, spec.nchannels)) {
    *why = "cannot read image " + file + ": " + *p;
    return std::nullopt;
  }
  return spec;
}

}  // namespace phellem
