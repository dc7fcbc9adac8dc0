// SceneDesc: the parsed, validated, immutable description of a scene file. Every entity
// remembers where it came from (file + JSON path) so later stages can report errors there.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/material_desc.h"
#include "scene/growth_desc.h"
#include "scene/stress_bark_desc.h"
#include "scene/strip_bark_desc.h"
#include "util/errors.h"
#include "util/math.h"

namespace phellem {

struct CameraDesc {
  Vec3f position{0, 1.5f, 5};
  Vec3f look_at{0, 1, 0};
  Vec3f up{0, 1, 0};
  float fov_deg = 40.0f;
  float aperture_radius = 0.0f;
  float focus_distance = 0.0f;  // 0: distance from position to look_at
};

enum class FilterType { BlackmanHarris, Gaussian, Box };
struct FilterDesc {
  FilterType type = FilterType::BlackmanHarris;
  float radius = 1.5f;  // pixels
};

// Dicing of displaced / parametric surfaces (see bark/geometry/tessellation.h).
struct TessellationDesc {
  enum class Mode { Screen, Object } mode = Mode::Screen;
  float pixels_per_edge = 1.0f;             // screen mode: target micro-triangle edge in pixels
  float edge_length = 0.01f;                // object mode: target edge length in metres
  float edge_length_scale = 1.0f;           // memory knob: multiplies the target edge
  long long max_triangles = 20'000'000;     // memory knob: budget for all diced surfaces
  std::optional<CameraDesc> dicing_camera;  // default: the render camera
  bool crack_aware = true;                  // stress-bark cracks: refine only the surface the cracks reach
};

struct RenderDesc {
  int width = 960, height = 540;
  int spp = 64;
  int max_depth = 8;
  uint64_t seed = 0;  // [0, 2^64 - 1]
  FilterDesc filter;
  TessellationDesc tessellation;
};

enum class LightType { EnvironmentUniform, EnvironmentMap, Sun, Sky };
struct LightDesc {
  LightType type = LightType::EnvironmentUniform;
  Location where;
  Color color{1, 1, 1};
  std::string file;  // environment map (resolved path)
  float intensity = 1.0f;
  float rotation_deg = 0.0f;
  float clamp = 0.0f;        // environment map: luminance clamped to this (0 = off), e.g. a sun disk given as a `sun`
  Vec3f direction{0, 1, 0};  // sun / sky: towards the sun (normalized)
  bool has_direction = false;
  float irradiance = 1.0f;             // sun: irradiance on a surface facing it
  float angle_deg = 0.53f;             // sun: angular diameter
  float turbidity = 3.0f;              // sky
  std::optional<float> sky_intensity;  // sky: explicit scale (default: the sun's irradiance)
  float ground_albedo = 0.3f;          // sky: lower hemisphere
};

struct DisplacementMap;  // scene/displacement_map.h

// Displacement along the normal, evaluated while dicing: procedural, or a height map image
// (scene/displacement_map.h) looked up at the surface's texture coordinates.
struct DisplacementDesc {
  enum class Type { None, Grooves, Noise, Image } type = Type::None;
  float amplitude = 0.0f;   // metres; grooves cut inwards by up to this depth
  float frequency = 12.0f;  // grooves around the circumference / noise cycles per metre
  float sharpness = 3.0f;   // grooves: ridge sharpness
  float waviness = 0.3f;    // grooves: lateral wander of the furrows
  uint64_t seed = 1;        // folded to the noise's 32 bits (fold_seed)
  // image: offset = scale × (value − midlevel) metres, value the map's code value / largest
  // code (integer images) or its float value (EXR), at texcoord × uv_repeat.
  std::string file;  // resolved path
  float scale = 0.01f;
  float midlevel = 0.5f;
  float uv_repeat = 1.0f;
  bool clamp = false;  // "wrap": "clamp" (edges extend) or "repeat" (the default: the map tiles)
  std::shared_ptr<const DisplacementMap> map;  // read by the scene parser
};

struct TransformDesc {
  Mat4f matrix = Mat4f::Identity();
};

struct BranchDesc {
  float attach = 0.5f;       // fraction of the parent's axis length
  float azimuth_deg = 0.0f;  // around the parent's axis
  float angle_deg = 45.0f;   // between parent axis and branch
  float length = 1.0f;
  std::vector<float> radius;  // radius profile, equally spaced along the branch
  float curvature = 0.0f;     // upward bend (fraction of length)
  std::vector<BranchDesc> branches;
  Location where;
};

struct TreeDesc {
  std::vector<Vec3f> axis;                          // spline control points (Catmull-Rom through them)
  std::shared_ptr<const StripBarkDesc> strip_bark;  // `"bark": {"model": "strips"}`, if any
  std::vector<float> radius;                        // radius profile, equally spaced in arc length
  std::vector<BranchDesc> branches;
  DisplacementDesc displacement;          // procedural, at (θ / 2π, arc length in metres)
  DisplacementDesc texture_displacement;  // an image's, at the texture coordinates (as the albedo)
  float uv_repeat = 1.0f;                 // texture repeats around the circumference
};

// A mesh made by Phellem instead of read from a file (bark/geometry/procedural_meshes.h):
// `"procedural": {"shape": "trunk" | "log" | "torus_knot" | "vase" | "sheet" | "sphere" |
// "branch_junction", ...}` (a log is a trunk closed by flat end caps, a closed surface that can
// grow; a branch junction is a log with a branch, bark/geometry/branch_junction.h).
struct ProceduralMeshDesc {
  std::string shape;
  int triangles = 8000;  // approximate
  float radius = 0.15f;  // trunk, log, vase (base), torus knot (overall), sphere, branch junction's trunk
  float height = 1.0f;   // trunk, log, vase, sheet (and its width), branch junction's trunk
  float tube = 0.06f;    // torus knot
  float jitter = 0.3f;   // trunk, vase, sheet, branch junction: vertex jitter (fraction of the spacing)
  uint64_t seed = 1;     // of the jitter
  // branch junction: 0 for the branch's radius and length means 0.6 × and 4 × radius
  float branch_radius = 0, branch_length = 0;
  float branch_angle_deg = 50;  // from the trunk's axis
  float branch_height = 0.45f;  // where the branch's axis leaves the trunk's (fraction of height)
};

// A patch (`"type": "patch"`) is a flat rectangle of bark at a known physical size, diced and
// displaced like a mesh: texture coordinates run from (0, 0) at its bottom-left corner to
// (1, 1) at its top-right, so a scan's height map and albedo cover it once.
enum class ObjectType { Sphere, Plane, Mesh, Tree, Patch };
struct ObjectDesc {
  ObjectType type = ObjectType::Sphere;
  Location where;
  std::string name;
  std::string material;  // name in SceneDesc::materials; empty: mesh's own or default
  // sphere
  Vec3f center{0, 0, 0};
  float radius = 1.0f;
  // plane
  Vec3f point{0, 0, 0};
  Vec3f normal{0, 1, 0};
  Vec2f size{10, 10};     // plane, patch (metres: width along `right`, height along `up`)
  float uv_scale = 1.0f;  // plane: metres per texture repeat
  Vec3f up{0, 1, 0};      // patch: its v direction (made orthogonal to the normal)
  // mesh
  std::string file;  // empty for a procedural mesh
  std::optional<ProceduralMeshDesc> procedural;
  // mesh or tree: `"bark": {"model": "stress", ...}` (the stress-field cracking model; a tree
  // is tessellated into one triangle mesh of its trunk and branches first)
  std::shared_ptr<const StressBarkDesc> stress_bark;
  // mesh: `"growth": {...}` (cambial growth before the bark is cracked and rendered)
  std::shared_ptr<const GrowthDesc> growth;
  TransformDesc transform;
  DisplacementDesc displacement;
  // tree
  TreeDesc tree;
};

struct SceneDesc {
  std::string file;  // "<default scene>" for the embedded one
  std::filesystem::path base_dir;
  // The files the scene names as meshes, environment maps and textures, resolved (outputs must
  // not replace them: OutputSet::expect_input).
  std::vector<std::string> files;
  CameraDesc camera;
  RenderDesc render;
  std::vector<LightDesc> lights;
  std::vector<MaterialDesc> materials;
  std::vector<ObjectDesc> objects;

  int find_material(const std::string& name) const {
    for (size_t i = 0; i < materials.size(); ++i)
      if (materials[i].name == name) return static_cast<int>(i);
    return -1;
  }
};

}  // namespace phellem
