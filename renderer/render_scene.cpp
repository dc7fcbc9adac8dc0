#include "renderer/render_scene.h"

#include <chrono>
#include <map>
#include <mutex>

#include "renderer/scene_dicing.h"
#include "renderer/scene_lights.h"
#include "util/progress.h"

namespace phellem {

// Embree reports errors through a C callback; exceptions must not cross it, so the first
// message is kept and thrown after the Embree call returns (check_embree).
struct EmbreeErrors {
  std::mutex mutex;
  std::string first;
};

struct RenderScene::Shape {
  bool sphere = false;
  int instance = -1;  // top-level instance geometry: index into instances_
  std::shared_ptr<const MeshData> mesh;
  Vec3f center{0, 0, 0};
  float radius = 0;
  int material = 0;
  int object_id = 0;
  int area_first = -1;
  std::shared_ptr<const bark::BarkSurface> bark;  // shaded from the mesh's per-vertex params
};
struct RenderScene::Prototype {
  ScenePtr scene;
  std::vector<Shape> shapes;
};
struct RenderScene::Instance {
  int prototype = 0;
  Mat4f xf;
  Mat3f normal_xf;
  int material_override = -1;
  int object_id = 0;
};

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void embree_error(void* user, RTCError code, const char* msg) {
  if (code == RTC_ERROR_NONE) return;
  auto* e = static_cast<EmbreeErrors*>(user);
  std::lock_guard<std::mutex> lock(e->mutex);
  if (e->first.empty()) e->first = "Embree error " + std::to_string(int(code)) + ": " + (msg ? msg : "");
}

void check_embree(EmbreeErrors& e) {
  std::lock_guard<std::mutex> lock(e.mutex);
  if (!e.first.empty()) throw std::runtime_error(e.first);
}

}  // namespace

RenderScene::~RenderScene() {
  // Embree scenes must go before the device; member order handles shapes/prototypes.
  scene_.reset();
  prototypes_.clear();
  device_.reset();
}

void RenderScene::add_mesh_to(RTCScene scene, std::vector<Shape>& shapes, std::shared_ptr<const MeshData> mesh, int material,
                              int object_id, int area_first, std::shared_ptr<const bark::BarkSurface> bark) {
  RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh->positions.data(), 0, sizeof(Vec3f),
                             mesh->positions.size());
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh->indices.data(), 0, 3 * sizeof(uint32_t),
                             mesh->triangle_count());
  rtcCommitGeometry(g);
  const unsigned id = rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  if (shapes.size() <= id) shapes.resize(id + 1);
  Shape& s = shapes[id];
  s.mesh = std::move(mesh);
  s.material = material;
  s.object_id = object_id;
  s.area_first = area_first;
  s.bark = std::move(bark);
  stats_.geometry_bytes += s.mesh->memory_bytes() + (s.bark ? s.bark->memory_bytes() : 0);
}

RenderScene::RenderScene(Key) : textures_(std::make_unique<TextureStore>()) {
  embree_errors_ = std::make_shared<EmbreeErrors>();
  embree_bytes_now_ = std::make_shared<std::atomic<long long>>(0);
  embree_bytes_peak_ = std::make_shared<std::atomic<long long>>(0);
  device_.reset(rtcNewDevice("threads=0"));
  if (!device_) throw std::runtime_error("cannot create Embree device");
  rtcSetDeviceErrorFunction(device_.get(), embree_error, embree_errors_.get());
  rtcSetDeviceMemoryMonitorFunction(
      device_.get(),
      [](void* ptr, ssize_t bytes, bool) -> bool {
        auto* self = static_cast<RenderScene*>(ptr);
        const long long now = (*self->embree_bytes_now_ += bytes);
        long long peak = self->embree_bytes_peak_->load();
        while (now > peak && !self->embree_bytes_peak_->compare_exchange_weak(peak, now)) {
        }
        return true;
      },
      this);
  scene_.reset(rtcNewScene(device_.get()));
}

std::unique_ptr<RenderScene> RenderScene::build(const SceneDesc& desc, const BarkResults& bark, const CameraDesc& dicing_cam,
                                                int width, int height, bool progress) {
  (void)width;
  auto s = std::make_unique<RenderScene>(Key{});
  const auto t0 = Clock::now();
  // Load.
  SceneContents contents = load_scene_contents(desc, bark, *s->textures_);
  s->materials_ = std::move(contents.materials);
  // Tessellate: one bar over the dicing jobs and the BVH build (a job is one displaced surface).
  Progress bar("tessellate", (long long)contents.jobs.size() + 1, progress);
  const auto& tess = desc.render.tessellation;
  DicedMeshes diced = dice_jobs(contents.jobs, dicing_params(tess, dicing_cam, height), tess.max_triangles, bar);
  s->stats_.dicing_scale = diced.dicing_scale;
  s->stats_.tessellate_s = seconds_since(t0);
  // BVH.
  std::vector<AreaLights::Triangle> area = s->build_bvh(contents, std::move(diced.meshes));
  bar.advance();
  bar.finish();
  check_embree(*s->embree_errors_);
  s->stats_.embree_bytes = size_t(s->embree_bytes_peak_->load());
  // Lights.
  const bool has_area = !area.empty();
  s->lights_ = make_lights(desc, std::move(area));
  if (has_area) s->area_ = static_cast<AreaLights*>(s->lights_.back().get());
  for (const auto& l : s->lights_)
    if (l->infinite()) s->infinite_.push_back(l.get());
  return s;
}

std::vector<AreaLights::Triangle> RenderScene::build_bvh(const SceneContents& c, std::vector<MeshData> diced) {
  std::vector<AreaLights::Triangle> area_tris;
  auto add_area = [&](const MeshData& m, int material) -> int {
    if (!materials_[material].emissive()) return -1;
    const int first = int(area_tris.size());
    for (size_t f = 0; f + 2 < m.indices.size(); f += 3)
      area_tris.push_back({m.positions[m.indices[f]], m.positions[m.indices[f + 1]], m.positions[m.indices[f + 2]],
                           materials_[material].emission});
    return first;
  };
  auto add_top = [&](std::shared_ptr<const MeshData> mesh, int material, int object_id,
                     std::shared_ptr<const bark::BarkSurface> bark) {
    const int area_first = add_area(*mesh, material);
    stats_.unique_triangles += mesh->triangle_count();
    stats_.triangles += mesh->triangle_count();
    add_mesh_to(scene_.get(), shapes_, std::move(mesh), material, object_id, area_first, std::move(bark));
  };
  // Instanced mesh files: one Embree scene each.
  for (const MeshPrototype& p : c.prototypes) {
    Prototype proto;
    proto.scene.reset(rtcNewScene(device_.get()));
    for (size_t k = 0; k < p.meshes.size(); ++k) {
      stats_.unique_triangles += p.meshes[k]->triangle_count();
      add_mesh_to(proto.scene.get(), proto.shapes, p.meshes[k], p.materials[k], 0, -1);
    }
    rtcCommitScene(proto.scene.get());
    prototypes_.push_back(std::move(proto));
  }
  for (const ScenePiece& piece : c.pieces) {
    switch (piece.kind) {
      case ScenePiece::Kind::Mesh:
        add_top(piece.mesh, piece.material, piece.object_id, piece.bark);
        break;
      case ScenePiece::Kind::Sphere: {
        RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
        float* v =
            static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
        v[0] = piece.center.x();
        v[1] = piece.center.y();
        v[2] = piece.center.z();
        v[3] = piece.radius;
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene_.get(), g);
        rtcReleaseGeometry(g);
        if (shapes_.size() <= id) shapes_.resize(id + 1);
        shapes_[id].sphere = true;
        shapes_[id].center = piece.center;
        shapes_[id].radius = piece.radius;
        shapes_[id].material = piece.material;
        shapes_[id].object_id = piece.object_id;
        break;
      }
      case ScenePiece::Kind::Instance: {
        Instance inst;
        inst.prototype = piece.prototype;
        inst.xf = piece.xf;
        inst.normal_xf = piece.xf.topLeftCorner<3, 3>().inverse().transpose();
        inst.material_override = piece.material_override;
        inst.object_id = piece.object_id;
        stats_.triangles += c.prototypes[size_t(piece.prototype)].triangles;
        RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, prototypes_[inst.prototype].scene.get());
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, inst.xf.data());
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene_.get(), g);
        rtcReleaseGeometry(g);
        if (shapes_.size() <= id) shapes_.resize(id + 1);
        shapes_[id].instance = int(instances_.size());
        shapes_[id].object_id = piece.object_id;
        instances_.push_back(inst);
        break;
      }
    }
  }
  // The diced surfaces after everything else.
  for (size_t k = 0; k < diced.size(); ++k) {
    MeshData& m = diced[k];
    stats_.diced_triangles += m.triangle_count();
    stats_.diced_bytes += m.memory_bytes();
    m.positions.reserve(m.positions.size() + 1);  // Embree's 16-byte loads: one spare element
    const DicingJob& j = c.jobs[k];
    add_top(std::make_shared<MeshData>(std::move(m)), j.material, j.object_id, j.bark);
  }
  const auto t1 = Clock::now();
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_MEDIUM);
  rtcCommitScene(scene_.get());
  stats_.bvh_s = seconds_since(t1);
  return area_tris;
}

std::unique_ptr<RenderScene> build_render_scene(const SceneDesc& desc, const BarkResults& bark, const CameraDesc& dicing,
                                                int width, int height, bool progress) {
  return RenderScene::build(desc, bark, dicing, width, height, progress);
}

std::unique_ptr<RenderScene> build_render_scene(const SceneDesc& desc, const CameraDesc& dicing, int width, int height) {
  return RenderScene::build(desc, simulate_bark(desc, false), dicing, width, height, false);
}

bool RenderScene::intersect(const Ray& ray, float tmax, SurfaceHit* hit) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh = make_rayhit(ray.o, ray.d, tmax);
  rtcIntersect1(scene_.get(), &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  fill_hit(rh, ray, hit);
  return true;
}

bool RenderScene::occluded(const Vec3f& o, const Vec3f& d, float tmax) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay r = make_rayhit(o, d, tmax).ray;
  rtcOccluded1(scene_.get(), &ctx, &r);
  return r.tfar < 0.0f;
}

void RenderScene::fill_hit(const RTCRayHit& rh, const Ray& ray, SurfaceHit* hit) const {
  const Shape* shape;
  const Instance* inst = nullptr;
  if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
    inst = &instances_[shapes_[rh.hit.instID[0]].instance];
    shape = &prototypes_[inst->prototype].shapes[rh.hit.geomID];
  } else {
    shape = &shapes_[rh.hit.geomID];
  }
  hit->t = rh.ray.tfar;
  hit->p = ray.o + ray.d * rh.ray.tfar;
  hit->material = inst && inst->material_override >= 0 ? inst->material_override : shape->material;
  hit->object_id = inst ? inst->object_id : shape->object_id;
  hit->area_light = -1;
  hit->crack_mask = hit->crack_depth = 0;
  hit->displacement = 0;
  hit->bark = false;
  hit->albedo_scale = Color::Ones();
  hit->bark_roughness = -1;
  hit->texture_levels = Vec2f(0, 0);
  if (shape->sphere) {
    const Vec3f n = (hit->p - shape->center).normalized();
    hit->ng = hit->ns = n;
    hit->uv = Vec2f(0.5f + std::atan2(n.z(), n.x()) / kTwoPi, 1.0f - std::acos(std::clamp(n.y(), -1.0f, 1.0f)) / kPi);
    const Vec3f t = Vec3f(-n.z(), 0, n.x());
    const float len = t.norm();
    hit->tangent = len > 0 ? Vec4f(t.x() / len, 0, t.z() / len, 1) : Vec4f(1, 0, 0, 1);
    hit->uv_per_metre = 1.0f / (kTwoPi * shape->radius);
    return;
  }
  const MeshData& m = *shape->mesh;
  const uint32_t* idx = &m.indices[3 * size_t(rh.hit.primID)];
  const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;
  const Vec3f& p0 = m.positions[idx[0]];
  const Vec3f& p1 = m.positions[idx[1]];
  const Vec3f& p2 = m.positions[idx[2]];
  Vec3f ng = (p1 - p0).cross(p2 - p0);
  const float area2 = ng.norm();
  ng = area2 > 0 ? Vec3f(ng / area2) : Vec3f(0, 1, 0);
  Vec3f ns = m.normals.empty() ? ng : Vec3f(w * m.normals[idx[0]] + u * m.normals[idx[1]] + v * m.normals[idx[2]]);
  if (!m.uvs.empty()) {
    const Vec2f &t0 = m.uvs[idx[0]], &t1 = m.uvs[idx[1]], &t2 = m.uvs[idx[2]];
    hit->uv = w * t0 + u * t1 + v * t2;
    const Vec2f a = t1 - t0, b = t2 - t0;
    const float uv_area2 = std::abs(a.x() * b.y() - a.y() * b.x());
    hit->uv_per_metre = area2 > 0 ? std::sqrt(uv_area2 / area2) : 1.0f;
  } else {
    hit->uv = Vec2f(u, v);
    hit->uv_per_metre = 1.0f;
  }
  if (!m.texture_levels.empty())
    hit->texture_levels = w * m.texture_levels[idx[0]] + u * m.texture_levels[idx[1]] + v * m.texture_levels[idx[2]];
  if (!m.displacement.empty())
    hit->displacement = w * m.displacement[idx[0]] + u * m.displacement[idx[1]] + v * m.displacement[idx[2]];
  if (shape->bark && !m.params.empty()) {
    const Vec4f q = w * m.params[idx[0]] + u * m.params[idx[1]] + v * m.params[idx[2]];
    const bark::BarkShade sh = shape->bark->shade(q, w * p0 + u * p1 + v * p2);
    hit->bark = sh.replaces_albedo;
    hit->crack_mask = sh.mask;
    hit->crack_depth = sh.depth;
    hit->bark_albedo = Color(sh.albedo.x(), sh.albedo.y(), sh.albedo.z());
    hit->albedo_scale = sh.albedo_scale * Color(sh.tint.x(), sh.tint.y(), sh.tint.z());
    hit->bark_roughness = sh.roughness;
  }
  if (!m.tangents.empty())
    hit->tangent = w * m.tangents[idx[0]] + u * m.tangents[idx[1]] + v * m.tangents[idx[2]];
  else
    hit->tangent = Vec4f(Frame(ng).s.x(), Frame(ng).s.y(), Frame(ng).s.z(), 1);
  if (inst) {
    ng = (inst->normal_xf * ng).normalized();
    ns = inst->normal_xf * ns;
    const Vec3f t = transform_vector(inst->xf, hit->tangent.head<3>());
    hit->tangent.head<3>() = t;
    const float s = std::cbrt(std::abs(inst->xf.topLeftCorner<3, 3>().determinant()));
    hit->uv_per_metre /= std::max(1e-12f, s);
  }
  ns = ns.squaredNorm() > 0 ? Vec3f(ns.normalized()) : ng;
  // Keep the geometric normal on the side of the authored shading normal.
  if (ng.dot(ns) < 0) ng = -ng;
  hit->ng = ng;
  hit->ns = ns;
  if (shape->area_first >= 0) hit->area_light = shape->area_first + int(rh.hit.primID);
}

}  // namespace phellem
