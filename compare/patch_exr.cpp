#include "compare/patch_exr.h"

#include <OpenImageIO/imageio.h>

#include "util/errors.h"

namespace phellem {

void write_patch_exr(const HeightField& f, const std::string& path) {
  OIIO::ImageSpec spec(f.width, f.height, 1, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"Y"};
  spec.attribute("compression", "zip");
  spec.attribute("phellem:px_per_cm", float(f.px_per_cm));
  auto out = OIIO::ImageOutput::create("exr");
  if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, f.z.data()) || !out->close())
    throw UserError(path, "", "cannot write the patch EXR: " + (out ? out->geterror() : OIIO::geterror()));
}

}  // namespace phellem
