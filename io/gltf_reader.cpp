#include "io/gltf_reader.h"

#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string_view>

#include "util/input_file.h"
#include "util/json_nesting.h"

namespace phellem {

namespace {

namespace fs = std::filesystem;

// tinygltf takes a file's length as an unsigned int.
constexpr uintmax_t kMaxGltfFileBytes = 0xFFFFFFFFu;

uint32_t le32(const unsigned char* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }

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
void check_glb_header(const std::vector<unsigned char>& h, const std::string& path) {
  if (h.size() < 12) return;                                             // too short: tinygltf says so
  if (h[0] != 'g' || h[1] != 'l' || h[2] != 'T' || h[3] != 'F') return;  // not GLB: tinygltf says so
  const uint32_t version = le32(h.data() + 4);
  if (version != 2)
    throw UserError(path, "GLB header",
                    "GLB version " + std::to_string(version) + " is not supported; only version 2 (glTF 2.0)");
}

// The whole file, read here rather than by tinygltf so that its JSON is checked
// (check_json_nesting) before tinygltf parses it: a regular file (open_gltf checked), at most
// what tinygltf's 32-bit lengths can address.
std::vector<unsigned char> read_gltf_file(const std::string& path) {
  std::error_code ec;
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) throw UserError(path, "read", "invalid glTF: cannot read the file size");
  if (size > kMaxGltfFileBytes)
    throw UserError(path, "read",
                    "the file is " + std::to_string(size) + " bytes; at most " + std::to_string(kMaxGltfFileBytes) +
                        " are read (tinygltf's lengths are 32-bit)");
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes(size);
  if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
    throw UserError(path, "read", "invalid glTF: cannot read the file");
  if (bytes.empty()) throw UserError(path, "read", "invalid glTF: the file is empty");
  return bytes;
}

// The JSON of a .gltf (all of it) or of a .glb (its first chunk, as far as the file holds it;
// a broken header is left to tinygltf, which reports it).
std::string_view json_text(const std::vector<unsigned char>& bytes, bool binary) {
  const std::string_view all(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (!binary) return all;
  if (bytes.size() < 20) return {};
  return all.substr(20, le32(bytes.data() + 12));
}

// The byte offsets, lengths and strides of accessors and bufferViews as the file writes them.
// tinygltf reads them as unsigned integers and, where the key is optional, silently replaces
// anything else (-4, 2.5, "8") by its default: an accessor's byteOffset of -4 would read from
// byte 0. So the file's own values are looked at, before tinygltf parses it: a parse that
// keeps only the two arrays (the callback drops everything else, base64 buffers included,
// as it is read).
void check_byte_fields(std::string_view json_text, const std::string& path) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(json_text, [](int depth, nlohmann::json::parse_event_t e, nlohmann::json& v) {
      if (depth == 1 && e == nlohmann::json::parse_event_t::key) return v == "accessors" || v == "bufferViews";
      return true;
    });
  } catch (const nlohmann::json::exception&) {
    return;  // invalid JSON: tinygltf reports it
  }
  if (!doc.is_object()) return;
  auto check = [&](const char* array, std::initializer_list<const char*> keys) {
    const auto it = doc.find(array);
    if (it == doc.end() || !it->is_array()) return;
    for (size_t i = 0; i < it->size(); ++i) {
      const nlohmann::json& e = (*it)[i];
      if (!e.is_object()) continue;
      for (const char* key : keys) {
        const auto v = e.find(key);
        if (v == e.end() || v->is_number_unsigned()) continue;
        std::string found = v->dump();
        if (found.size() > 40) found = found.substr(0, 40) + "...";
        throw UserError(path, std::string(array) + "[" + std::to_string(i) + "]." + key,
                        "must be an integer >= 0, found " + printable(found));
      }
    }
  };
  check("accessors", {"byteOffset", "count"});
  check("bufferViews", {"byteOffset", "byteLength", "byteStride"});
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
  const bool binary = fs::path(path).extension() == ".glb";
  const std::vector<unsigned char> bytes = read_gltf_file(path);
  if (binary) check_glb_header(bytes, path);
  const std::string_view json = json_text(bytes, binary);
  check_json_nesting(json, path, binary ? "JSON chunk, " : "");  // before any parser recurses into it
  check_byte_fields(json, path);
  const std::string base_dir = fs::path(path).parent_path().string();  // relative buffer and image URIs
  const auto size = static_cast<unsigned int>(bytes.size());
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), size, base_dir)
                : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()), size, base_dir);
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
