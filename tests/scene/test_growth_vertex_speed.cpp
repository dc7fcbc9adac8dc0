// A speed map painted on the vertices of a glTF mesh (scene/growth_desc.h; Kratt et al.,
// Woodification, sec. 4.4): the attribute's first component scales the growth at each vertex,
// and a file without it, or with a value no speed can have, is refused naming where.
#include <gtest/gtest.h>

#include <cmath>

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

// An icosphere of radius 0.1 as a glb, with `name` = `paint(unit position)` per vertex.
std::string painted_sphere(const std::string& dir, const std::string& name, float (*paint)(const Eigen::Vector3d&)) {
  const bark::TriMesh s = bark::icosphere(3, 0.1);
  GlbMesh glb;
  glb.vertices = to_mesh_data(s);
  compute_vertex_normals(glb.vertices);
  std::vector<float> values;
  for (const auto& p : s.positions) values.push_back(paint(p.normalized()));
  if (!name.empty()) glb.scalars = {{name, values}};
  GlbPart part;
  part.name = "bark";
  part.indices = glb.vertices.indices;
  glb.parts = {part};
  const std::string path = dir + "/sphere_" + (name.empty() ? std::string("plain") : name) + ".glb";
  write_glb(path, "sphere", glb);
  return path;
}

std::string scene(const std::string& glb, const std::string& map) {
  return R"({"objects": [{"type": "mesh", "name": "s", "file": ")" + glb +
         R"(", "growth": {"steps": 4, "years": 10, "age_scale": 10, "thickness": 0.03, "speed_map": )" + map + "}}]}";
}

}  // namespace

TEST(GrowthVertexSpeed, APaintedAttributeScalesTheGrowthAtEachVertex) {
  const std::string dir = test::temp_dir("growth_vertex_speed");
  // Full speed on the upper cap, none below the equator.
  const std::string glb = painted_sphere(dir, "_GROWTH_SPEED", [](const Eigen::Vector3d& n) {
    return float(std::clamp(2 * n.y() - 0.2, 0.0, 1.0));
  });
  const GrowthRun run =
      run_growth_object(parse_scene(scene(glb, R"({"attribute": "_GROWTH_SPEED", "scale": 1})"), dir + "/s.json", dir), 0, false);
  double top = 0, bottom = 0;
  int nt = 0, nb = 0;
  for (const auto& p : run.surface->positions) {
    const double r = p.norm(), y = p.y() / r;
    if (y > 0.8) top += r - 0.1, ++nt;
    if (y < -0.3) bottom += r - 0.1, ++nb;
  }
  ASSERT_GT(nt, 5);
  ASSERT_GT(nb, 5);
  top /= nt, bottom /= nb;
  // 0.03 × (1 − e^−1) ≈ 19 mm at full speed; the unpainted half stays (its vertices lie on the
  // icosphere's facets, within 1 mm of the radius).
  EXPECT_GT(top, 0.012) << "top grew " << top;
  EXPECT_LT(std::abs(bottom), 0.001) << "bottom grew " << bottom;
}

TEST(GrowthVertexSpeed, AMissingAttributeOrABadValueIsRefusedWithWhereItIs) {
  const std::string dir = test::temp_dir("growth_vertex_speed_bad");
  const std::string plain = painted_sphere(dir, "", [](const Eigen::Vector3d&) { return 1.0f; });
  try {
    run_growth_object(parse_scene(scene(plain, R"({"attribute": "_GROWTH_SPEED"})"), dir + "/s.json", dir), 0, false);
    FAIL() << "a mesh without the attribute grew";
  } catch (const UserError& e) {
    EXPECT_EQ(e.what(), plain + ": meshes[0].primitives[0].attributes: has no vertex attribute _GROWTH_SPEED");
  }
  const std::string negative = painted_sphere(dir, "_NEG", [](const Eigen::Vector3d& n) { return float(n.x()); });
  try {
    run_growth_object(parse_scene(scene(negative, R"({"attribute": "_NEG"})"), dir + "/s.json", dir), 0, false);
    FAIL() << "a negative speed factor grew";
  } catch (const UserError& e) {
    EXPECT_EQ(e.where(), "/objects/0/growth/speed_map/attribute");
    EXPECT_NE(e.detail().find("a speed factor must lie in [0, 1e6]"), std::string::npos) << e.what();
  }
  // The keys: both a file and an attribute; an attribute on a procedural mesh.
  const auto refused_at = [&](const std::string& json) { return test::where_refused(json, dir + "/s.json", dir); };
  EXPECT_EQ(refused_at(scene(plain, R"({"attribute": "_A", "file": "paint.png"})")), "/objects/0/growth/speed_map/attribute");
  EXPECT_EQ(refused_at(scene(plain, R"({"attribute": ""})")), "/objects/0/growth/speed_map/attribute");
  EXPECT_EQ(refused_at(R"({"objects": [{"type": "mesh", "procedural": {"shape": "log"},
      "growth": {"speed_map": {"attribute": "COLOR_0"}}}]})"),
            "/objects/0/growth/speed_map/attribute");
}
