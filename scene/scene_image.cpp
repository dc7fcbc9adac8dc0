#include "scene/scene_image.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "io/builtin_files.h"
#include "io/image_decode.h"
#include "io/image_limits.h"
#include "scene/json_reader.h"
#include "util/input_file.h"

namespace phellem {

SceneImage read_scene_image(const JsonValue& v, const std::string& base_dir) {
  std::filesystem::path p(v.string());
  if (is_builtin_path(v.string())) {
    if (auto why = builtin_problem(v.string()); !why.empty()) v.fail(why);
  } else {
    if (p.is_relative()) p = std::filesystem::path(base_dir) / p;
    if (auto why = input_file_message(p.string(), "an image")) v.fail(*why);
  }
  ImageSource src = open_image_source(p.string());
  auto& in = src.in;
  if (!in) v.fail("cannot read image " + p.string() + ": " + src.why);
  const OIIO::ImageSpec& spec = in->spec();
  // The header alone decides whether the pixels may be decoded (io/image_limits.h).
  if (auto why = image_size_problem(spec.width, spec.height, spec.depth, spec.nchannels))
    v.fail("cannot read image " + p.string() + ": " + *why);
  SceneImage img;
  img.path = p.string();
  img.width = spec.width;
  img.height = spec.height;
  img.channels = spec.nchannels;
  img.encoded = spec.format.basetype != OIIO::TypeDesc::FLOAT && spec.format.basetype != OIIO::TypeDesc::HALF;
  img.pixels.resize(size_t(spec.width) * spec.height * spec.depth * spec.nchannels);
  if (auto why = decode_image(*in, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
    v.fail("cannot read image " + p.string() + ": " + *why);
  return img;
}

}  // namespace phellem
