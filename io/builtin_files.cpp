#include "io/builtin_files.h"

#include "util/input_file.h"

namespace phellem {

bool is_builtin_path(std::string_view path) { return path.starts_with(kBuiltinPrefix); }

std::optional<std::span<const unsigned char>> builtin_bytes(std::string_view path) {
  if (is_builtin_path(path)) path.remove_prefix(kBuiltinPrefix.size());
  for (const BuiltinFile& f : builtin_files())
    if (path == f.name) return std::span<const unsigned char>(f.begin, f.end);
  return std::nullopt;
}

std::string builtin_names() {
  std::string s;
  for (const BuiltinFile& f : builtin_files()) {
    if (!s.empty()) s += ", ";
    s += std::string(kBuiltinPrefix) + f.name;
  }
  return s;
}

std::string builtin_problem(std::string_view path) {
  if (!is_builtin_path(path) || builtin_bytes(path)) return {};
  return "unknown builtin file \"" + std::string(path) + "\"; builtin files: " + builtin_names();
}

ImageSource open_image_source(const std::string& path, const OIIO::ImageSpec* config) {
  ImageSource s;
  if (!is_builtin_path(path)) {
    // Never open what is not a regular file: OpenImageIO would wait on a FIFO for ever.
    if (auto why = input_file_problem(path)) {
      s.why = *why + "; an image is read from a regular file";
      return s;
    }
    s.in = OIIO::ImageInput::open(path, config);
    if (!s.in) s.why = OIIO::geterror();
    return s;
  }
  const auto bytes = builtin_bytes(path);
  if (!bytes) {
    s.why = builtin_problem(path);
    return s;
  }
  // IOMemReader reads without copying; it only ever reads, the const_cast is its API's.
  s.proxy = std::make_unique<OIIO::Filesystem::IOMemReader>(const_cast<unsigned char*>(bytes->data()), bytes->size());
  // The name without the prefix: OpenImageIO picks the reader by its extension.
  s.in = OIIO::ImageInput::open(path.substr(kBuiltinPrefix.size()), config, s.proxy.get());
  if (!s.in) s.why = OIIO::geterror();
  return s;
}

}  // namespace phellem
