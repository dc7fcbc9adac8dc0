// The preview's image displacement (shaders/displacement_map.glsl) against the C++ one the path
// tracer dices with: every tessellated vertex, captured by transform feedback, where
// patch_surface / the tree's parametric surface put it, within 1e-5 m. Patches with maps made
// here (a sine that tiles and a ramp that does not) in repeat and clamp modes, past the map's
// edges; a tree's trunk and branch at the tree's texcoords; a strip tree, where the image adds
// to the FractureField's depth; a stress-bark trunk, where it adds to the cracks. Each
// comparison also runs against a wrong C++ reference (another midlevel, the other wrap), which
// must miss: the check can fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "preview/preview_renderer.h"
#include "bark/dressing/crack_bark_surface.h"
#include "bark/dressing/field_bark_surface.h"
#include "preview/preview_scene.h"
#include "scene/bark_results.h"
#include "scene/displacement.h"
#include "scene/displacement_map.h"
#include "scene/object_meshes.h"
#include "scene/scene_parser.h"
#include "scene/tree_surface.h"
#include "tests/preview/gl_context_for_tests.h"

using namespace phellem;
using namespace phellem::preview;

namespace {

constexpr double kTolerance = 1e-5;  // m, absolute

// 3 × 2 periods over the map: it tiles without a seam.
std::shared_ptr<const DisplacementMap> sine_map() {
  auto m = std::make_shared<DisplacementMap>();
  m->width = 48;
  m->height = 40;
  for (int j = 0; j < m->height; ++j)
    for (int i = 0; i < m->width; ++i)
      m->value.push_back(0.5f + 0.45f * std::sin(kTwoPi * 3.0f * float(i) / float(m->width)) *
                                    std::cos(kTwoPi * 2.0f * float(j) / float(m->height)));
  return m;
}

// Rising to the right and towards the top row (v = 1): opposite edges differ, so repeat blends
// the last texel into the first and clamp holds the edges.
std::shared_ptr<const DisplacementMap> ramp_map() {
  auto m = std::make_shared<DisplacementMap>();
  m->width = 20;
  m->height = 12;
  for (int j = 0; j < m->height; ++j)
    for (int i = 0; i < m->width; ++i)
      m->value.push_back(0.8f * float(i) / float(m->width - 1) + 0.2f * float(m->height - 1 - j) / float(m->height - 1));
  return m;
}

DisplacementDesc image(std::shared_ptr<const DisplacementMap> map, float scale, float midlevel, float uv_repeat, bool clamp) {
  DisplacementDesc d;
  d.type = DisplacementDesc::Type::Image;
  d.file = "<in memory>";
  d.map = std::move(map);
  d.scale = scale;
  d.midlevel = midlevel;
  d.uv_repeat = uv_repeat;
  d.clamp = clamp;
  return d;
}

// A 30 × 20 cm patch, tilted so that no axis is special, seen from its front.
ObjectDesc tilted_patch(const DisplacementDesc& d) {
  ObjectDesc o;
  o.type = ObjectType::Patch;
  o.point = Vec3f(0.1f, 1.0f, -0.2f);
  o.normal = Vec3f(0.3f, 0.2f, 1.0f).normalized();
  o.up = Vec3f(0.1f, 1.0f, 0.0f);
  o.size = Vec2f(0.3f, 0.2f);
  o.displacement = d;
  return o;
}

CameraModel facing(const Vec3f& target, const Vec3f& normal, float distance, int size) {
  CameraDesc c;
  c.look_at = target;
  c.position = target + distance * normal + Vec3f(0.03f, 0.02f, 0.0f);
  c.up = Vec3f(0, 1, 0);
  c.fov_deg = 45;
  return CameraModel(c, size, size);
}

PreviewSettings fine() {
  PreviewSettings s;
  s.target_near_px = 2;
  return s;
}

struct Deviation {
  double worst = 0, wrong = 0;  // against the C++, and against a wrong C++ reference
  size_t vertices = 0;
};

}  // namespace

class PatchImageDisplacement : public ::testing::TestWithParam<int> {};

TEST_P(PatchImageDisplacement, EveryTessellatedVertexIsWhereTheCppPatchSurfacePutsIt) {
  PHELLEM_REQUIRE_GL();
  struct Case {
    const char* name;
    DisplacementDesc d;
  };
  const Case cases[] = {
      {"sine, repeat 2.5", image(sine_map(), 0.02f, 0.4f, 2.5f, false)},
      {"ramp, repeat 1.3", image(ramp_map(), 0.015f, 0.5f, 1.3f, false)},
      {"ramp, clamp 1.3", image(ramp_map(), -0.015f, 0.3f, 1.3f, true)},
  };
  const Case& c = cases[GetParam()];
  SCOPED_TRACE(c.name);
  SceneDesc desc;
  desc.objects.push_back(tilted_patch(c.d));
  const PreviewScene scene = build_preview_scene(desc, BarkResults{});
  ASSERT_EQ(scene.objects.size(), 1u);
  ASSERT_TRUE(scene.objects[0].image);
  PreviewRenderer renderer(scene);
  const ObjectDesc& o = desc.objects[0];
  const auto fb = renderer.capture(0, facing(o.point, o.normal, 0.4f, 256), fine());
  ASSERT_GT(fb.base.size(), 20000u);
  // The C++ surface the path tracer dices, and two wrong ones: another midlevel, the other wrap.
  DisplacementDesc other_mid = c.d, other_wrap = c.d;
  other_mid.midlevel += 0.01f;
  other_wrap.clamp = !c.d.clamp;
  const ParametricSurface surface = patch_surface(o, make_displacement(c.d));
  const ParametricSurface wrong_mid = patch_surface(o, make_displacement(other_mid));
  const ParametricSurface wrong_wrap = patch_surface(o, make_displacement(other_wrap));
  const PatchFrame frame = patch_frame(o);
  Deviation dev;
  double wrong_wrap_worst = 0, texcoord_worst = 0, most_offset = 0;
  Vec2f lo(1e9f, 1e9f), hi(-1e9f, -1e9f);
  for (size_t k = 0; k < fb.base.size(); ++k) {
    const Vec2f t = fb.texcoord[k];
    // The texcoords are the point's place on the patch ((0, 0) bottom-left, (1, 1) top-right).
    const Vec3f rel = fb.base[k] - frame.centre;
    const Vec2f at(rel.dot(frame.right) / o.size.x() + 0.5f, rel.dot(frame.up) / o.size.y() + 0.5f);
    texcoord_worst = std::max(texcoord_worst, double((at - t).cwiseAbs().maxCoeff()));
    float offset = 0;
    const Vec3f expected = surface.position(t.x(), t.y(), &offset);
    dev.worst = std::max(dev.worst, double((fb.displaced[k] - expected).norm()));
    dev.wrong = std::max(dev.wrong, double((fb.displaced[k] - wrong_mid.position(t.x(), t.y(), nullptr)).norm()));
    wrong_wrap_worst = std::max(wrong_wrap_worst, double((fb.displaced[k] - wrong_wrap.position(t.x(), t.y(), nullptr)).norm()));
    most_offset = std::max(most_offset, double(std::abs(offset)));
    lo = lo.cwiseMin(t);
    hi = hi.cwiseMax(t);
  }
  RecordProperty("max_deviation_m", std::to_string(dev.worst));
  std::printf("  %s: %zu vertices, max deviation %.3g m (wrong midlevel %.3g m, wrong wrap %.3g m)\n", c.name, fb.base.size(),
              dev.worst, dev.wrong, wrong_wrap_worst);
  EXPECT_LT(dev.worst, kTolerance);
  EXPECT_LT(texcoord_worst, 1e-5);
  // The comparison covers the whole patch, a real relief, and can fail.
  EXPECT_LT(lo.maxCoeff(), 0.01f);
  EXPECT_GT(hi.minCoeff(), 0.99f);
  EXPECT_GT(most_offset, 0.25 * std::abs(c.d.scale));
  EXPECT_GT(dev.wrong, 10 * kTolerance);
  EXPECT_GT(wrong_wrap_worst, 10 * kTolerance);
}

INSTANTIATE_TEST_SUITE_P(Maps, PatchImageDisplacement, ::testing::Values(0, 1, 2));

namespace {

// The offset of part k of `parts` at (u, v), as the dicer evaluates it.
float part_offset(const std::vector<TreePart>& parts, size_t k, float u, float v) {
  float offset = 0;
  parts[k].surface.position(u, v, &offset);
  return offset;
}

// Each part of a tree (object k of the preview scene is part k) against the C++ surface's
// offset at the same (u, v), and against a deliberately wrong one; the base point is the
// preview's own (curved patches through the grid), so the offset along its normal is compared.
Deviation compare_tree_parts(const PreviewScene& scene, const CameraModel& camera, const std::vector<TreePart>& parts,
                             const std::vector<TreePart>& wrong_parts) {
  PreviewRenderer renderer(scene);
  PreviewSettings s = fine();
  s.cull = false;  // every patch, the far side too
  Deviation dev;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const auto fb = renderer.capture(k, camera, s);
    EXPECT_GT(fb.base.size(), 3000u) << "part " << k;
    for (size_t i = 0; i < fb.base.size(); ++i) {
      const Vec3f n = fb.normal[i].normalized();
      const Vec2f uv = fb.param[i];
      const Vec3f expected = fb.base[i] + part_offset(parts, k, uv.x(), uv.y()) * n;
      const Vec3f wrong = fb.base[i] + part_offset(wrong_parts, k, uv.x(), uv.y()) * n;
      dev.worst = std::max(dev.worst, double((fb.displaced[i] - expected).norm()));
      dev.wrong = std::max(dev.wrong, double((fb.displaced[i] - wrong).norm()));
    }
    dev.vertices += fb.base.size();
  }
  return dev;
}

const char* kTree = R"({
  "camera": {"position": [0.0, 0.5, 0.8], "look_at": [0, 0.5, 0], "fov_deg": 40},
  "objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 0.5, 0.02], [0, 1.0, 0]], "radius": [0.1, 0.08], "uv_repeat": 2,
    "branches": [{"attach": 0.6, "azimuth_deg": 30, "angle_deg": 50, "length": 0.4, "radius": [0.04, 0.02]}]}]
})";

}  // namespace

TEST(TreeImageDisplacement, TrunkAndBranchAreDisplacedAtTheTreesTexcoordsAsTheCppSurface) {
  PHELLEM_REQUIRE_GL();
  SceneDesc desc = parse_scene(kTree, "tree.json", ".");
  TreeDesc& tree = desc.objects[0].tree;
  tree.texture_displacement = image(sine_map(), 0.01f, 0.45f, 1.5f, false);
  desc.objects[0].displacement = tree.texture_displacement;
  const PreviewScene scene = build_preview_scene(desc, BarkResults{});
  ASSERT_EQ(scene.objects.size(), 2u);  // the trunk and its branch
  // The path tracer's surfaces (scene/tree_surface.cpp): the image at the texcoords of (u, v).
  const auto parts = build_tree(tree, make_displacement(tree.displacement));
  TreeDesc wrong_tree = tree;
  wrong_tree.texture_displacement.midlevel += 0.01f;
  const auto wrong_parts = build_tree(wrong_tree, make_displacement(tree.displacement));
  const Deviation dev = compare_tree_parts(scene, CameraModel(desc.camera, 200, 200), parts, wrong_parts);
  RecordProperty("max_deviation_m", std::to_string(dev.worst));
  std::printf("  tree: %zu vertices, max deviation %.3g m (wrong midlevel %.3g m)\n", dev.vertices, dev.worst, dev.wrong);
  EXPECT_LT(dev.worst, kTolerance);
  EXPECT_GT(dev.wrong, 10 * kTolerance);
}

// Strip bark: the image's offset adds to the FractureField's depth, as the path tracer's
// per-part displacement adds them (renderer/scene_contents.cpp). This also compares the field's
// own lookup, which missed by up to the fracture depth left of the first texel centre (u = 0:
// GLSL's % of a negative column index) until fracture_field.glsl wrapped it as the C++ does.
TEST(TreeImageDisplacement, OnStripBarkTheImageAddsToTheFractureDepth) {
  PHELLEM_REQUIRE_GL();
  SceneDesc desc = parse_scene(R"({
    "camera": {"position": [0.0, 0.5, 0.5], "look_at": [0, 0.5, 0], "fov_deg": 35},
    "objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 1.0, 0]], "radius": [0.1, 0.08],
      "bark": {"model": "strips", "preset": "furrowed", "steps": 150, "growth_rate": 1.004, "strip_width": 0.006, "seed": 4,
               "depth": {"max_depth": 0.012, "depth_per_width": 1.2}}}]
  })", "strips.json", ".");
  TreeDesc& tree = desc.objects[0].tree;
  tree.texture_displacement = image(ramp_map(), 0.006f, 0.5f, 1.0f, false);
  desc.objects[0].displacement = tree.texture_displacement;
  const BarkResults bark = simulate_bark(desc, false);
  const PreviewScene scene = build_preview_scene(desc, bark);
  ASSERT_EQ(scene.objects.size(), 1u);
  ASSERT_EQ(scene.objects[0].bark, BarkKind::Field);
  ASSERT_TRUE(scene.objects[0].image);
  const auto& strips = bark.find(0)->strip_parts;
  ASSERT_EQ(strips.size(), 1u);
  // As scene_contents.cpp builds the parts it dices.
  auto parts_with = [&](const TreeDesc& t) {
    const DisplacementFn disp = make_displacement(t.displacement);
    return build_tree(t, [&](size_t k) -> DisplacementFn {
      std::shared_ptr<const bark::FieldBarkSurface> b = strips[k];
      return [b, disp](const Vec2f& uv, const Vec3f& p) {
        bark::SurfacePoint sp;
        sp.param = Eigen::Vector2d(uv.x(), uv.y() / b->length());
        sp.position = p;
        return disp(uv, p) + b->displace(sp).offset;
      };
    });
  };
  const auto parts = parts_with(tree);
  TreeDesc wrong_tree = tree;
  wrong_tree.texture_displacement.midlevel += 0.01f;
  const auto wrong_parts = parts_with(wrong_tree);
  const Deviation dev = compare_tree_parts(scene, CameraModel(desc.camera, 200, 200), parts, wrong_parts);
  RecordProperty("max_deviation_m", std::to_string(dev.worst));
  std::printf("  strip tree: %zu vertices, max deviation %.3g m (wrong midlevel %.3g m)\n", dev.vertices, dev.worst, dev.wrong);
  EXPECT_LT(dev.worst, kTolerance);
  EXPECT_GT(dev.wrong, 5 * kTolerance);
}

// Stress bark on a mesh: the image at the mesh's UVs adds to the cracks' V-profiles, as the
// path tracer's stress job adds its own displacement to them (renderer/scene_contents.cpp).
TEST(MeshImageDisplacement, OnStressBarkTheImageAddsToTheCracks) {
  PHELLEM_REQUIRE_GL();
  SceneDesc desc = parse_scene(R"({
    "camera": {"position": [0.0, 0.3, 0.3], "look_at": [0, 0.3, 0], "fov_deg": 30},
    "objects": [{"type": "mesh",
      "procedural": {"shape": "trunk", "triangles": 3000, "radius": 0.1, "height": 0.6},
      "bark": {"model": "stress", "preset": "woodification", "iterations": 40, "alpha": 0.8, "seed": 5,
               "crack": {"width_per_edge": 0.002, "max_width": 0.008, "max_depth": 0.01}}}]
  })", "trunk.json", ".");
  desc.objects[0].displacement = image(sine_map(), 0.004f, 0.5f, 2.0f, false);
  const BarkResults bark = simulate_bark(desc, false);
  const PreviewScene scene = build_preview_scene(desc, bark);
  ASSERT_EQ(scene.objects.size(), 1u);
  ASSERT_EQ(scene.objects[0].bark, BarkKind::Cracks);
  ASSERT_TRUE(scene.objects[0].image);
  PreviewRenderer renderer(scene);
  const auto fb = renderer.capture(0, CameraModel(desc.camera, 160, 160), fine());
  ASSERT_GT(fb.base.size(), 3000u);
  const auto& surface = *scene.objects[0].surface;
  const DisplacementFn own = make_displacement(desc.objects[0].displacement);
  DisplacementDesc other_mid = desc.objects[0].displacement;
  other_mid.midlevel += 0.01f;
  const DisplacementFn wrong = make_displacement(other_mid);
  Deviation dev;
  int in_cracks = 0;
  for (size_t k = 0; k < fb.base.size(); ++k) {
    const Vec3f n = fb.normal[k].normalized();
    bark::SurfacePoint p;
    p.position = fb.base[k];
    p.normal = n;
    const bark::BarkDisplacement d = surface.displace(p);
    in_cracks += d.attributes.y() > 0;
    const Vec2f t = fb.texcoord[k];
    dev.worst = std::max(dev.worst, double((fb.displaced[k] - (fb.base[k] + (own(t, fb.base[k]) + d.offset) * n)).norm()));
    dev.wrong = std::max(dev.wrong, double((fb.displaced[k] - (fb.base[k] + (wrong(t, fb.base[k]) + d.offset) * n)).norm()));
  }
  RecordProperty("max_deviation_m", std::to_string(dev.worst));
  std::printf("  stress mesh: %zu vertices (%d in cracks), max deviation %.3g m (wrong midlevel %.3g m)\n", fb.base.size(),
              in_cracks, dev.worst, dev.wrong);
  EXPECT_LT(dev.worst, kTolerance);
  EXPECT_GT(dev.wrong, 2 * kTolerance);
  EXPECT_GT(in_cracks, 100);
}
