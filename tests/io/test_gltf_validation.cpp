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
#include "util/json_nesting.h"
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

// The document's text; with `raw_extras`, compact and with that text (which need not be
// valid JSON, or may nest deeper than nlohmann would write) as the top-level "extras".
std::string text_of(json doc, const std::string& raw_extras) {
  if (raw_extras.empty()) return doc.dump(1);
  doc["extras"] = "@EXTRAS@";
  std::string text = doc.dump();
  const size_t at = text.find("\"@EXTRAS@\"");
  return text.substr(0, at) + raw_extras + text.substr(at + 10);
}

std::string write_gltf(const std::string& dir, Gltf g, const std::string& raw_extras = "") {
  g.doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(g.bin);
  const std::string path = dir + "/model.gltf";
  std::ofstream(path) << text_of(g.doc, raw_extras);
  return path;
}

std::string write_glb(const std::string& dir, const Gltf& g, uint32_t version, const std::string& raw_extras = "") {
  std::string text = raw_extras.empty() ? g.doc.dump() : text_of(g.doc, raw_extras);
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
  std::string name;
  std::function<std::string(const std::string& dir)> make;
  std::string where;   // the glTF element the error names
  std::string expect;  // substring of what it says
};

// Each case: load_gltf throws a UserError naming the file, `where` and `expect`, and the CLI
// exits 2 with the same file and element. The CLI runs first, limited in memory and time,
// so that a file that would hang or exhaust memory fails the test instead of hanging it.
void expect_refused(const std::vector<Bad>& cases, const std::string& tag) {
  for (const auto& c : cases) {
    const std::string dir = test::temp_dir(tag + "_" + std::to_string(&c - cases.data()));
    const std::string file = c.make(dir);
    test::write_text(dir + "/scene.json",
                     R"({"objects": [{"type": "mesh", "file": ")" + file + R"("}], "render": {"resolution": [8, 8], "spp": 1}})");
    const auto r = test::run_phellem_limited("render " + dir + "/scene.json -o " + dir + "/o.exr", 4096, 120);
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: " + file + ": " + c.where + ": ", 0), 0u) << c.name << ": " << r.output;
    if (r.exit_code == 2) test::expect_user_error([&] { load_gltf(file); }, c.name, file, c.where, c.expect);
  }
}

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
  expect_refused(cases, "gltf_validation");
}

// A triangle with TEXCOORD_0 (accessor 2: three VEC2 floats after the indices), the first
// vertex's u set to `u0`.
Gltf with_uvs(float u0) {
  Gltf g = triangle();
  const float uv[6] = {u0, 0, 1, 0, 0, 1};
  const size_t at = g.bin.size();
  g.bin.resize(at + sizeof uv);
  std::memcpy(g.bin.data() + at, uv, sizeof uv);
  g.doc["buffers"][0]["byteLength"] = g.bin.size();
  g.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", sizeof uv}});
  g.doc["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}});
  g.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
  return g;
}

// A triangle whose material is `material`.
Gltf with_material(const json& material) {
  Gltf g = triangle();
  g.doc["materials"] = json::array({material});
  g.doc["meshes"][0]["primitives"][0]["material"] = 0;
  return g;
}

std::function<std::string(const std::string&)> material_case(const json& material) {
  return [material](const std::string& d) { return write_gltf(d, with_material(material)); };
}

TEST(GltfValidation, MaterialValuesOutsideTheirRangesExitTwo) {
  // glTF bounds its factors to [0, 1]; emissiveStrength is bounded by 1e6 here (a float
  // sample of the radiance stays finite).
  const std::vector<Bad> cases = {
      {"negative base colour", material_case({{"pbrMetallicRoughness", {{"baseColorFactor", {-0.5, 0.5, 0.5, 1}}}}}),
       "materials[0].pbrMetallicRoughness.baseColorFactor[0]", "must lie in [0, 1], found -0.5"},
      {"negative metallic", material_case({{"pbrMetallicRoughness", {{"metallicFactor", -1}}}}),
       "materials[0].pbrMetallicRoughness.metallicFactor", "must lie in [0, 1]"},
      {"roughness 2", material_case({{"pbrMetallicRoughness", {{"roughnessFactor", 2}}}}),
       "materials[0].pbrMetallicRoughness.roughnessFactor", "must lie in [0, 1]"},
      {"negative emission", material_case({{"emissiveFactor", {-1, 1, 0}}}), "materials[0].emissiveFactor[0]",
       "must lie in [0, 1], found -1"},
      {"emission 1e300", material_case({{"emissiveFactor", {0, 1e300, 0}}}), "materials[0].emissiveFactor[1]",
       "must lie in [0, 1]"},
      {"negative strength",
       material_case({{"emissiveFactor", {1, 1, 1}}, {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", -2}}}}}}),
       "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength", "must lie in [0, 1e6]"},
      {"strength 1e300",
       material_case({{"emissiveFactor", {1, 1, 1}}, {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e300}}}}}}),
       "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength", "must lie in [0, 1e6]"},
      {"strength a string",
       material_case({{"emissiveFactor", {1, 1, 1}}, {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", "x"}}}}}}),
       "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength", "must be a number"},
      {"specular 2", material_case({{"extensions", {{"KHR_materials_specular", {{"specularFactor", 2}}}}}}),
       "materials[0].extensions.KHR_materials_specular.specularFactor", "must lie in [0, 1]"},
  };
  expect_refused(cases, "gltf_material_ranges");
}

TEST(GltfValidation, MaterialValuesAtTheirBoundsLoad) {
  const std::string dir = test::temp_dir("gltf_material_bounds");
  const LoadedModel m = load_gltf(write_gltf(
      dir, with_material({{"pbrMetallicRoughness", {{"baseColorFactor", {0, 1, 0.5, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 1}}},
                          {"emissiveFactor", {1, 0, 0}},
                          {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e6}}}}}})));
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].type, MaterialType::Emissive);
  EXPECT_FLOAT_EQ(m.materials[0].strength, 1e6f);
}

TEST(GltfValidation, NegativeOrFractionalByteFieldsExitTwo) {
  // tinygltf replaced these (optional keys) by 0 without a word: byteOffset -4 read from byte 0.
  auto edit = [](const char* array, int index, const char* key, json value) {
    return [=](const std::string& d) {
      Gltf g = triangle();
      g.doc[array][index][key] = value;
      return write_gltf(d, g);
    };
  };
  const std::vector<Bad> cases = {
      {"accessor byteOffset -4", edit("accessors", 0, "byteOffset", -4), "accessors[0].byteOffset",
       "must be an integer >= 0, found -4"},
      {"accessor byteOffset 2.5", edit("accessors", 1, "byteOffset", 2.5), "accessors[1].byteOffset",
       "must be an integer >= 0, found 2.5"},
      {"bufferView byteOffset -8", edit("bufferViews", 1, "byteOffset", -8), "bufferViews[1].byteOffset",
       "must be an integer >= 0, found -8"},
      {"bufferView byteStride -12", edit("bufferViews", 0, "byteStride", -12), "bufferViews[0].byteStride",
       "must be an integer >= 0, found -12"},
      {"bufferView byteLength -1", edit("bufferViews", 0, "byteLength", -1), "bufferViews[0].byteLength",
       "must be an integer >= 0, found -1"},
  };
  expect_refused(cases, "gltf_byte_fields");
}

TEST(GltfValidation, HugeTextureCoordinatesExitTwo) {
  const std::vector<Bad> cases = {
      {"u 1e7", [](const std::string& d) { return write_gltf(d, with_uvs(1e7f)); }, "meshes[0].primitives[0].attributes.TEXCOORD_0",
       "accessor 2 element 0 has texture coordinate 10000000"},
      {"u -2e6", [](const std::string& d) { return write_gltf(d, with_uvs(-2e6f)); },
       "meshes[0].primitives[0].attributes.TEXCOORD_0", "at most 1e6 in magnitude"},
  };
  expect_refused(cases, "gltf_uvs");
  const std::string dir = test::temp_dir("gltf_uv_bound");
  const LoadedModel m = load_gltf(write_gltf(dir, with_uvs(1e6f)));
  ASSERT_EQ(m.meshes.size(), 1u);
  EXPECT_FLOAT_EQ(m.meshes[0].uvs[0].x(), 1e6f);
}

// ---- Nesting, node graphs and transforms (issue 43) ------------------------------------

TEST(GltfValidation, DeeplyNestedJsonExitsTwoInsteadOfCrashing) {
  // 200000 levels of extras overflowed the stack of tinygltf's recursive conversion (SIGSEGV).
  // The top-level object is level 1: the 512th bracket of the extras goes one level too deep.
  const std::string arrays = std::string(200000, '[') + std::string(200000, ']');
  std::string objects;
  for (int i = 0; i < 200000; ++i) objects += "{\"a\":";
  objects.push_back('0');
  objects.append(200000, '}');
  // Where the extras start in the text written (a .gltf carries its buffer as a data: URI).
  auto column = [](json doc, size_t bracket_width) {
    const std::string text = text_of(doc, "@");
    return "line 1, column " + std::to_string(text.find('@') + 1 + (kMaxJsonNesting - 1) * bracket_width);
  };
  Gltf with_uri = triangle();
  with_uri.doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(with_uri.bin);
  const std::vector<Bad> cases = {
      {"nested arrays", [&](const std::string& d) { return write_gltf(d, triangle(), arrays); }, column(with_uri.doc, 1),
       "nest deeper than 512 levels"},
      {"nested objects in a GLB", [&](const std::string& d) { return write_glb(d, triangle(), 2, objects); },
       "JSON chunk, " + column(triangle().doc, 5), "nest deeper than 512 levels"},
  };
  expect_refused(cases, "gltf_nesting");
}

// `count` nodes in a chain, node k listing node k + 1 as its child `fan` times; the last one
// holds the mesh (a triangle, or with `vertices` unindexed vertices).
Gltf chain(int count, int fan, int vertices = 0) {
  Gltf g = triangle();
  if (vertices > 0) {
    g.bin.assign(size_t(vertices) * 12, 0);
    g.doc["buffers"][0]["byteLength"] = g.bin.size();
    g.doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", g.bin.size()}}});
    g.doc["accessors"] = json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", vertices}, {"type", "VEC3"}}});
    g.doc["meshes"][0]["primitives"][0].erase("indices");
  }
  g.doc["nodes"] = json::array();
  for (int k = 0; k < count; ++k) {
    json n = json::object();
    if (k + 1 < count) n["children"] = std::vector<int>(size_t(fan), k + 1);
    else n["mesh"] = 0;
    g.doc["nodes"].push_back(n);
  }
  return g;
}

TEST(GltfValidation, SharedChildrenAreCountedBeforeFlattening) {
  // Nodes that list the same child twice form a graph with 2^39 paths to its last node: the
  // old flattening ran out of memory (bad_alloc, exit 1) or for ever. Counted per node first,
  // the first node whose subtree expands beyond a bound is named.
  const std::vector<Bad> cases = {
      // Node k expands to 2^(40-k) - 1 instances: node 20 is the first beyond 1000000.
      {"2^40 instances", [](const std::string& d) { return write_gltf(d, chain(40, 2)); }, "nodes[20]",
       "makes 1048575 node instances; at most 1000000 are allowed"},
      // 524287 instances of 402 vertices from node 1: 105 million vertices, beyond 100 million.
      {"105 million vertices", [](const std::string& d) { return write_gltf(d, chain(20, 2, 402)); }, "nodes[1]",
       "makes 105381888 vertices; at most 100000000 are allowed"},
      {"the scene lists one node 2000000 times",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["scenes"][0]["nodes"] = std::vector<int>(2000000, 0);
         return write_gltf(d, g);
       },
       "scenes[0].nodes", "makes 2000000 node instances"},
  };
  expect_refused(cases, "gltf_node_graph");
  // Shared children within the bounds still load, once per path.
  const std::string dir = test::temp_dir("gltf_node_graph_ok");
  EXPECT_EQ(load_gltf(write_gltf(dir, chain(4, 2))).meshes.size(), 8u);
}

TEST(GltfValidation, NodeCyclesAreNamed) {
  const std::vector<Bad> cases = {
      {"two nodes, each the other's child",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["nodes"] = json::array({{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}});
         return write_gltf(d, g);
       },
       "nodes[1].children", "lists nodes[0], one of its own ancestors: the node hierarchy has a cycle"},
      {"child index out of range",
       [](const std::string& d) {
         Gltf g = triangle();
         g.doc["nodes"][0]["children"] = {7};
         return write_gltf(d, g);
       },
       "nodes[0].children", "node index 7 out of range (file has 1 nodes)"},
  };
  expect_refused(cases, "gltf_node_cycles");
}

TEST(GltfValidation, ComposedTransformsMustStayFinite) {
  // Each node's own numbers fit a float; what they compose to does not.
  const std::vector<Bad> cases = {
      {"40 nested scales of 1e10",
       [](const std::string& d) {
         Gltf g = chain(40, 1);
         for (auto& n : g.doc["nodes"]) n["scale"] = {1e10, 1e10, 1e10};
         return write_gltf(d, g);
       },
       "nodes[3]", "its world transform (its own composed with its ancestors') overflows a float"},
      {"two translations of 3e38",
       [](const std::string& d) {
         Gltf g = chain(2, 1);
         for (auto& n : g.doc["nodes"]) n["translation"] = {3e38, 0, 0};
         return write_gltf(d, g);
       },
       "nodes[1]", "overflows a float"},
      {"a position of 3e38 scaled by 2",
       [](const std::string& d) {
         Gltf g = triangle();
         const float big = 3e38f;
         std::memcpy(g.bin.data() + 12, &big, 4);  // vertex 1's x
         g.doc["nodes"][0]["scale"] = {2, 2, 2};
         return write_gltf(d, g);
       },
       "nodes[0]", "moves vertex 1 of meshes[0].primitives[0] beyond the range of a float"},
  };
  expect_refused(cases, "gltf_transforms");
}

}  // namespace
}  // namespace phellem
