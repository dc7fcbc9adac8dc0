#include "renderer/render_scene.h"

#include <OpenImageIO/imagebuf.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <map>
#include <mutex>

#include "scene/displacement.h"
#include "util/errors.h"
#include "io/mesh_io.h"
#include "bark/dressing/crack_profile.h"
#include "scene/mesh_source.h"
#include "util/progress.h"
#include "scene/stress_bark_run.h"
#include "scene/strip_bark_tree.h"
#include "bark/geometry/tessellation.h"
#include "scene/tree_surface.h"

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
  std::shared_ptr<const bark::BarkSurface> bark;  // strip bark of a tree part
  float crack_darkening = -1;  // ≥ 0: stress-bark cracks (mesh params hold normalized depth and mask)
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

std::shared_ptr<MeshData> padded(MeshData m) {
  // Embree reads vertex buffers with 16-byte loads: keep one spare element after the end.
  m.positions.reserve(m.positions.size() + 1);
  return std::make_shared<MeshData>(std::move(m));
}

MeshData plane_mesh(const ObjectDesc& o) {
  const Frame f(o.normal);
  MeshData m;
  const float hx = 0.5f * o.size.x(), hy = 0.5f * o.size.y();
  const Vec2f corners[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  for (const auto& c : corners) {
    m.positions.push_back(o.point + f.s * c.x() + f.t * c.y());
    m.normals.push_back(o.normal);
    m.uvs.push_back(c / o.uv_scale);
    m.tangents.emplace_back(f.s.x(), f.s.y(), f.s.z(), 1.0f);
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

MeshData sphere_mesh(const Vec3f& c, float r) {
  MeshData m;
  const int nu = 96, nv = 48;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const float th = kPi * j / nv, ph = kTwoPi * i / nu;
      const Vec3f n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
      m.positions.push_back(c + r * n);
      m.normals.push_back(n);
      m.uvs.emplace_back(float(i) / nu, 1.0f - float(j) / nv);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = j * (nu + 1) + i, b = a + 1, d = a + nu + 1, e = d + 1;
      m.indices.insert(m.indices.end(), {a, e, b, a, d, e});
    }
  return m;
}

std::vector<float> load_environment_image(const LightDesc& l, int* w, int* h) {
  OIIO::ImageBuf buf(l.file);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT))
    throw UserError(l.where.file, l.where.path + "/file", "cannot read environment map " + l.file + ": " + buf.geterror());
  const auto& spec = buf.spec();
  if (spec.width < 2 || spec.height < 1 || spec.nchannels < 1)
    throw UserError(l.where.file, l.where.path + "/file", "environment map has no pixels");
  *w = spec.width;
  *h = spec.height;
  std::vector<float> px(size_t(spec.width) * spec.height * spec.nchannels);
  buf.get_pixels(buf.roi(), OIIO::TypeDesc::FLOAT, px.data());
  std::vector<float> rgb(size_t(spec.width) * spec.height * 3);
  for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = px[i * spec.nchannels + std::min(c, spec.nchannels - 1)];
      rgb[i * 3 + c] = std::isfinite(v) ? std::max(0.0f, v) : 0.0f;
    }
  return rgb;
}

}  // namespace

RenderScene::~RenderScene() {
  // Embree scenes must go before the device; member order handles shapes/prototypes.
  scene_.reset();
  prototypes_.clear();
  device_.reset();
}

void RenderScene::add_mesh_to(RTCScene scene, std::vector<Shape>& shapes, std::shared_ptr<const MeshData> mesh, int material,
                              int object_id, int area_first, std::shared_ptr<const bark::BarkSurface> bark, float crack_darkening) {
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
  s.crack_darkening = crack_darkening;
  stats_.geometry_bytes += s.mesh->memory_bytes() + (s.bark ? s.bark->memory_bytes() : 0);
}

RenderScene::RenderScene(const SceneDesc& desc, const CameraDesc& dicing_cam, int width, int height, SceneBuildOptions* options)
    : textures_(std::make_unique<TextureStore>()) {
  SceneBuildOptions defaults;
  SceneBuildOptions& opts = options ? *options : defaults;
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

  // Materials: the scene's, then a default grey, then those of mesh files as they load.
  for (const auto& m : desc.materials) materials_.push_back(compile_material(m, *textures_));
  const int default_material = int(materials_.size());
  MaterialDesc grey;
  grey.name = "<default>";
  materials_.push_back(compile_material(grey, *textures_));

  std::vector<AreaLights::Triangle> area_tris;
  auto add_area = [&](const MeshData& m, int material) -> int {
    if (!materials_[material].emissive()) return -1;
    const int first = int(area_tris.size());
    for (size_t f = 0; f + 2 < m.indices.size(); f += 3)
      area_tris.push_back({m.positions[m.indices[f]], m.positions[m.indices[f + 1]], m.positions[m.indices[f + 2]],
                           materials_[material].emission});
    return first;
  };
  auto add_top = [&](MeshData m, int material, int object_id, std::shared_ptr<const bark::BarkSurface> bark = nullptr,
                     float crack_darkening = -1) {
    auto mesh = padded(std::move(m));
    const int area_first = add_area(*mesh, material);
    stats_.unique_triangles += mesh->triangle_count();
    stats_.triangles += mesh->triangle_count();
    add_mesh_to(scene_.get(), shapes_, mesh, material, object_id, area_first, std::move(bark), crack_darkening);
  };

  // Dicing set-up (screen space uses the dicing camera, fixed across turntable frames).
  const auto& tess = desc.render.tessellation;
  const CameraDesc& dc = tess.dicing_camera ? *tess.dicing_camera : dicing_cam;
  DicingParams dicing;
  dicing.screen_space = tess.mode == TessellationDesc::Mode::Screen;
  dicing.target = dicing.screen_space ? tess.pixels_per_edge : tess.edge_length;
  dicing.scale = tess.edge_length_scale;
  dicing.camera_position = dc.position;
  dicing.pixel_angle = 2.0f * std::tan(radians(dc.fov_deg) * 0.5f) / float(height);
  (void)width;

  // Collect displaced surfaces first so the triangle budget can be applied to all of them.
  struct DicedJob {
    const ObjectDesc* obj;
    int material;
    int object_id;
    ParametricSurface surface;
    std::shared_ptr<const MeshData> base;
    DisplacementFn disp;
    std::shared_ptr<const bark::BarkSurface> bark;
    // Stress-bark cracks: the V-profiles with per-vertex shading params (normalized depth,
    // mask), the crack-aware dicing predicate and the depth darkening.
    SurfaceDisplacementFn crack_disp = {};
    std::function<bool(const Vec3f&, const Vec3f&)> refine = {};
    float crack_darkening = -1;
  };
  std::vector<DicedJob> jobs;
  // Stress bark (mesh or tree): crack the object's mesh (unless given), then displace the
  // V-profiles of its cracks as real geometry, diced only where the cracks reach.
  auto add_stress_job = [&](const ObjectDesc& o, size_t oi, int mat, int object_id) {
    std::shared_ptr<const bark::CrackedMesh> cracked;
    if (auto it = opts.cracked.find(oi); it != opts.cracked.end()) {
      cracked = it->second;
    } else {
      const auto tb = Clock::now();
      cracked = run_stress_object(desc, oi, std::nullopt, opts.progress).cracked;
      opts.cracked[oi] = cracked;
      opts.bark_seconds += seconds_since(tb);
    }
    MeshData base = to_mesh_data(cracked->mesh);
    compute_vertex_normals(base, true);  // one normal per position: seams shade (and displace) alike
    auto profile = std::make_shared<const CrackProfile>(*cracked, o.stress_bark->look, uint32_t(o.stress_bark->params.seed));
    DicedJob j{&o, mat, object_id, {}, std::make_shared<MeshData>(std::move(base)), nullptr, nullptr};
    // A mesh's own procedural displacement adds to the cracks (a tree's is already in its mesh);
    // it reaches everywhere, so the dicing is then uniform.
    const bool extra = o.type == ObjectType::Mesh && o.displacement.type != DisplacementDesc::Type::None;
    const DisplacementFn own = extra ? make_displacement(o.displacement) : DisplacementFn{};
    j.crack_disp = [profile, own](const Vec2f& uv, const Vec3f& p, const Vec3f& n, Vec2f* params) {
      const CrackProfile::Sample s = profile->at(p, n);
      if (params) *params = Vec2f(s.relative, s.mask);
      return (own ? own(uv, p) : 0.0f) - s.depth;
    };
    if (tess.crack_aware && !extra) j.refine = [profile](const Vec3f& a, const Vec3f& b) { return profile->reaches(a, b); };
    j.crack_darkening = o.stress_bark->look.darkening;
    jobs.push_back(std::move(j));
  };
  std::map<std::string, int> prototype_of_file;
  std::map<std::string, std::pair<LoadedModel, int>> models;  // file -> (model, first material index)

  auto t0 = Clock::now();
  const double bark_before = opts.bark_seconds;
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& o = desc.objects[oi];
    const int object_id = int(oi) + 1;
    const int mat = o.material.empty() ? default_material : desc.find_material(o.material);
    switch (o.type) {
      case ObjectType::Sphere: {
        if (materials_[mat].emissive()) {
          add_top(sphere_mesh(o.center, o.radius), mat, object_id);
          break;
        }
        RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
        float* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
        v[0] = o.center.x();
        v[1] = o.center.y();
        v[2] = o.center.z();
        v[3] = o.radius;
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene_.get(), g);
        rtcReleaseGeometry(g);
        if (shapes_.size() <= id) shapes_.resize(id + 1);
        shapes_[id].sphere = true;
        shapes_[id].center = o.center;
        shapes_[id].radius = o.radius;
        shapes_[id].material = mat;
        shapes_[id].object_id = object_id;
        break;
      }
      case ObjectType::Plane:
        add_top(plane_mesh(o), mat, object_id);
        break;
      case ObjectType::Tree: {
        if (o.stress_bark) {
          add_stress_job(o, oi, mat, object_id);
          break;
        }
        const DisplacementFn disp = make_displacement(o.tree.displacement);
        if (!o.tree.strip_bark) {
          for (auto& part : build_tree(o.tree, disp)) jobs.push_back({&o, mat, object_id, part.surface, nullptr, nullptr, nullptr});
          break;
        }
        // Strip bark: the fracture depth displaces the surface inwards (true geometry) and the
        // dressed field shades it.
        auto it = opts.bark.find(oi);
        if (it == opts.bark.end()) {
          const auto tb = Clock::now();
          TreeStripSimulation sim(o, oi);
          sim.run(opts.progress);
          it = opts.bark.emplace(oi, sim.surfaces()).first;
          opts.bark_seconds += seconds_since(tb);
        }
        const auto& surfaces = it->second;
        auto parts = build_tree(o.tree, [&](size_t k) -> DisplacementFn {
          if (k >= surfaces.size()) return disp;
          std::shared_ptr<const bark::BarkSurface> b = surfaces[k];
          return [b, disp](const Vec2f& uv, const Vec3f& p) {
            return disp(uv, p) - b->depth(uv.x(), uv.y() / b->length());
          };
        });
        for (size_t k = 0; k < parts.size(); ++k) {
          parts[k].surface.keep_params = true;
          jobs.push_back({&o, mat, object_id, parts[k].surface, nullptr, nullptr, k < surfaces.size() ? surfaces[k] : nullptr});
        }
        break;
      }
      case ObjectType::Mesh: {
        if (o.stress_bark) {
          add_stress_job(o, oi, mat, object_id);
          break;
        }
        if (o.procedural) {
          MeshData w = to_mesh_data(object_trimesh(o));
          compute_vertex_normals(w);
          if (o.displacement.type != DisplacementDesc::Type::None)
            jobs.push_back({&o, mat, object_id, {}, std::make_shared<MeshData>(std::move(w)), make_displacement(o.displacement), nullptr});
          else
            add_top(std::move(w), mat, object_id);
          break;
        }
        auto it = models.find(o.file);
        if (it == models.end()) {
          LoadedModel model = load_mesh_file(o.file);
          const int first = int(materials_.size());
          for (const auto& md : model.materials) materials_.push_back(compile_material(md, *textures_));
          it = models.emplace(o.file, std::make_pair(std::move(model), first)).first;
        }
        const LoadedModel& model = it->second.first;
        const int first_mat = it->second.second;
        auto resolve = [&](const MeshData& m) {
          if (!o.material.empty()) return mat;
          return m.material >= 0 ? first_mat + m.material : default_material;
        };
        bool flatten = o.displacement.type != DisplacementDesc::Type::None;
        for (const auto& m : model.meshes) flatten = flatten || materials_[resolve(m)].emissive();
        if (flatten) {
          const Mat3f nrm = o.transform.matrix.topLeftCorner<3, 3>().inverse().transpose();
          for (const auto& m : model.meshes) {
            MeshData w = m;
            for (auto& p : w.positions) p = transform_point(o.transform.matrix, p);
            for (auto& n : w.normals) n = (nrm * n).normalized();
            for (auto& t : w.tangents) t.head<3>() = transform_vector(o.transform.matrix, t.head<3>()).normalized();
            if (w.normals.empty()) compute_vertex_normals(w);
            if (o.displacement.type != DisplacementDesc::Type::None) {
              jobs.push_back({&o, resolve(m), object_id, {}, std::make_shared<MeshData>(std::move(w)), make_displacement(o.displacement), nullptr});
            } else {
              add_top(std::move(w), resolve(m), object_id);
            }
          }
          break;
        }
        // Instanced: one prototype per file, shared by every object that uses it.
        auto pit = prototype_of_file.find(o.file);
        if (pit == prototype_of_file.end()) {
          Prototype proto;
          proto.scene.reset(rtcNewScene(device_.get()));
          for (const auto& m : model.meshes) {
            auto mesh = padded(m);
            stats_.unique_triangles += mesh->triangle_count();
            add_mesh_to(proto.scene.get(), proto.shapes, mesh, m.material >= 0 ? first_mat + m.material : default_material, 0, -1);
          }
          rtcCommitScene(proto.scene.get());
          prototypes_.push_back(std::move(proto));
          pit = prototype_of_file.emplace(o.file, int(prototypes_.size() - 1)).first;
        }
        Instance inst;
        inst.prototype = pit->second;
        inst.xf = o.transform.matrix;
        inst.normal_xf = o.transform.matrix.topLeftCorner<3, 3>().inverse().transpose();
        inst.material_override = o.material.empty() ? -1 : mat;
        inst.object_id = object_id;
        for (const auto& m : model.meshes) stats_.triangles += m.triangle_count();
        RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, prototypes_[inst.prototype].scene.get());
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, inst.xf.data());
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene_.get(), g);
        rtcReleaseGeometry(g);
        if (shapes_.size() <= id) shapes_.resize(id + 1);
        shapes_[id].instance = int(instances_.size());
        shapes_[id].object_id = object_id;
        instances_.push_back(inst);
        break;
      }
    }
  }

  // One bar over the dicing jobs and the BVH build (a job is one displaced surface).
  Progress bar("tessellate", (long long)jobs.size() + 1, opts.progress);
  // Adaptive tessellation under the triangle budget: coarsen uniformly until the estimate fits.
  if (!jobs.empty()) {
    for (int iter = 0; iter < 8; ++iter) {
      long long estimate = 0;
      for (const auto& j : jobs) {
        DicingParams dj = dicing;
        dj.refine_edge = j.refine;
        estimate += !j.base ? estimate_triangles(j.surface, dicing)
                    : j.crack_disp ? estimate_triangles(*j.base, j.crack_disp, dj)
                                   : estimate_triangles(*j.base, j.disp, dicing);
      }
      if (estimate <= tess.max_triangles) break;
      const float grow = std::sqrt(float(estimate) / float(tess.max_triangles)) * 1.05f;
      dicing.scale *= grow;
      stats_.dicing_scale *= grow;
    }
    for (const auto& j : jobs) {
      DicingParams dj = dicing;
      dj.refine_edge = j.refine;
      MeshData m = !j.base ? dice(j.surface, dicing) : j.crack_disp ? dice(*j.base, j.crack_disp, dj, true) : dice(*j.base, j.disp, dicing);
      stats_.diced_triangles += m.triangle_count();
      stats_.diced_bytes += m.memory_bytes();
      add_top(std::move(m), j.material, j.object_id, j.bark, j.crack_darkening);
      bar.advance();
    }
  }
  stats_.tessellate_s = seconds_since(t0) - (opts.bark_seconds - bark_before);  // bark simulation reported apart

  auto t1 = Clock::now();
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_MEDIUM);
  rtcCommitScene(scene_.get());
  stats_.bvh_s = seconds_since(t1);
  bar.advance();
  bar.finish();
  check_embree(*embree_errors_);
  stats_.embree_bytes = size_t(embree_bytes_peak_->load());

  // Lights.
  for (const LightDesc& l : desc.lights) {
    switch (l.type) {
      case LightType::EnvironmentUniform:
        lights_.push_back(std::make_unique<UniformEnvironment>(l.color * l.intensity));
        break;
      case LightType::EnvironmentMap: {
        int w, h;
        auto rgb = load_environment_image(l, &w, &h);
        lights_.push_back(std::make_unique<EnvironmentMap>(std::move(rgb), w, h, l.intensity, l.rotation_deg));
        break;
      }
      case LightType::Sun:
        lights_.push_back(std::make_unique<SunLight>(l.direction, l.irradiance, l.angle_deg, l.color));
        break;
      case LightType::Sky:
        lights_.push_back(make_preetham_sky(l.direction, l.turbidity, l.sky_intensity.value_or(1.0f), l.ground_albedo));
        break;
    }
  }
  if (!area_tris.empty()) {
    auto area = std::make_unique<AreaLights>(std::move(area_tris));
    area_ = area.get();
    lights_.push_back(std::move(area));
  }
  for (const auto& l : lights_)
    if (l->infinite()) infinite_.push_back(l.get());
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
  hit->bark = false;
  hit->albedo_scale = 1.0f;
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
  if (shape->bark && !m.params.empty()) {
    const Vec2f q = w * m.params[idx[0]] + u * m.params[idx[1]] + v * m.params[idx[2]];
    const bark::BarkSurface::Shade sh = shape->bark->shade(q.x(), q.y());
    hit->bark = true;
    hit->crack_mask = sh.mask;
    hit->crack_depth = sh.depth;
    hit->bark_albedo = Color(sh.albedo.x(), sh.albedo.y(), sh.albedo.z());
  }
  if (shape->crack_darkening >= 0 && !m.params.empty()) {
    const Vec2f q = w * m.params[idx[0]] + u * m.params[idx[1]] + v * m.params[idx[2]];
    hit->crack_depth = q.x();
    hit->crack_mask = q.y();
    hit->albedo_scale = 1.0f - shape->crack_darkening * q.x();
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
