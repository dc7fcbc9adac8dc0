// Growth directions painted on the vertices of a glTF mesh (scene/growth_desc.h "direction_map";
// Kratt et al., Woodification, sec. 4.4's user-defined growth directions): a VEC3 attribute turns
// the growth from the normal by its length (up to 1), in the scene's space, and a file without
// it, an attribute of another type, or one on a mesh that has no file are refused naming where.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <limits>

#include "bark/geometry/procedural_meshes.h"
#include "io/gltf_writer.h"
#include "scene/growth_run.h"
#include "scene/mesh_source.h"
#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

using namespace phellem;

namespace {

// An icosphere of radius 0.1 as a glb with a VEC3 `_GROWTH_DIRECTION` = `paint(unit position)`
// (or a SCALAR `_SCALAR`, when `scalar`).
std::string painted_sphere(const std::string& dir, const std::string& file, Vec3f (*paint)(const Eigen::Vector3d&),
                           bool scalar = false) {
  const bark::TriMesh s = bark::icosphere(3, 0.1);
  GlbMesh glb;
  glb.vertices = to_mesh_data(s);
  compute_vertex_normals(glb.vertices);
  std::vector<Vec3f> values;
  for (const auto& p : s.positions) values.push_back(paint(p.normalized()));
  if (scalar) {
    std::vector<float> x;
    for (const Vec3f& v : values) x.push_back(v.x());
    glb.scalars = {{"_SCALAR", x}};
  } else {
    glb.vectors = {{"_GROWTH_DIRECTION", values}};
  }
  GlbPart part;
  part.name = "bark";
  part.indices = glb.vertices.indices;
  glb.parts = {part};
  const std::string path = dir + "/" + file;
  write_glb(path, "sphere", glb);
  return path;
}

std::string scene(const std::string& glb, const std::string& growth_extra, const std::string& transform = "") {
  return R"({"objects": [{"type": "mesh", "name": "s", "file": ")" + glb + "\"" + transform +
         R"(, "growth": {"steps": 6, "years": 10, "age_scale": 10, "thickness": 0.03)" + growth_extra + "}}]}";
}

// The point of the growth volume that starts at the top of the sphere, followed by its index
// through the steps (vertex identity), where it ends; and the height of the grown surface.
std::pair<Eigen::Vector3d, double> followed_top(const SceneDesc& scene) {
  long top = -1;
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  const GrowthRun run = run_growth_object(scene, 0, false, [&](const bark::CambialGrowth& g) {
    const bark::TetComplex& c = g.complex();
    if (top < 0)  // after the first step, which moves it less than a millimetre
      for (uint32_t i = 0; i < c.points.size(); ++i)
        if (c.on_interface[i] && c.source_vertex[i] >= 0 && (top < 0 || c.points[i].y() > c.points[size_t(top)].y())) top = i;
    at = c.points[size_t(top)];
  });
  double height = -1e300;
  for (const auto& p : run.surface->positions) height = std::max(height, p.y());
  return {at, height};
}

// A uniform 4 × 4 image of `channels` channels at `path`: every pixel `value` (8-bit when
// `png`, 32-bit float otherwise).
std::string uniform_image(const std::string& path, std::vector<float> value, bool png) {
  const int channels = int(value.size());
  OIIO::ImageSpec spec(4, 4, channels, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  std::vector<float> px;
  for (int i = 0; i < 16; ++i) px.insert(px.end(), value.begin(), value.end());
  auto out = OIIO::ImageOutput::create(path);
  EXPECT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, px.data()) && out->close()) << path;
  return path;
}

std::string log_scene(const std::string& growth_extra) {
  return R"({"objects": [{"type": "mesh", "name": "log",
      "procedural": {"shape": "log", "triangles": 3000, "radius": 0.1, "height": 0.3},
      "growth": {"steps": 6, "years": 10, "age_scale": 10, "thickness": 0.03)" + growth_extra + "}}]}";
}

// The point of the log's side at mid-height facing +x (u = 0, where u grows towards −z and v
// towards +y), followed by index through the growth: where it ends.
Eigen::Vector3d followed_side(const SceneDesc& scene) {
  long side = -1;
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  run_growth_object(scene, 0, false, [&](const bark::CambialGrowth& g) {
    const bark::TetComplex& c = g.complex();
    auto score = [&](uint32_t i) { return c.points[i].x() - 4 * std::abs(c.points[i].y() - 0.15) - 4 * std::abs(c.points[i].z()); };
    if (side < 0)
      for (uint32_t i = 0; i < c.points.size(); ++i)
        if (c.on_interface[i] && c.source_vertex[i] >= 0 && (side < 0 || score(i) > score(uint32_t(side)))) side = i;
    at = c.points[size_t(side)];
  });
  return at;
}

}  // namespace

TEST(GrowthDirectionMap, AFlowMapTurnsTheGrowthAlongTheTexturesUAndVAxes) {
  const std::string dir = test::temp_dir("growth_flow_map");
  auto map = [](const std::string& file) { return R"(, "direction_map": {"file": ")" + file + "\"}"; };
  // A PNG holds 0.5 + 0.5·d: red 1, green mid-grey is "along u, by 1".
  uniform_image(dir + "/along_u.png", {1.0f, 128.0f / 255, 0}, true);
  // An EXR holds d itself: against v by 0.9.
  uniform_image(dir + "/down_v.exr", {0, -0.9f}, false);
  const Eigen::Vector3d plain = followed_side(parse_scene(log_scene(""), dir + "/s.json", dir));
  const Eigen::Vector3d along_u = followed_side(parse_scene(log_scene(map("along_u.png")), dir + "/s.json", dir));
  const Eigen::Vector3d down_v = followed_side(parse_scene(log_scene(map("down_v.exr")), dir + "/s.json", dir));
  // About 19 mm of growth: straight out along +x unturned; turned fully along u (towards −z),
  // the point slides ~18 mm round the log; 0.9 of the way down v, it slides down the log.
  EXPECT_GT(plain.x(), 0.115) << plain.transpose();
  EXPECT_LT(std::abs(plain.z()), 0.003) << plain.transpose();
  EXPECT_LT(along_u.z(), plain.z() - 0.012) << along_u.transpose();
  EXPECT_LT(std::abs(along_u.y() - plain.y()), 0.002) << along_u.transpose();
  EXPECT_LT(down_v.y(), plain.y() - 0.012) << down_v.transpose();
  EXPECT_LT(std::abs(down_v.z() - plain.z()), 0.002) << down_v.transpose();
  // "scale" 0 turns nothing: the growth with none (to float rounding: turned directions are
  // computed in float).
  const Eigen::Vector3d scaled = followed_side(
      parse_scene(log_scene(R"(, "direction_map": {"file": "along_u.png", "scale": 0})"), dir + "/s.json", dir));
  EXPECT_LT((scaled - plain).norm(), 1e-5) << scaled.transpose() << " vs " << plain.transpose();
}

TEST(GrowthDirectionMap, ABadFlowMapIsRefusedNamingWhere) {
  const std::string dir = test::temp_dir("growth_flow_map_bad");
  uniform_image(dir + "/grey.png", {0.5f}, true);
  uniform_image(dir + "/good.png", {1.0f, 0.5f, 0.5f}, true);
  uniform_image(dir + "/nan.exr", {std::numeric_limits<float>::quiet_NaN(), 0}, false);
  uniform_image(dir + "/huge.exr", {3e6f, 0}, false);
  const auto refused = [&](const std::string& map, const std::string& where, const std::string& detail) {
    test::expect_user_error([&] { parse_scene(log_scene(R"(, "direction_map": )" + map), dir + "/s.json", dir); }, map,
                            dir + "/s.json", "/objects/0/growth/direction_map" + where, detail);
  };
  refused(R"({"file": "grey.png"})", "/file", "a flow map needs two (red: along u, green: along v)");
  refused(R"({"file": "nan.exr"})", "/file", "not finite at pixel 0, 0");
  refused(R"({"file": "huge.exr"})", "/file", "longer than 1e6");
  refused(R"({"file": "missing.png"})", "/file", "file not found");
  refused(R"({})", "/file", "needs an image \"file\" (a flow map) or a vertex \"attribute\"");
  refused(R"({"file": "good.png", "scale": -1})", "/scale", "scale must lie in [0, 1000]");
  refused(R"({"file": "good.png", "attribute": "_D"})", "/attribute", "not both");
  refused(R"({"attribute": "_D", "scale": 2})", "/attribute", "scale belongs to an image");
  // A mesh without texture coordinates has no frame to read a flow map in.
  bark::TriMesh bare = bark::icosphere(3, 0.1);
  bare.uvs.clear();
  GlbMesh glb;
  glb.vertices = to_mesh_data(bare);
  compute_vertex_normals(glb.vertices);
  GlbPart part;
  part.name = "bark";
  part.indices = glb.vertices.indices;
  glb.parts = {part};
  write_glb(dir + "/bare.glb", "sphere", glb);
  test::expect_user_error(
      [&] { run_growth_object(parse_scene(scene(dir + "/bare.glb", R"(, "direction_map": {"file": "good.png"})"), dir + "/s.json", dir), 0, false); },
      "no uvs", dir + "/s.json", "/objects/0/growth/direction_map", "needs a mesh with texture coordinates");
  // (A glTF file without TEXCOORD_0 loads with every UV at 0: a painted speed map is refused
  // on it the same way, rather than read at one texel everywhere.)
  test::expect_user_error(
      [&] { run_growth_object(parse_scene(scene(dir + "/bare.glb", R"(, "speed_map": {"file": "grey.png"})"), dir + "/s.json", dir), 0, false); },
      "no uvs, speed", dir + "/s.json", "/objects/0/growth/speed_map", "needs a mesh with texture coordinates");
}

TEST(GrowthDirectionMap, APaintedDirectionLeansTheGrowthWhereItIsPaintedAndFollowsTheTransform) {
  const std::string dir = test::temp_dir("growth_direction_map");
  // The upper cap painted +x at full length, the rest not at all.
  const std::string glb = painted_sphere(dir, "lean.glb", [](const Eigen::Vector3d& n) {
    return n.y() > 0.5 ? Vec3f(1, 0, 0) : Vec3f::Zero();
  });
  const std::string map = R"(, "direction_map": {"attribute": "_GROWTH_DIRECTION"})";
  const auto [plain, plain_height] = followed_top(parse_scene(scene(glb, ""), dir + "/s.json", dir));
  const auto [lean, lean_height] = followed_top(parse_scene(scene(glb, map), dir + "/s.json", dir));
  // 0.03 × (1 − e^−1) ≈ 19 mm of growth: turned to the normal's least share (0.2), the point at
  // the top slides about 18 mm towards +x; unturned, it rises along the axis.
  EXPECT_LT(std::abs(plain.x()), 0.001) << plain.transpose();
  EXPECT_GT(plain.y(), 0.115) << plain.transpose();
  EXPECT_GT(lean.x(), 0.015) << lean.transpose();
  // Turned from the normal, the cap grows outwards less: the surface ends lower.
  EXPECT_LT(lean_height, plain_height - 0.005) << lean_height << " vs " << plain_height;
  // Turned a quarter around y by the object's transform, the painted +x points along −z.
  const auto [turned, turned_height] =
      followed_top(parse_scene(scene(glb, map, R"(, "transform": {"rotate_deg": [0, 90, 0]})"), dir + "/s.json", dir));
  EXPECT_LT(turned.z(), -0.015) << turned.transpose();
  EXPECT_LT(std::abs(turned.x()), 0.002) << turned.transpose();
}

TEST(GrowthDirectionMap, AMissingOrScalarAttributeAndMeshesWithoutAFileAreRefused) {
  const std::string dir = test::temp_dir("growth_direction_map_bad");
  const std::string map = R"(, "direction_map": {"attribute": "_GROWTH_DIRECTION"})";
  const std::string scalar = painted_sphere(dir, "scalar.glb", [](const Eigen::Vector3d&) { return Vec3f(1, 0, 0); }, true);
  try {
    run_growth_object(parse_scene(scene(scalar, map), dir + "/s.json", dir), 0, false);
    FAIL() << "a mesh without the attribute grew";
  } catch (const UserError& e) {
    EXPECT_EQ(e.what(), scalar + ": meshes[0].primitives[0].attributes: has no vertex attribute _GROWTH_DIRECTION");
  }
  try {
    run_growth_object(parse_scene(scene(scalar, R"(, "direction_map": {"attribute": "_SCALAR"})"), dir + "/s.json", dir), 0, false);
    FAIL() << "a scalar attribute turned the growth";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("meshes[0].primitives[0].attributes._SCALAR"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected 3"), std::string::npos) << e.what();
  }
  const auto refused_at = [&](const std::string& json) { return test::where_refused(json, dir + "/s.json", dir); };
  EXPECT_EQ(refused_at(scene(scalar, R"(, "direction_map": {"attribute": ""})")), "/objects/0/growth/direction_map/attribute");
  EXPECT_EQ(refused_at(R"({"objects": [{"type": "mesh", "procedural": {"shape": "log"},
      "growth": {"direction_map": {"attribute": "_GROWTH_DIRECTION"}}}]})"),
            "/objects/0/growth/direction_map/attribute");
}
