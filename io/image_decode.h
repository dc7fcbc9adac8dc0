// Decoding a whole image, refusing one the decoder complained about. OpenImageIO's read_image
// returns true for a JPEG cut short: libjpeg warns "Premature end of JPEG file", fills the
// missing rows with grey, and the warning reaches only the reader's error state. Every image
// Phellem decodes (height maps, photographs, scene images, environment maps, textures) is
// decoded here, so such a file is an error rather than an image with a grey part.
#pragma once

#include <OpenImageIO/imageio.h>

#include <optional>
#include <string>

namespace phellem {

// Decodes channels [chbegin, chend) of the first subimage of `in`, as `type`, into `data`
// (width × height × depth × (chend − chbegin) values). nullopt when every pixel decoded and
// the decoder reported nothing; else what the decoder said.
std::optional<std::string> decode_image(OIIO::ImageInput& in, int chbegin, int chend, OIIO::TypeDesc type, void* data);

}  // namespace phellem
