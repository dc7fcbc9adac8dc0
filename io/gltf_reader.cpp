#include "io/gltf_reader.h"

#include <array>
#include <filesystem>
#include <fstream>

#include "util/input_file.h"

namespace phellem {

namespace {

// Keep encoded image bytes; OpenImageIO decodes them later (tinygltf's stb decode is skipped).
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                        int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->width = image->height = -1;
  return true;
}

// The extensions whose meaning the loaders know (io/gltf_loader.cpp reads the two material
// extensions; GltfReader::floats reads the integer vertex attributes of KHR_mesh_quantization
// and the node transforms that undo them are applied). A file that requires any other one
// cannot be read correctly without it (glTF 2.0, 3.12).
constexpr std::array<const char*, 3> kSupportedExtensions = {"KHR_materials_emissive_strength", "KHR_materials_specular",
                                                             "KHR_mesh_quantization"};

// GLB header: magic "glTF", version 2 (version 1 is the old binary glTF 1.0, whose JSON
// tinygltf would misread as 2.0).
void check_glb_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char h[12] = {};
  if (!in.read(reinterpret_cast<char*>(h), sizeof h)) return;            // too short: tinygltf says so
  if (h[0] != 'g' || h[1] != 'l' || h[2] != 'T' || h[3] != 'F') return;  // not GLB: tinygltf says so
  const uint32_t version = uint32_t(h[4]) | uint32_t(h[5]) << 8 | uint32_t(h[6]) << 16 | uint32_t(h[7]) << 24;
  if (version != 2)
    throw UserError(path, "GLB header",
                    "GLB version " + std::to_string(version) + " is not supported; only version 2 (glTF 2.0)");
}

void check_model(const tinygltf::Model& model, const std::string& path) {
  const std::string& version = model.asset.version;
  if (version.rfind("2.", 0) != 0)
    throw UserError(path, "asset.version",
                    version.empty() ? std::string("missing; only glTF 2.0 is supported")
                                    : "glTF version \"" + printable(version) + "\" is not supported; only 2.0");
  if (!model.asset.minVersion.empty() && model.asset.minVersion != "2.0")
    throw UserError(path, "asset.minVersion",
                    "the file needs glTF " + printable(model.asset.minVersion) + "; only 2.0 is supported");
  for (size_t k = 0; k < model.extensionsRequired.size(); ++k) {
    const std::string& e = model.extensionsRequired[k];
    if (std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), e) != kSupportedExtensions.end()) continue;
    std::string supported;
    for (const char* s : kSupportedExtensions) supported += (supported.empty() ? "" : ", ") + std::string(s);
    throw UserError(path, "extensionsRequired[" + std::to_string(k) + "]",
                    "the file requires extension " + printable(e) + ", which is not supported (supported: " + supported + ")");
  }
  // Every accessor's elements inside its bufferView and buffer, before anything reads one
  // (and sizes an array by its count). Accessors without a bufferView (all zeros) and sparse
  // ones are refused when read.
  const GltfReader rd(model, path);
  for (size_t i = 0; i < model.accessors.size(); ++i) {
    const tinygltf::Accessor& a = model.accessors[i];
    if (a.bufferView >= 0 && !a.sparse.isSparse) rd.layout(a, int(i), "");
  }
}

// tinygltf's file access for the glTF file and the buffers and images it names, refusing what is
// not a regular file before opening it (util/input_file.h): its own FileExists opens the file
// to see whether it is there, and reading a FIFO blocks for ever.
bool file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

bool read_regular_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  if (auto why = input_file_problem(path)) {
    if (err) *err += *why + "; glTF buffers and images are read from regular files\n";
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, path, nullptr);
}

}  // namespace

tinygltf::Model open_gltf(const std::string& path) {
  require_input_file(path, path, "read", "a glTF file");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_encoded_image, nullptr);
  loader.SetFsCallbacks({file_exists, tinygltf::ExpandFilePath, read_regular_file, tinygltf::WriteWholeFile, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = std::filesystem::path(path).extension() == ".glb";
  if (binary) check_glb_header(path);
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
  check_model(model, path);
  return model;
}

}  // namespace phellem
