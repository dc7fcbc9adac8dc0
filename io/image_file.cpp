#include "io/image_file.h"

#include <OpenImageIO/filesystem.h>

#include <stdexcept>
#include <string_view>

#include "util/checked_write.h"
#include "util/errors.h"

namespace phellem {

std::vector<unsigned char> encode_image(const std::string& name, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                                        const void* pixels) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  auto out = OIIO::ImageOutput::create(name);
  if (!out || !out->supports("ioproxy"))
    throw std::runtime_error("no image writer with I/O proxies for " + name + ": " + OIIO::geterror());
  OIIO::ImageSpec with_proxy = spec;
  void* ptr = &proxy;
  with_proxy.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &ptr);
  if (!out->open(name, with_proxy) || !out->write_image(type, pixels) || !out->close())
    throw std::runtime_error("cannot encode " + name + ": " + out->geterror());
  return bytes;
}

void write_image_file(const std::string& path, const std::string& file, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                      const void* pixels) {
  std::vector<unsigned char> bytes;
  try {
    bytes = encode_image(file, spec, type, pixels);
  } catch (const std::runtime_error& e) {
    throw UserError(path, "write", e.what());
  }
  write_file_checked(path, file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace phellem
