// RenderScene: the immutable, compiled form of a SceneDesc that the integrator alone reads —
// a committed Embree scene (with instancing for mesh files), flat per-geometry records,
// runtime materials, textures and lights.
#pragma once

#include <embree3/rtcore.h>

#include <atomic>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bark/dressing/bark_surface.h"
#include "bark/geometry/mesh_data.h"
#include "renderer/camera.h"
#include "renderer/light.h"
#include "renderer/material.h"
#include "renderer/scene_contents.h"
#include "renderer/textures.h"
#include "scene/bark_results.h"
#include "scene/scene_desc.h"

namespace phellem {

struct EmbreeErrors;

struct SurfaceHit {
  float t = 0;
  Vec3f p, ng, ns;  // world position, geometric and shading normal (unit; same side)
  Vec2f uv{0, 0};
  Vec4f tangent{1, 0, 0, 1};
  float uv_per_metre = 1.0f;  // for texture footprints
  Vec2f texture_levels{0, 0};  // a grown surface's texture cell levels (MeshData::texture_levels)
  int material = 0;
  int object_id = 0;    // 1-based object index in the scene file
  int area_light = -1;  // triangle index in the area lights, or -1
  // The object's BarkSurface (either bark model) shaded here: fracture coverage, normalized
  // depth, and either a dressed albedo replacing the material's base colour (`bark`) or a
  // depth darkening of it (`albedo_scale`).
  float crack_mask = 0, crack_depth = 0;
  // Offset of the diced surface along its base normal (m), from MeshData::displacement; 0 on
  // geometry that was not displaced.
  float displacement = 0;
  bool bark = false;
  Color bark_albedo = Color::Zero();
  Color albedo_scale = Color::Ones();  // per channel: depth darkening × the bark's tint
  float bark_roughness = -1;  // the bark's own roughness here (< 0: the material's)
};

struct GeometryStats {
  long long triangles = 0;         // all triangles in the Embree scene (instances counted once per instance)
  long long unique_triangles = 0;  // stored triangles
  long long diced_triangles = 0;   // produced by adaptive tessellation
  size_t diced_bytes = 0;          // memory of the diced meshes
  size_t geometry_bytes = 0;       // vertex/index/attribute arrays
  size_t embree_bytes = 0;         // peak memory Embree allocated (BVH etc.)
  double tessellate_s = 0, bvh_s = 0;
  float dicing_scale = 1.0f;  // >1 when the triangle budget coarsened the dicing
};

struct DeviceDeleter {
  void operator()(RTCDevice d) const { rtcReleaseDevice(d); }
};
struct SceneDeleter {
  void operator()(RTCScene s) const { rtcReleaseScene(s); }
};
using DevicePtr = std::unique_ptr<RTCDeviceTy, DeviceDeleter>;
using ScenePtr = std::unique_ptr<RTCSceneTy, SceneDeleter>;

// An Embree ray/hit record for a ray from o along d up to tmax, nothing hit yet.
inline RTCRayHit make_rayhit(const Vec3f& o, const Vec3f& d, float tmax) {
  RTCRayHit rh;
  rh.ray.org_x = o.x();
  rh.ray.org_y = o.y();
  rh.ray.org_z = o.z();
  rh.ray.dir_x = d.x();
  rh.ray.dir_y = d.y();
  rh.ray.dir_z = d.z();
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = tmax;
  rh.ray.time = 0;
  rh.ray.mask = 0xFFFFFFFF;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// Built in stages like pbrt-v4's, each a function of its inputs: the scene's bark is simulated
// first (scene/bark_results.h), then load (renderer/scene_contents.h) -> tessellate
// (renderer/scene_dicing.h) -> BVH (here) -> lights (renderer/scene_lights.h).
class RenderScene {
  struct Key {
    explicit Key() = default;
  };

 public:
  explicit RenderScene(Key);  // through build() only
  // `dicing` is the camera used for screen-space tessellation (the render camera by default; a
  // turntable passes its first frame so geometry does not crawl). Every object with bark must
  // have its entry in `bark`.
  static std::unique_ptr<RenderScene> build(const SceneDesc& desc, const BarkResults& bark, const CameraDesc& dicing, int width,
                                            int height, bool progress = false);
  ~RenderScene();
  RenderScene(const RenderScene&) = delete;
  RenderScene& operator=(const RenderScene&) = delete;

  bool intersect(const Ray& ray, float tmax, SurfaceHit* hit) const;
  bool occluded(const Vec3f& o, const Vec3f& d, float tmax) const;

  const std::vector<Material>& materials() const { return materials_; }
  const TextureStore& textures() const { return *textures_; }
  const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }
  const std::vector<const Light*>& infinite_lights() const { return infinite_; }
  const AreaLights* area_lights() const { return area_; }
  const GeometryStats& stats() const { return stats_; }
  RTCScene embree_scene() const { return scene_.get(); }

 private:
  struct Shape;
  struct Prototype;
  struct Instance;
  // Stage 3: the Embree scene from the loaded pieces and the diced meshes, in that order;
  // returns the emissive triangles.
  std::vector<AreaLights::Triangle> build_bvh(const SceneContents& contents, std::vector<MeshData> diced);
  void add_mesh_to(RTCScene scene, std::vector<Shape>& shapes, std::shared_ptr<const MeshData> mesh, int material, int object_id,
                   int area_first, std::shared_ptr<const bark::BarkSurface> bark = nullptr);
  void fill_hit(const struct RTCRayHit& rh, const Ray& ray, SurfaceHit* hit) const;

  DevicePtr device_;
  ScenePtr scene_;
  std::unique_ptr<TextureStore> textures_;
  std::vector<Material> materials_;
  std::vector<Shape> shapes_;
  std::vector<Prototype> prototypes_;
  std::vector<Instance> instances_;
  std::vector<std::unique_ptr<Light>> lights_;
  std::vector<const Light*> infinite_;
  AreaLights* area_ = nullptr;
  GeometryStats stats_;
  std::shared_ptr<std::atomic<long long>> embree_bytes_now_, embree_bytes_peak_;
  std::shared_ptr<EmbreeErrors> embree_errors_;
};

// The render scene of `desc` with bark already simulated.
std::unique_ptr<RenderScene> build_render_scene(const SceneDesc& desc, const BarkResults& bark, const CameraDesc& dicing,
                                                int width, int height, bool progress = false);
// Simulates the scene's bark first (tests, benchmarks, one-off renders).
std::unique_ptr<RenderScene> build_render_scene(const SceneDesc& desc, const CameraDesc& dicing, int width, int height);

}  // namespace phellem
