#include "io/gltf_reader.h"

#include <filesystem>

namespace phellem {

namespace {

// Keep encoded image bytes; OpenImageIO decodes them later (tinygltf's stb decode is skipped).
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->width = image->height = -1;
  return true;
}

}  // namespace

tinygltf::Model open_gltf(const std::string& path) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_encoded_image, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = std::filesystem::path(path).extension() == ".glb";
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path) : loader.LoadASCIIFromFile(&model, &err, &warn, path);
  } catch (const std::exception& e) {
    throw UserError(path, "read", std::string("invalid glTF: ") + e.what());
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw UserError(path, "read", "invalid glTF: " + (err.empty() ? std::string("unreadable file") : err));
  }
  return model;
}

}  // namespace phellem
