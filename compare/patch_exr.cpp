#include "compare/patch_exr.h"

#include <OpenImageIO/imageio.h>

#include "io/image_file.h"

namespace phellem {

void write_patch_exr(const HeightField& f, const std::string& path) {
  OIIO::ImageSpec spec(f.width, f.height, 1, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"Y"};
  spec.attribute("compression", "zip");
  spec.attribute("phellem:px_per_cm", float(f.px_per_cm));
  write_image_file(path, path, spec, OIIO::TypeDesc::FLOAT, f.z.data());
}

}  // namespace phellem
