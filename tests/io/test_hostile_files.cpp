// Hostile input files, second round (issue 43): a FIFO wherever a file is read (it would block
// the reader for ever), a JPEG cut short (libjpeg only warns and fills the rest with grey), and
// a texture cache entry left truncated by a full disk (util/cache_dir.h never trusts an entry
// it has not compared with the bytes it should hold).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/height_image.h"
#include "io/mesh_io.h"
#include "renderer/textures.h"
#include "scene/environment_image.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

namespace fs = std::filesystem;

// A size × size RGB image of noise (so that it compresses badly) in whatever format `path` names.
// grey: R = G = B (a height map saved in colour; random colours are a colour photo to `compare`).
std::string noise_image(const std::string& path, int size = 64, bool grey = false) {
  std::vector<unsigned char> px(size_t(size) * size_t(size) * 3);
  uint32_t x = 12345;
  for (auto& p : px) p = static_cast<unsigned char>((x = x * 1664525u + 1013904223u) >> 24);
  if (grey)
    for (size_t i = 0; i < px.size(); i += 3) px[i + 1] = px[i + 2] = px[i];
  auto out = OIIO::ImageOutput::create(path);
  EXPECT_TRUE(out && out->open(path, OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::UINT8)) &&
              out->write_image(OIIO::TypeDesc::UINT8, px.data()) && out->close())
      << path;
  return path;
}

// A valid JPEG (whole.jpg) and its first half (cut.jpg): the header reads, half the scan data
// is missing.
std::string truncated_jpeg(const std::string& dir, int size = 64, bool grey = false) {
  const std::string bytes = test::read_text(noise_image(dir + "/whole.jpg", size, grey));
  const std::string cut = dir + "/cut.jpg";
  test::write_text(cut, bytes.substr(0, bytes.size() / 2));
  return cut;
}

std::string fifo(const std::string& path) {
  EXPECT_EQ(mkfifo(path.c_str(), 0600), 0) << path;
  return path;
}

// Textures are converted into the cache: a folder of the test's own.
void use_cache_in(const std::string& dir) { setenv("XDG_CACHE_HOME", (dir + "/cache").c_str(), 1); }

// A one-triangle glTF with texture coordinates whose material's base colour is image 0 at
// `image_uri`; its buffer is the file m.bin beside it (written unless `write_bin` is false).
std::string triangle_gltf(const std::string& dir, const std::string& image_uri, bool write_bin = true) {
  const float data[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
  if (write_bin) test::write_text(dir + "/m.bin", std::string(reinterpret_cast<const char*>(data), sizeof data));
  nlohmann::json g = {
      {"asset", {{"version", "2.0"}}},
      {"buffers", {{{"uri", "m.bin"}, {"byteLength", 60}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}}, {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}},
      {"images", {{{"uri", image_uri}}}},
      {"textures", {{{"source", 0}}}},
      {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"material", 0}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"scene", 0}};
  test::write_text(dir + "/model.gltf", g.dump());
  return dir + "/model.gltf";
}

std::string data_uri(const std::string& png_bytes) {
  return "data:image/png;base64," + test::base64(std::vector<unsigned char>(png_bytes.begin(), png_bytes.end()));
}

// A one-triangle OBJ whose material library is m.mtl beside it (not written here).
std::string triangle_obj(const std::string& dir) {
  test::write_text(dir + "/model.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl bark\nf 1/1 2/2 3/3\n");
  return dir + "/model.obj";
}

// `phellem render` of a scene holding the mesh file `mesh`, at most 60 s: a build that opens
// a FIFO times out (exit 124) instead of hanging the test.
test::CommandResult render_mesh(const std::string& dir, const std::string& mesh) {
  test::write_text(dir + "/scene.json", R"({"objects": [{"type": "mesh", "file": ")" + mesh +
                                            R"("}], "render": {"resolution": [8, 8], "spp": 1}})");
  return test::run_phellem_limited("render " + dir + "/scene.json -o " + dir + "/out.exr", 4096, 60);
}

void expect_refused(const test::CommandResult& r, const std::string& file_and_where, const std::string& says) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + file_and_where, 0), 0u) << r.output;
  EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
}

// --- A FIFO is refused before it is opened -------------------------------------------------

TEST(FifoInput, AnObjMaterialLibraryThatIsAFifoIsRefused) {
  const std::string dir = test::temp_dir("fifo_mtl");
  use_cache_in(dir);
  const std::string obj = triangle_obj(dir);
  fifo(dir + "/m.mtl");
  expect_refused(render_mesh(dir, obj), obj + ": mtllib m.mtl: ",
                 dir + "/m.mtl is not a regular file (a FIFO); a material library is read from a regular file");
}

TEST(FifoInput, AnObjTextureThatIsAFifoIsRefused) {
  const std::string dir = test::temp_dir("fifo_map_kd");
  const std::string obj = triangle_obj(dir);
  test::write_text(dir + "/m.mtl", "newmtl bark\nKd 0.5 0.5 0.5\nmap_Kd tex.png\n");
  fifo(dir + "/tex.png");
  test::expect_user_error([&] { load_obj(obj); }, "map_Kd", obj, "material bark: map_Kd",
                          dir + "/tex.png is not a regular file (a FIFO); a texture is read from a regular file");
}

TEST(FifoInput, AGltfBufferThatIsAFifoIsRefused) {
  const std::string dir = test::temp_dir("fifo_bin");
  use_cache_in(dir);
  noise_image(dir + "/tex.png");
  const std::string gltf = triangle_gltf(dir, "tex.png", false);
  fifo(dir + "/m.bin");
  expect_refused(render_mesh(dir, gltf), gltf + ": read: invalid glTF: ",
                 "is not a regular file (a FIFO); glTF buffers and images are read from regular files");
}

TEST(FifoInput, AGltfImageThatIsAFifoIsRefused) {
  const std::string dir = test::temp_dir("fifo_gltf_image");
  use_cache_in(dir);
  const std::string gltf = triangle_gltf(dir, "tex.png");
  fifo(dir + "/tex.png");
  expect_refused(render_mesh(dir, gltf), gltf + ": images[0].uri: ",
                 dir + "/tex.png is not a regular file (a FIFO); an image is read from a regular file");
}

TEST(FifoInput, AHeightMapOrPhotoThatIsAFifoIsRefused) {
  const std::string dir = test::temp_dir("fifo_height");
  const std::string f = fifo(dir + "/height.png");
  const std::string says = "is not a regular file (a FIFO); an image is read from a regular file";
  test::expect_user_error([&] { read_height_image(f); }, "height map", f, "", says);
  test::expect_user_error([&] { read_albedo_image(f); }, "albedo", f, "", says);
  // Before any other check: `compare` and `fit` say so too, at once.
  noise_image(dir + "/other.png");
  expect_refused(test::run_phellem_limited("compare " + f + " " + dir + "/other.png --scale A=10 --scale B=10", 4096, 60),
                 f + ": ", says);
  expect_refused(test::run_phellem_limited("fit " + f + " --scale 10 --model strips -o " + dir + "/out", 4096, 60), f + ": ",
                 says);
}

// --- A truncated JPEG is refused, not read with a grey lower half --------------------------

TEST(TruncatedJpeg, IsRefusedAsAHeightMapAndAsAPhoto) {
  const std::string dir = test::temp_dir("jpeg_cut_height");
  const std::string cut = truncated_jpeg(dir);
  test::expect_user_error([&] { read_height_image(cut); }, "height map", cut, "pixels", "Premature end of JPEG file");
  test::expect_user_error([&] { read_albedo_image(cut); }, "albedo", cut, "pixels", "Premature end of JPEG file");
  EXPECT_NO_THROW(read_height_image(dir + "/whole.jpg"));
}

// 512 px at 10 px/cm: large enough for both commands, which take the whole image. Grey noise:
// random colours are refused by `compare` as a colour photo (issue 44), whole or not.
TEST(TruncatedJpeg, CompareAndFitExitTwo) {
  const std::string dir = test::temp_dir("jpeg_cut_cli");
  const std::string cut = truncated_jpeg(dir, 512, true), whole = dir + "/whole.jpg";
  const std::string says = "cannot decode the pixels: the file is damaged or cut short (JPEG error: Premature end of JPEG file";
  const std::string scales = " --scale A=10 --scale B=10";
  expect_refused(test::run_phellem_limited("compare " + cut + " " + whole + scales, 4096, 120), cut + ": pixels: ", says);
  expect_refused(test::run_phellem_limited("fit " + cut + " --scale 10 --model strips --max-evals 1 -o " + dir + "/out", 4096, 120),
                 cut + ": pixels: ", says);
  EXPECT_FALSE(fs::exists(dir + "/out"));
  const auto r = test::run_phellem_limited("compare " + whole + " " + whole + scales, 4096, 120);
  EXPECT_EQ(r.exit_code, 0) << r.output;  // the same file whole
}

TEST(TruncatedJpeg, IsRefusedAsATexture) {
  const std::string dir = test::temp_dir("jpeg_cut_texture");
  use_cache_in(dir);
  const std::string cut = truncated_jpeg(dir);
  const Location where{dir + "/scene.json", "/materials/bark/base_color_texture"};
  for (bool srgb : {true, false}) {  // decoded to linear by Phellem, or converted by OpenImageIO
    TextureStore store;
    TextureDesc d;
    d.file = cut;
    d.srgb = srgb;
    test::expect_user_error([&] { store.add(d, where); }, srgb ? "sRGB" : "linear", where.file, where.path,
                            "cannot read image " + cut + ": the file is damaged or cut short");
    d.file = dir + "/whole.jpg";
    EXPECT_GE(store.add(d, where), 0);
  }
}

TEST(TruncatedJpeg, IsRefusedAsAnEnvironmentMap) {
  const std::string dir = test::temp_dir("jpeg_cut_env");
  LightDesc l;
  l.type = LightType::EnvironmentMap;
  l.where = {dir + "/scene.json", "/lights/0"};
  l.file = truncated_jpeg(dir);
  int w = 0, h = 0;
  test::expect_user_error([&] { load_environment_image(l, &w, &h); }, "environment", l.where.file, "/lights/0/file",
                          "Premature end of JPEG file");
}

// --- The texture cache: entries verified before use, written whole or not at all ----------

// Loads `gltf` and returns the file its material's base colour texture is read from.
std::string base_color_file(const std::string& gltf) {
  const LoadedModel m = load_gltf(gltf);
  EXPECT_EQ(m.materials.size(), 1u);
  return m.materials.empty() ? std::string() : m.materials[0].base_color_texture.file;
}

TEST(TextureCache, AnEmbeddedImageEntryThatHoldsOtherBytesIsWrittenAgain) {
  const std::string dir = test::temp_dir("cache_poisoned");
  use_cache_in(dir);
  const std::string png = test::read_text(noise_image(dir + "/tex.png"));
  const std::string gltf = triangle_gltf(dir, data_uri(png));
  const std::string entry = base_color_file(gltf);
  ASSERT_EQ(entry.rfind(dir + "/cache/phellem/textures/", 0), 0u) << entry;
  ASSERT_EQ(test::read_text(entry), png);
  // What a full disk left (the first half), another file's bytes of the same size, and an
  // empty file: each is found out and replaced by the image's bytes.
  for (const std::string& bad : {png.substr(0, png.size() / 2), std::string(png.size(), 'x'), std::string()}) {
    test::write_text(entry, bad);
    EXPECT_EQ(base_color_file(gltf), entry);
    EXPECT_EQ(test::read_text(entry), png) << "after an entry of " << bad.size() << " bytes";
  }
  // A FIFO at the entry's name is replaced too, never handed to a reader.
  fs::remove(entry);
  fifo(entry);
  EXPECT_EQ(base_color_file(gltf), entry);
  ASSERT_TRUE(fs::is_regular_file(entry));
  EXPECT_EQ(test::read_text(entry), png);
  EXPECT_TRUE(test::leftover_temporaries(dir + "/cache").empty());
}

// A full disk, simulated by a file size limit (with SIGXFSZ ignored, a write past it fails with
// EFBIG): the run that cannot write the entry says so and leaves nothing in the cache, and the
// next run, with room again, renders.
TEST(TextureCache, AFullDiskLeavesNoTruncatedEntryBehind) {
  const std::string dir = test::temp_dir("cache_full_disk");
  const std::string png = test::read_text(noise_image(dir + "/tex.png", 96));
  ASSERT_GT(png.size(), 16384u);
  const std::string gltf = triangle_gltf(dir, data_uri(png));
  test::write_text(dir + "/scene.json", R"({"objects": [{"type": "mesh", "file": ")" + gltf +
                                            R"("}], "render": {"resolution": [8, 8], "spp": 1}})");
  const std::string render = "XDG_CACHE_HOME=" + dir + "/cache timeout -k 5 120 " + PHELLEM_BINARY + " render " + dir +
                             "/scene.json -o " + dir + "/out.exr --quiet 2>&1";
  // ulimit -f counts 512-byte blocks in dash and 1 KiB ones in bash: 8 is at most 8 KiB.
  const auto full = test::run_command("ulimit -f 8 && trap '' XFSZ && " + render);
  expect_refused(full, gltf + ": images[0]: write: ", "File too large");
  const std::string textures = dir + "/cache/phellem/textures";
  for (const auto& e : fs::directory_iterator(textures)) ADD_FAILURE() << "left in the cache: " << e.path();
  const auto roomy = test::run_command(render);
  EXPECT_EQ(roomy.exit_code, 0) << roomy.output;
  EXPECT_TRUE(fs::exists(dir + "/out.exr"));
  size_t entries = 0;
  for (const auto& e : fs::directory_iterator(textures))
    if (e.path().filename().string().rfind("gltf_", 0) == 0) {
      ++entries;
      EXPECT_EQ(test::read_text(e.path().string()), png) << e.path();
    }
  EXPECT_EQ(entries, 1u);
}

}  // namespace
}  // namespace phellem
