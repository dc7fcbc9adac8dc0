// Stage 1 of building a RenderScene (load): the scene's objects turned into what the later
// stages consume — compiled materials, top-level geometry in scene order, one prototype per
// instanced mesh file, and the displaced surfaces still to be diced. Bark comes in finished
// (scene/bark_results.h): this stage only wraps it as BarkSurfaces.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bark/dressing/bark_surface.h"
#include "bark/geometry/mesh_data.h"
#include "bark/geometry/tessellation.h"
#include "renderer/material.h"
#include "renderer/textures.h"
#include "scene/bark_results.h"
#include "scene/scene_desc.h"

namespace phellem {

// One top-level geometry, attached to the BVH in this order.
struct ScenePiece {
  enum class Kind { Mesh, Sphere, Instance } kind = Kind::Mesh;
  std::shared_ptr<const MeshData> mesh;  // Mesh (padded for Embree's 16-byte loads)
  Vec3f center{0, 0, 0};                 // Sphere
  float radius = 0;
  int prototype = -1;  // Instance: index into SceneContents::prototypes
  Mat4f xf = Mat4f::Identity();
  int material_override = -1;  // Instance: the object's material, or -1 (the file's)
  int material = 0;
  int object_id = 0;                              // 1-based object index in the scene file
  std::shared_ptr<const bark::BarkSurface> bark;  // shades through MeshData::params
};

// A mesh file placed by instancing: its meshes once, with resolved materials.
struct MeshPrototype {
  std::vector<std::shared_ptr<const MeshData>> meshes;
  std::vector<int> materials;
  long long triangles = 0;
};

// A surface to dice: a parametric surface (trees) or a base mesh with a displacement.
struct DicingJob {
  int material = 0;
  int object_id = 0;
  ParametricSurface surface;  // when `base` is null
  std::shared_ptr<const MeshData> base;
  DisplacementFn disp;  // base mesh: procedural displacement
  // Base mesh with bark (stress bark's cracks): displacement that also writes the per-vertex
  // shading attributes, and the crack-aware dicing predicate.
  SurfaceDisplacementFn bark_disp = {};
  std::function<bool(const Vec3f&, const Vec3f&)> refine = {};
  std::shared_ptr<const bark::BarkSurface> bark;
};

struct SceneContents {
  std::vector<Material> materials;  // the scene's, a default grey, then each mesh file's
  std::vector<ScenePiece> pieces;
  std::vector<MeshPrototype> prototypes;
  std::vector<DicingJob> jobs;  // diced meshes are attached after `pieces`, in this order
};

// Every tree with strip bark and every stress-bark object must have its entry in `bark`.
SceneContents load_scene_contents(const SceneDesc& desc, const BarkResults& bark, TextureStore& textures);

}  // namespace phellem
