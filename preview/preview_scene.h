// What the preview draws, built from a scene and its bark without OpenGL (so tests can look
// at it): per object, a base mesh whose triangles become tessellation patches, with the
// per-vertex crack nearness the control stage needs; the bark in GPU layout — a stress
// object's crack segments with a uniform grid over them, a strip tree part's FractureField
// as texels — and the lights reduced to a sun and a sky/ground ambient.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bark/dressing/crack_bark_surface.h"
#include "bark/dressing/crack_profile.h"
#include "bark/dressing/field_bark_surface.h"
#include "scene/bark_results.h"
#include "scene/displacement_map.h"
#include "scene/scene_desc.h"
#include "util/math.h"

namespace phellem::preview {

// A CrackProfile for the GPU (shaders/crack_profile.glsl): 12 floats a segment (a, wa, b, wb,
// chain, 0, 0, 0) and a dense grid of cells ≥ the reach, each listing every segment whose
// box ± the reach touches it (cell_start: #cells + 1 offsets into items).
struct GpuCracks {
  std::vector<float> segments;
  std::vector<Vec3f> ridge_tints, fissure_tints;  // sorted by luminance (bark/dressing/bark_tints.h), at most 64
  uint32_t tint_seed = 0;
  std::vector<uint32_t> cell_start, items;
  Vec3f origin{0, 0, 0};
  float cell = 1;
  Eigen::Vector3i dims{1, 1, 1};
  uint32_t seed = 0;
  CrackLook look;
};
GpuCracks gpu_cracks(const CrackProfile& profile, size_t max_cells = size_t(1) << 21);
// The same with the surface's tints (the palettes it shades with).
GpuCracks gpu_cracks(const bark::CrackBarkSurface& surface, size_t max_cells = size_t(1) << 21);

struct GpuField {
  int width = 0, height = 0;
  std::vector<float> depth_mask, albedo;  // 2 and 4 floats a texel, rows from v = 0
  float max_depth = 1;
};

enum class BarkKind { None = 0, Cracks = 1, Field = 2 };

// An image displacement (`"displacement": {"type": "image"}`, scene/displacement_map.h) for the
// evaluation stage (shaders/displacement_map.glsl): the map as an R32F texture (rows as the
// map stores them, row 0 at the top), looked up at the interpolated texcoords; its offset adds
// to the bark's (cracks or a fracture field).
struct GpuImageDisplacement {
  std::shared_ptr<const DisplacementMap> map;
  float scale = 0.01f, midlevel = 0.5f, uv_repeat = 1.0f;
  bool clamp = false;
  // The most the offset can move a point either way (m): |scale| × the map's largest |value − midlevel|.
  float reach() const;
};
GpuImageDisplacement gpu_image_displacement(const DisplacementDesc& d);

struct PreviewObject {
  std::string name;
  int object_id = 0;  // 1-based, as the path tracer's object_id AOV
  std::vector<Vec3f> positions, normals;  // object space
  std::vector<Vec2f> params;              // strip bark: the part's (u, v); else 0
  std::vector<float> crack_near;          // 1 where a crack (or an image displacement) can reach an edge at this vertex
  std::vector<Vec2f> texcoords;           // where an image displacement is looked up (0 without one)
  std::vector<uint32_t> indices;          // triangles: the patches
  Mat4f model = Mat4f::Identity();
  Vec3f base_color{0.8f, 0.8f, 0.8f};
  BarkKind bark = BarkKind::None;
  bool curved = false;  // a smooth surface sampled at the grid's vertices: curved (PN) patches
  std::shared_ptr<const GpuCracks> cracks;
  std::shared_ptr<const GpuField> field;
  std::shared_ptr<const GpuImageDisplacement> image;  // added to the bark's offset, if any
  std::shared_ptr<const bark::BarkSurface> surface;  // the C++ surface the GPU mirrors
  size_t triangles() const { return indices.size() / 3; }
};

// An environment map as the background (scene/environment_image.h's pixels, rows top-down).
struct PreviewEnvironment {
  int width = 0, height = 0;
  std::vector<float> rgb;
  float intensity = 1, rotation_deg = 0;
};

struct PreviewScene {
  std::vector<PreviewObject> objects;
  Vec3f sun_direction{0.5f, 0.8f, 0.3f};  // towards the sun
  // Radiance a white Lambertian surface facing the sun gets per unit albedo, and the ambient
  // term for normals straight up (sky) and down (ground), blended by the normal's height.
  Vec3f sun_color{0.95f, 0.95f, 0.95f}, sky_color{0.35f, 0.42f, 0.55f}, ground_color{0.12f, 0.11f, 0.1f};
  std::shared_ptr<const PreviewEnvironment> environment;  // or a flat sky colour behind
  size_t triangles() const;
};

// Irradiance on a surface facing straight up and one facing straight down under an
// environment (intensity included): the ambient term is these over π.
std::pair<Vec3f, Vec3f> hemisphere_irradiance(const PreviewEnvironment& environment);

// The patches near cracks are pre-subdivided on the CPU to edges of at most this many times
// the cracks' minimum half-width, so that the hardware's 64 levels resolve a V at any zoom.
constexpr float kPresubdivideHalfWidths = 32;

// A stress-bark object: the cracked mesh as the path tracer takes it (one normal per
// position), pre-subdivided near the cracks, every vertex of an edge a crack reaches marked.
PreviewObject stress_preview_object(const bark::CrackedMesh& cracked, std::shared_ptr<const bark::CrackBarkSurface> surface);

// Every tree with strip bark and every stress-bark object must have its entry in `bark`.
// Image displacements are drawn where the path tracer dices them: on patches, on meshes at
// their UVs (stress bark's cracks included; a mesh without UVs is a UserError, as there), on
// tree parts at the tree's texcoords (strip bark's fracture depth included). A stress or grown
// tree's image displacement is already in its mesh. Procedural displacements of meshes and
// patches are not drawn (only a tree's, at the grid's vertices).
PreviewScene build_preview_scene(const SceneDesc& desc, const BarkResults& bark);

}  // namespace phellem::preview
