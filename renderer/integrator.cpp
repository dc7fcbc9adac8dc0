#include "renderer/integrator.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <limits>

#include "renderer/pixel_filter.h"
#include "renderer/sampler.h"
#include "util/hash.h"
#include "util/progress.h"

namespace phellem {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kTile = 16;

struct FirstHit {
  bool hit = false;
  Color albedo = Color::Zero();
  Vec3f normal = Vec3f::Zero(), position = Vec3f::Zero();
  float depth = 0;
  int object_id = 0;
  float crack_mask = 0, crack_depth = 0;
  float displacement = 0;
};

// A reflection must leave on the side it arrived on, a transmission on the other, judged by
// the geometric normal: shading normals then never leak light through surfaces.
inline bool geometrically_consistent(const Vec3f& wo, const Vec3f& wi, const Vec3f& ng, float wo_z, float wi_z) {
  const bool shading_reflect = wo_z * wi_z > 0;
  const bool geometric_reflect = wo.dot(ng) * wi.dot(ng) > 0;
  return shading_reflect == geometric_reflect;
}

Color trace_path(const RenderScene& scene, Ray ray, Sampler& sampler, int max_depth, float pixel_angle, FirstHit* first,
                 long long* rays) {
  Color L = Color::Zero(), beta = Color::Ones();
  bool specular = true;
  float prev_pdf = 0;
  Vec3f prev_p = ray.o, prev_n = Vec3f::Zero();  // previous vertex and its receiving normal
  const auto& materials = scene.materials();
  const auto& textures = scene.textures();
  for (int depth = 0;; ++depth) {
    SurfaceHit hit;
    ++*rays;
    if (!scene.intersect(ray, kInf, &hit)) {
      for (const Light* l : scene.infinite_lights()) {
        float light_pdf = 0;
        const Color Le = l->Le_pdf(ray.d, prev_n, &light_pdf);
        if ((Le <= 0.0f).all()) continue;
        L += beta * Le * (specular ? 1.0f : power_heuristic(prev_pdf, light_pdf));
      }
      break;
    }
    const Material& mat = materials[hit.material];
    const Vec3f wo = -ray.d;
    // Texture filter width: the pixel's footprint at the hit (a ray cone, widened after
    // the first bounce where the lobe spreads the cone).
    const float cone = pixel_angle * (depth == 0 ? 1.0f : 8.0f);
    const ShadingInput in{hit.uv, hit.t * cone * hit.uv_per_metre, depth == 0, hit.bark ? &hit.bark_albedo : nullptr,
                          hit.albedo_scale, hit.bark_roughness, hit.texture_levels};
    if (depth == 0) {
      first->hit = true;
      first->position = hit.p;
      first->depth = hit.t;
      first->object_id = hit.object_id;
      first->crack_mask = hit.crack_mask;
      first->crack_depth = hit.crack_depth;
      first->displacement = hit.displacement;
    }
    if (mat.emissive()) {
      // Two-sided emitter.
      if (specular) {
        L += beta * mat.emission;
      } else if (scene.area_lights() && hit.area_light >= 0) {
        const float light_pdf = scene.area_lights()->pdf_hit(size_t(hit.area_light), prev_p, hit.p, ray.d);
        L += beta * mat.emission * power_heuristic(prev_pdf, light_pdf);
      }
      if (depth == 0) {
        first->albedo = Color::Zero();
        first->normal = hit.ns;
      }
      break;
    }
    if (depth >= max_depth) break;

    Vec3f ng = hit.ng, ns = apply_normal_map(mat, textures, in, hit.ns, hit.tangent);
    const bool transmissive = mat.type == MaterialType::Dielectric;
    if (!transmissive && wo.dot(ng) < 0) {
      ng = -ng;
      ns = -ns;
    }
    if (!transmissive && wo.dot(ns) <= 0) ns = ng;  // grazing shading normal facing away
    if (ns.dot(ng) < 0) ns = ng;
    const Frame frame(ns, hit.tangent.head<3>());
    Color albedo;
    const BSDF bsdf = evaluate_bsdf(mat, textures, in, &albedo);
    if (depth == 0) {
      first->albedo = albedo;
      first->normal = ns;
    }
    const Vec3f wo_l = frame.to_local(wo);
    if (wo_l.z() == 0) break;

    // Next-event estimation: one sample of every light (the scene has a handful of light
    // objects — each sun, sky and environment, plus all emissive triangles as one light that
    // picks a triangle by power), so no light-selection noise.
    // Light can arrive from ng's side only, unless the surface transmits.
    const Vec3f receiving_n = transmissive ? Vec3f::Zero() : ng;
    if (!bsdf.is_delta()) {
      const auto& lights = scene.lights();
      Vec4f ul = Vec4f::Zero();
      for (size_t li = 0; li < lights.size(); ++li) {
        // Two lights share one 4D point: dimensions 0–1, then 2–3.
        if (li % 2 == 0) ul = sampler.get4d();
        const Vec2f u = li % 2 == 0 ? Vec2f(ul[0], ul[1]) : Vec2f(ul[2], ul[3]);
        const Light* light = lights[li].get();
        const auto ls = light->sample_at(hit.p, receiving_n, u);
        if (!ls || !(ls->delta || ls->pdf > 0) || !(ls->L > 0.0f).any()) continue;
        const Vec3f wi_l = frame.to_local(ls->wi);
        if (!geometrically_consistent(wo, ls->wi, ng, wo_l.z(), wi_l.z())) continue;
        const Color f = bsdf.eval(wo_l, wi_l) * std::abs(wi_l.z());
        if (!(f > 0.0f).any()) continue;
        const Vec3f o = offset_ray_origin(hit.p, ng, ls->wi);
        const float tmax = std::isinf(ls->dist) ? kInf : ls->dist * (1.0f - 1e-3f);
        ++*rays;
        if (scene.occluded(o, ls->wi, tmax)) continue;
        if (ls->delta) {
          L += beta * f * ls->L;
        } else {
          const float w = power_heuristic(ls->pdf, bsdf.pdf(wo_l, wi_l));
          L += beta * f * ls->L * (w / ls->pdf);
        }
      }
    }

    // Continue the path by sampling the BSDF.
    const Vec4f ub = sampler.get4d();
    const auto bs = bsdf.sample(wo_l, ub[0], Vec2f(ub[1], ub[2]));
    if (!bs || !(bs->pdf > 0)) break;
    const Vec3f wi = frame.to_world(bs->wi).normalized();
    if (!geometrically_consistent(wo, wi, ng, wo_l.z(), bs->wi.z())) break;
    beta *= bs->f * (std::abs(bs->wi.z()) / bs->pdf);
    specular = bs->delta;
    prev_pdf = bs->pdf;
    prev_p = hit.p;
    prev_n = receiving_n;
    ray = Ray{offset_ray_origin(hit.p, ng, wi), wi};
    // Russian roulette after a few bounces (survival ∝ throughput).
    if (depth >= 3) {
      const float q = std::max(0.05f, 1.0f - beta.maxCoeff());
      if (ub[3] < q) break;
      beta /= 1.0f - q;
    }
    if (!(beta > 0.0f).any()) break;
  }
  return L;
}

}  // namespace

RenderSettings render_settings(const RenderDesc& r) {
  RenderSettings s;
  s.spp = r.spp;
  s.max_depth = r.max_depth;
  s.seed = r.seed;
  s.filter = r.filter;
  return s;
}

RenderResult render_image(const RenderScene& scene, const Camera& camera, int width, int height, const RenderSettings& s) {
  RenderResult result;
  result.film = Film(width, height);
  Film& film = result.film;
  const PixelFilter filter(s.filter);
  const int tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;
  std::atomic<long long> rays{0}, invalid{0};
  Progress progress(s.progress_label, (long long)tiles_x * tiles_y, s.progress);
  const auto start = std::chrono::steady_clock::now();

  const uint32_t seed = fold_seed(s.seed);
  auto render_tile = [&](int tile) {
    const int x0 = (tile % tiles_x) * kTile, y0 = (tile / tiles_x) * kTile;
    long long tile_rays = 0, tile_invalid = 0;
    for (int y = y0; y < std::min(y0 + kTile, height); ++y)
      for (int x = x0; x < std::min(x0 + kTile, width); ++x) {
        Color sum = Color::Zero(), albedo = Color::Zero();
        Vec3f normal = Vec3f::Zero(), position = Vec3f::Zero();
        float depth = 0, coverage = 0, crack_mask = 0, crack_depth = 0, displacement = 0;
        int object_id = 0;
        const uint32_t pixel_seed = Sampler::hash_pixel(uint32_t(x), uint32_t(y), seed);
        for (int i = 0; i < s.spp; ++i) {
          Sampler sampler(pixel_seed, uint32_t(i));
          const Vec4f cam = sampler.get4d();
          const Vec2f offset = filter.sample(Vec2f(cam[0], cam[1]));
          const Ray ray = camera.generate(Vec2f(x + 0.5f + offset.x(), y + 0.5f + offset.y()), Vec2f(cam[2], cam[3]));
          FirstHit first;
          const Color L = trace_path(scene, ray, sampler, s.max_depth, camera.pixel_angle(), &first, &tile_rays);
          if (L.allFinite())
            sum += L;
          else
            ++tile_invalid;
          if (first.hit) {
            coverage += 1;
            albedo += first.albedo;
            normal += first.normal;
            position += first.position;
            depth += first.depth;
            crack_mask += first.crack_mask;
            crack_depth += first.crack_depth;
            displacement += first.displacement;
          }
          if (i == 0) object_id = first.object_id;
        }
        const float inv = 1.0f / float(s.spp);
        const size_t p = size_t(y) * width + x;
        for (int c = 0; c < 3; ++c) {
          film.beauty[p * 4 + c] = sum[c] * inv;
          film.albedo[p * 3 + c] = albedo[c] * inv;
          film.position[p * 3 + c] = coverage > 0 ? position[c] / coverage : 0.0f;
        }
        film.beauty[p * 4 + 3] = coverage * inv;
        const Vec3f n = normal.squaredNorm() > 0 ? Vec3f(normal.normalized()) : Vec3f::Zero();
        for (int c = 0; c < 3; ++c) film.normal[p * 3 + c] = n[c];
        film.depth[p] = coverage > 0 ? depth / coverage : 0.0f;
        film.crack[p * 2] = crack_mask * inv;  // coverage-weighted like the albedo
        film.crack[p * 2 + 1] = coverage > 0 ? crack_depth / coverage : 0.0f;
        film.displacement[p] = coverage > 0 ? displacement / coverage : 0.0f;
        film.object_id[p] = float(object_id);
      }
    rays += tile_rays;
    invalid += tile_invalid;
    progress.advance();
  };

  tbb::task_arena arena(s.threads > 0 ? s.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tiles_x * tiles_y, 1),
        [&](const tbb::blocked_range<int>& r) {
          for (int t = r.begin(); t < r.end(); ++t) render_tile(t);
        },
        tbb::simple_partitioner());
  });
  progress.finish();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.rays = rays.load();
  result.invalid_samples = invalid.load();
  return result;
}

}  // namespace phellem
