// A grown mesh file keeps the materials of its parts (renderer/scene_contents.h with
// bark/growth/face_origin.h): each grown face takes the material of the input face nearest to
// it, so a glTF trunk whose two halves carry two materials grows into two halves with them.
#include <gtest/gtest.h>

#include "bark/geometry/procedural_meshes.h"
#include "io/gltf_writer.h"
#include "renderer/scene_contents.h"
#include "scene/bark_results.h"
#include "scene/mesh_source.h"
#include "scene/scene_parser.h"
#include "tests/support/test_util.h"

using namespace phellem;

namespace {

// An icosphere of radius 0.1 whose faces with x < 0 are one part ("left", red) and the others
// another ("right", blue), sharing their vertices.
std::string two_part_sphere(const std::string& dir) {
  const bark::TriMesh s = bark::icosphere(3, 0.1);
  GlbMesh glb;
  glb.vertices = to_mesh_data(s);
  compute_vertex_normals(glb.vertices);
  GlbPart left{"left", {}, Color(0.8f, 0.1f, 0.1f)}, right{"right", {}, Color(0.1f, 0.1f, 0.8f)};
  for (const auto& f : s.triangles) {
    const double x = s.positions[f[0]].x() + s.positions[f[1]].x() + s.positions[f[2]].x();
    GlbPart& part = x < 0 ? left : right;
    part.indices.insert(part.indices.end(), f.begin(), f.end());
  }
  glb.parts = {left, right};
  const std::string path = dir + "/two_parts.glb";
  write_glb(path, "sphere", glb);
  return path;
}

}  // namespace

TEST(GrownMaterials, EachGrownFaceKeepsTheMaterialOfThePartItGrewFrom) {
  const std::string dir = test::temp_dir("grown_materials");
  const std::string glb = two_part_sphere(dir);
  for (const std::string material : {"", R"(, "material": "grey")"}) {
    const SceneDesc desc = parse_scene(R"({"materials": {"grey": {"type": "diffuse", "base_color": [0.5, 0.5, 0.5]}},
      "objects": [{"type": "mesh", "file": ")" + glb + R"(")" + material +
                                           R"(, "growth": {"steps": 3, "thickness": 0.02}}]})",
                                       dir + "/s.json", dir);
    const BarkResults bark = simulate_bark(desc, false);
    TextureStore textures;
    const SceneContents c = load_scene_contents(desc, bark, textures);
    size_t faces = 0;
    for (const ScenePiece& p : c.pieces) {
      ASSERT_EQ(p.kind, ScenePiece::Kind::Mesh);
      const Color base = c.materials.at(size_t(p.material)).base;
      faces += p.mesh->triangle_count();
      for (size_t f = 0; f < p.mesh->triangle_count(); ++f) {
        const uint32_t* t = &p.mesh->indices[3 * f];
        const float x = p.mesh->positions[t[0]].x() + p.mesh->positions[t[1]].x() + p.mesh->positions[t[2]].x();
        if (!material.empty()) {
          EXPECT_NEAR(base.x(), 0.5f, 1e-6f);  // the scene's material wins
        } else if (std::abs(x) > 0.03f) {     // away from the parts' border, which is ragged
          EXPECT_NEAR(base.x(), x < 0 ? 0.8f : 0.1f, 1e-6f) << "face " << f << " x " << x;
          EXPECT_NEAR(base.z(), x < 0 ? 0.1f : 0.8f, 1e-6f) << "face " << f << " x " << x;
        }
      }
    }
    EXPECT_EQ(c.pieces.size(), material.empty() ? 2u : 1u);
    EXPECT_EQ(faces, bark.find(0)->grown->triangles.size());
  }
}
