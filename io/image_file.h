// Image files written through OpenImageIO into memory, then to disk by write_file_checked
// (util/checked_write.h): OpenImageIO's own PNG writer reports success on a full disk and
// leaves a truncated file.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

namespace phellem {

// The file `name` would hold (its extension picks the format: .exr, .png, .tif, ...), encoded
// in memory from `pixels` (laid out as `spec` says, in `type`). std::runtime_error if
// OpenImageIO cannot encode it.
std::vector<unsigned char> encode_image(const std::string& name, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                                        const void* pixels);

// Encodes as encode_image and writes the bytes to `file` (usually the temporary of `path`):
// UserError(path, "write", ...) when the encoder or any write fails.
void write_image_file(const std::string& path, const std::string& file, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                      const void* pixels);

}  // namespace phellem
