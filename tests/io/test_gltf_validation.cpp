// glTF elements that tinygltf passes through unchecked are checked before use: a node
// matrix of the wrong length, an extension the file requires but Phellem does not know, a
// GLB of version 1, accessors whose count or offset reach past their bufferView or buffer
// (checked before anything is allocated from the count). Each is an exit-2 error naming the
// glTF element; the valid forms still load.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/mesh_io.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

using nlohmann::json;

// One triangle: positions (36 bytes) and uint16 indices (6 bytes, padded to 8) in one buffer.
struct Gltf {
  json doc;
  std::vector<unsigned char> bin;
};

Gltf triangle() {
  Gltf g;
  const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint16_t idx[4] = {0, 1, 2, 0};
  g.bin.resize(44);
  std::memcpy(g.bin.data(), pos, 36);
  std::memcpy(g.bin.data() + 36, idx, 8);
  g.doc = {{"asset", {{"version", "2.0"}}},
           {"buffers", json::array({{{"byteLength", 44}}})},
           {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                        {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}})},
           {"accessors", json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                                      {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}})},
           {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}})}}})},
           {"nodes", json::array({{{"mesh", 0}}})},
           {"scenes", json::array({{{"nodes", {0}}}})},
           {"scene", 0}};
  return g;
}

using test::base64;

std::string write_gltf(const std::string& dir, Gltf g) {
  g.doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(g.bin);
  const std::string path = dir + "/model.gltf";
  std::ofstream(path) << g.doc.dump(1);
  return path;
}

std::string write_glb(const std::string& dir, const Gltf& g, uint32_t version) {
  std::string text = g.doc.dump();
  while (text.size() % 4) text.push_back(' ');
  std::vector<unsigned char> out;
  auto u32 = [&](uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back((v >> (8 * i)) & 0xFF);
  };
  u32(0x46546C67);
  u32(version);
  u32(uint32_t(12 + 8 + text.size() + 8 + g.bin.size()));
  u32(uint32_t(text.size()));
  u32(0x4E4F534A);
  out.insert(out.end(), text.begin(), text.end());
  u32(uint32_t(g.bin.size()));
  u32(0x004E4942);
  out.insert(out.end(), g.bin.begin(), g.bin.end());
  const std::string path = dir + "/model.glb";
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
  return path;
}

TEST(GltfValidation, ValidFormsLoad) {
  const std::string dir = test::temp_dir("gltf_valid_forms");
  EXPECT_EQ(load_gltf(write_gltf(dir, triangle())).meshes.size(), 1u);
  Gltf g = triangle();
  g.doc["nodes"][0]["matrix"] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 0, 0, 1};  // scale 2, then x + 1
  g.doc["extensionsUsed"] = {"KHR_materials_specular"};
  g.doc["extensionsRequired"] = {"KHR_materials_specular"};
  const LoadedModel m = load_gltf(write_gltf(dir, g));
  ASSERT_EQ(m.meshes.size(), 1u);
  EXPECT_TRUE(m.meshes[0].positions[1].isApprox(Vec3f(3, 0, 0)));
  Gltf b = triangle();
  EXPECT_EQ(load_gltf(write_glb(dir, b, 2)).meshes.size(), 1u);
}

struct Bad {
  const char* name;
  std::function<std::string(const std::string& dir)> make;
  const char* where;   // the glTF element the error names
  const char* expect;  // substring of what it says
};

TEST(GltfValidation, BadElementsExitTwoNamingTheElement) {
  const std::vector<Bad> cases = {
      {"matrix of 15 numbers",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0};
         return write_gltf(d, g);
       },
       "nodes[0].matrix", "must have 16 numbers, has 15"},
      {"translation of 2 numbers",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["nodes"][0]["translation"] = {1, 2};
         return write_gltf(d, g);
       },
       "nodes[0].translation", "must have 3 numbers, has 2"},
      {"required Draco",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["extensionsUsed"] = {"KHR_materials_specular", "KHR_draco_mesh_compression"};
         g.doc["extensionsRequired"] = {"KHR_materials_specular", "KHR_draco_mesh_compression"};
         return write_gltf(d, g);
       },
       "extensionsRequired[1]", "requires extension KHR_draco_mesh_compression, which is not supported"},
      {"GLB version 1", [](const std::string& d) { return write_glb(d, triangle(), 1); }, "GLB header",
       "GLB version 1 is not supported"},
      {"asset version 1.0",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["asset"]["version"] = "1.0";
         return write_gltf(d, g);
       },
       "asset.version", "\"1.0\" is not supported"},
      {"position count 4294967295",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["accessors"][0]["count"] = 4294967295u;
         return write_gltf(d, g);
       },
       "accessors[0].count", "count 4294967295 of 12-byte elements"},
      {"index count 4294967295",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["accessors"][1]["count"] = 4294967295u;
         return write_gltf(d, g);
       },
       "accessors[1].count", "overruns bufferViews[1] (6 bytes: room for 3)"},
      {"count one too many",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["accessors"][0]["count"] = 4;
         return write_gltf(d, g);
       },
       "accessors[0].count", "room for 3"},
      {"byteOffset past the view",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["accessors"][0]["byteOffset"] = 4294967296u;
         return write_gltf(d, g);
       },
       "accessors[0].byteOffset", "beyond the end of bufferViews[0]"},
      {"bufferView past the buffer",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["bufferViews"][1]["byteOffset"] = 18446744073709551000u;  // offset + length wraps in 64 bits
         return write_gltf(d, g);
       },
       "bufferViews[1]", "buffers[0] holds 44 bytes"},
      {"unused accessor out of bounds",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["accessors"].push_back({{"bufferView", 0}, {"componentType", 5126}, {"count", 4294967295u}, {"type", "MAT4"}});
         return write_gltf(d, g);
       },
       "accessors[2].count", "overruns bufferViews[0]"},
  };
  for (const auto& c : cases) {
    const std::string dir = test::temp_dir(std::string("gltf_validation_") + std::to_string(&c - cases.data()));
    const std::string file = c.make(dir);
    test::expect_user_error([&] { load_gltf(file); }, c.name, file, c.where, c.expect);
    test::write_text(dir + "/scene.json",
                     R"({"objects": [{"type": "mesh", "file": ")" + file + R"("}], "render": {"resolution": [8, 8], "spp": 1}})");
    const auto r = test::run_phellem_limited("render " + dir + "/scene.json -o " + dir + "/o.exr", 4096, 120);
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: " + file + ": " + c.where + ": ", 0), 0u) << c.name << ": " << r.output;
  }
}

}  // namespace
}  // namespace phellem
