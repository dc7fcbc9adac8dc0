// glTF input: hand-made files built here (node transforms, several primitives, textures,
// .glb) and malformed ones that must fail with exit code 2 and a message, never a crash.
#include <gtest/gtest.h>
#include <functional>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/mesh_io.h"
#include "renderer/textures.h"
#include "tests/support/render_helpers.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

using test::base64;

template <typename T>
void append(std::vector<unsigned char>& b, const std::vector<T>& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(v.data());
  b.insert(b.end(), p, p + v.size() * sizeof(T));
}

// Two quads (one triangle pair each) in two primitives of one mesh, used by two nodes: the
// second is a child translated by +2 in x and scaled by 2. Primitive 1 has a texture.
struct TestGltf {
  nlohmann::json doc;
  std::vector<unsigned char> bin;
};

TestGltf make_gltf(const std::string& texture_uri) {
  TestGltf g;
  const std::vector<float> pos = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<float> nrm = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const std::vector<float> uv = {0, 1, 1, 1, 1, 0, 0, 0};
  const std::vector<uint16_t> idx = {0, 1, 2, 0, 2, 3};
  append(g.bin, pos);  // 0..48
  append(g.bin, nrm);  // 48..96
  append(g.bin, uv);   // 96..128
  append(g.bin, idx);  // 128..140
  g.bin.resize(140);
  using nlohmann::json;
  json& d = g.doc;
  d["asset"] = {{"version", "2.0"}};
  d["buffers"] = json::array({{{"byteLength", 140}}});
  d["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                                  {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 48}},
                                  {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 32}},
                                  {{"buffer", 0}, {"byteOffset", 128}, {"byteLength", 12}}});
  d["accessors"] = json::array(
      {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
       {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
       {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
       {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}});
  json prim = {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}, {"indices", 3}, {"material", 0}};
  json prim2 = prim;
  prim2["material"] = 1;
  d["meshes"] = json::array({{{"primitives", json::array({prim, prim2})}}});
  d["materials"] =
      json::array({{{"pbrMetallicRoughness",
                     {{"baseColorFactor", {0.5, 0.25, 1.0, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}},
                   {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 1.0}}}}});
  d["textures"] = json::array({{{"source", 0}}});
  d["images"] = json::array({{{"uri", texture_uri}}});
  d["nodes"] = json::array({{{"mesh", 0}, {"translation", {0, 0, -1}}, {"children", {1}}},
                            {{"mesh", 0}, {"translation", {2, 0, 0}}, {"scale", {2, 2, 2}}}});
  d["scenes"] = json::array({{{"nodes", {0}}}});
  d["scene"] = 0;
  return g;
}

void write_png_texture(const std::string& path) {
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> px(4 * 4 * 3, 188);  // sRGB 188 ≈ linear 0.5
  ASSERT_TRUE(out->open(path, spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
  out->close();
}

// Removes the one texture, so that a malformed file fails on its geometry, not its image.
void drop_texture(TestGltf& g) {
  g.doc["images"] = nlohmann::json::array();
  g.doc["textures"] = nlohmann::json::array();
  g.doc["materials"][1]["pbrMetallicRoughness"].erase("baseColorTexture");
}

std::string write_gltf(const std::string& dir, TestGltf g, bool embed_buffer = true) {
  if (embed_buffer) g.doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(g.bin);
  const std::string path = dir + "/model.gltf";
  std::ofstream(path) << g.doc.dump(1);
  return path;
}

std::string write_glb(const std::string& dir, const TestGltf& g, size_t truncate_to = 0) {
  std::string json = g.doc.dump();
  while (json.size() % 4) json.push_back(' ');
  std::vector<unsigned char> bin = g.bin;
  while (bin.size() % 4) bin.push_back(0);
  std::vector<unsigned char> out;
  auto u32 = [&](uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back((v >> (8 * i)) & 0xFF);
  };
  u32(0x46546C67);
  u32(2);
  u32(uint32_t(12 + 8 + json.size() + 8 + bin.size()));
  u32(uint32_t(json.size()));
  u32(0x4E4F534A);
  out.insert(out.end(), json.begin(), json.end());
  u32(uint32_t(bin.size()));
  u32(0x004E4942);
  out.insert(out.end(), bin.begin(), bin.end());
  if (truncate_to) out.resize(truncate_to);
  const std::string path = dir + "/model.glb";
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
  return path;
}

TEST(Gltf, NodeTransformsPrimitivesAndMaterials) {
  const std::string dir = test::temp_dir("gltf_ok");
  write_png_texture(dir + "/tex.png");
  const LoadedModel m = load_gltf(write_gltf(dir, make_gltf("tex.png")));
  ASSERT_EQ(m.meshes.size(), 4u);  // 2 nodes × 2 primitives
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.materials[0].type, MaterialType::Bark);
  EXPECT_NEAR(m.materials[0].base_color[1], 0.25f, 1e-6f);
  EXPECT_EQ(m.materials[1].type, MaterialType::Conductor);
  EXPECT_NE(m.materials[1].base_color_texture.file.find("tex.png"), std::string::npos);
  // Parent: translated by z = -1. Child: parent ∘ (translate x+2, scale 2).
  EXPECT_TRUE(m.meshes[0].positions[2].isApprox(Vec3f(1, 1, -1)));
  EXPECT_TRUE(m.meshes[2].positions[2].isApprox(Vec3f(4, 2, -1)));
  EXPECT_EQ(m.meshes[1].material, 1);
  // glTF's v runs down; Phellem's runs up.
  EXPECT_NEAR(m.meshes[0].uvs[0].y(), 0.0f, 1e-6f);
}

TEST(Gltf, SpecularExtensionSetsTheCoatStrength) {
  const std::string dir = test::temp_dir("gltf_specular");
  write_png_texture(dir + "/tex.png");
  TestGltf g = make_gltf("tex.png");
  EXPECT_FLOAT_EQ(load_gltf(write_gltf(dir, g)).materials[0].specular, 0.5f);  // glTF default F0 0.04
  g.doc["materials"][0]["extensions"] = {{"KHR_materials_specular", {{"specularFactor", 0.0}}}};
  EXPECT_FLOAT_EQ(load_gltf(write_gltf(dir, g)).materials[0].specular, 0.0f);  // pure Lambert
  g.doc["materials"][0]["extensions"] = {
      {"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularColorFactor", {0.2, 0.8, 0.4}}}}};
  EXPECT_FLOAT_EQ(load_gltf(write_gltf(dir, g)).materials[0].specular, 0.2f);
  g.doc["materials"][0]["extensions"] = {{"KHR_materials_specular", {{"specularFactor", -1.0}}}};
  try {
    load_gltf(write_gltf(dir, g));
    FAIL() << "negative specularFactor accepted";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("materials[0].extensions.KHR_materials_specular"), std::string::npos) << e.what();
  }
}

TEST(Gltf, BinaryGlbLoadsTheSame) {
  const std::string dir = test::temp_dir("glb_ok");
  TestGltf g = make_gltf("tex.png");
  g.doc["buffers"][0].erase("uri");
  g.doc["images"][0] = {{"bufferView", 0}, {"mimeType", "image/png"}};  // bogus image bytes are fine until decoded
  g.doc["materials"][1]["pbrMetallicRoughness"].erase("baseColorTexture");
  const LoadedModel m = load_gltf(write_glb(dir, g));
  EXPECT_EQ(m.meshes.size(), 4u);
  EXPECT_TRUE(m.meshes[2].positions[2].isApprox(Vec3f(4, 2, -1)));
}

TEST(Gltf, RendersWithTexturesThroughTheCli) {
  const std::string dir = test::temp_dir("gltf_render");
  write_png_texture(dir + "/tex.png");
  write_gltf(dir, make_gltf("tex.png"));
  test::write_text(dir + "/scene.json", R"({
    "camera": {"position": [2, 1, 6], "look_at": [2, 1, -1]},
    "render": {"resolution": [32, 24], "spp": 4},
    "lights": [{"type": "environment", "color": [1, 1, 1]}],
    "objects": [{"type": "mesh", "file": "model.gltf"},
                {"type": "mesh", "file": "model.gltf", "transform": {"translate": [0, 0, -3], "rotate_deg": [0, 30, 0], "scale": 0.5}}]
  })");
  const auto r = test::run_phellem("render " + dir + "/scene.json -o " + dir + "/out.exr --stats " + dir + "/stats.json");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir + "/stats.json");
  const auto stats = nlohmann::json::parse(in);
  EXPECT_EQ(stats["triangles"].get<int>(), 16);        // two instances of 8 triangles
  EXPECT_EQ(stats["unique_triangles"].get<int>(), 8);  // stored once (Embree instancing)
}

struct Malformed {
  const char* name;
  std::function<std::string(const std::string& dir)> make;
  const char* expect;  // substring of the message
};

TEST(Gltf, MalformedFilesExitTwoWithAMessage) {
  std::vector<Malformed> cases = {
      {"truncated glb", [](const std::string& d) { return write_glb(d, make_gltf("x.png"), 60); }, "invalid glTF"},
      {"bad accessor index",
       [](const std::string& d) {
         TestGltf g = make_gltf("x.png");
         g.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 42;
         drop_texture(g);
         return write_gltf(d, g);
       },
       "accessor"},
      {"index out of range",
       [](const std::string& d) {
         TestGltf g = make_gltf("x.png");
         g.bin[128] = 99;
         drop_texture(g);
         return write_gltf(d, g);
       },
       "meshes[0].primitives[0].indices: index 99"},
      {"missing buffer file",
       [](const std::string& d) {
         TestGltf g = make_gltf("x.png");
         g.doc["buffers"][0]["uri"] = "missing.bin";
         return write_gltf(d, g, false);
       },
       "invalid glTF"},
      {"buffer too short",
       [](const std::string& d) {
         TestGltf g = make_gltf("x.png");
         g.bin.resize(100);
         g.doc["buffers"][0]["byteLength"] = 100;
         drop_texture(g);
         return write_gltf(d, g);
       },
       "bufferViews"},
      {"not json",
       [](const std::string& d) {
         test::write_text(d + "/model.gltf", "{ this is not json");
         return d + "/model.gltf";
       },
       "invalid glTF"},
      {"missing texture file", [](const std::string& d) { return write_gltf(d, make_gltf("nothere.png")); },
       "image file not found"},
  };
  for (const auto& c : cases) {
    const std::string dir = test::temp_dir(std::string("gltf_bad_") + std::to_string(&c - cases.data()));
    const std::string file = c.make(dir);
    try {
      load_gltf(file);
      ADD_FAILURE() << c.name << ": no error";
    } catch (const UserError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << c.name << ": " << e.what();
      EXPECT_EQ(e.file(), file);
    }
    test::write_text(dir + "/scene.json", std::string(R"({"objects": [{"type": "mesh", "file": ")") + file +
                                              R"("}], "render": {"resolution": [8, 8], "spp": 1}})");
    const auto r = test::run_phellem("render " + dir + "/scene.json -o " + dir + "/o.exr");
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: " + file, 0), 0u) << c.name << ": " << r.output;
  }
}

TEST(Obj, LoadsTrianglesAndRejectsGarbage) {
  const std::string dir = test::temp_dir("obj");
  test::write_text(dir + "/q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const LoadedModel m = load_obj(dir + "/q.obj");
  ASSERT_EQ(m.meshes.size(), 1u);
  EXPECT_EQ(m.meshes[0].triangle_count(), 2u);
  test::write_text(dir + "/bad.obj", "v 0 0 0\nf 1 2 3\n");
  EXPECT_THROW(load_obj(dir + "/bad.obj"), UserError);
}

}  // namespace
}  // namespace phellem

namespace phellem {
namespace {

TEST(Textures, SrgbImagesAreLinearizedAndFiltered) {
  const std::string dir = test::temp_dir("texstore");
  write_png_texture(dir + "/tex.png");  // sRGB 188 everywhere
  TextureStore store;
  TextureDesc d;
  d.file = dir + "/tex.png";
  const int h = store.add(d, {"<t>", "/t"});
  const Color c = store.rgb(h, Vec2f(0.3f, 0.6f), 0.0f);
  EXPECT_NEAR(c[0], 0.5029f, 0.01f);  // sRGB 188/255 decoded
  d.srgb = false;
  const int raw = store.add(d, {"<t>", "/t"});
  EXPECT_NEAR(store.rgb(raw, Vec2f(0.3f, 0.6f), 0.0f)[0], 188.0f / 255.0f, 0.01f);
  TextureDesc missing;
  missing.file = dir + "/corrupt.png";
  test::write_text(missing.file, "not an image");
  EXPECT_THROW(store.add(missing, {"<t>", "/t"}), UserError);
}

}  // namespace
}  // namespace phellem
