// Throughput benchmark: the renderer's rays per second against raw Embree rtcIntersect1 on
// the same geometry with incoherent rays of the same kind (diffuse bounces from the camera's
// first hits), measured in the same run and reported as a ratio; thread scaling 1 -> N;
// BVH build time and bytes per triangle. Medians of `--repeat` runs.
//
//   phellem_bench_throughput [SCENE.json] [--spp N] [--res WxH] [--repeat R] [--json OUT]
#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>

#include "renderer/integrator.h"
#include "renderer/render_scene.h"
#include "renderer/sampling.h"
#include "scene/scene_parser.h"

using namespace phellem;
using Clock = std::chrono::steady_clock;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct RayBatch {
  std::vector<Vec3f> o, d;
};

// Diffuse-bounce rays: origins at first hits of camera rays, cosine-distributed directions.
RayBatch make_rays(const RenderScene& scene, const Camera& cam, int w, int h, size_t count) {
  RayBatch b;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0, 1);
  while (b.o.size() < count) {
    const Ray r = cam.generate(Vec2f(u(rng) * w, u(rng) * h), Vec2f(0.5f, 0.5f));
    SurfaceHit hit;
    if (!scene.intersect(r, 1e30f, &hit)) continue;
    Vec3f n = hit.ng.dot(r.d) > 0 ? Vec3f(-hit.ng) : hit.ng;
    const Vec3f d = Frame(n).to_world(sample_cosine_hemisphere(Vec2f(u(rng), u(rng))));
    b.o.push_back(offset_ray_origin(hit.p, n, d));
    b.d.push_back(d);
  }
  return b;
}

double raw_embree_mrays(RTCScene scene, const RayBatch& b, int threads) {
  tbb::task_arena arena(threads);
  std::atomic<long> hits{0};
  const auto t0 = Clock::now();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, b.o.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      long local = 0;
      for (size_t i = r.begin(); i < r.end(); ++i) {
        RTCRayHit rh = make_rayhit(b.o[i], b.d[i], 1e30f);
        rtcIntersect1(scene, &ctx, &rh);
        local += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      }
      hits += local;
    });
  });
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  return double(b.o.size()) / s * 1e-6;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_path, json_out;
  int spp = 16, repeat = 3, w = 0, h = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--spp" && i + 1 < argc)
      spp = std::atoi(argv[++i]);
    else if (a == "--repeat" && i + 1 < argc)
      repeat = std::atoi(argv[++i]);
    else if (a == "--json" && i + 1 < argc)
      json_out = argv[++i];
    else if (a == "--res" && i + 1 < argc)
      std::sscanf(argv[++i], "%dx%d", &w, &h);
    else
      scene_path = a;
  }
  const SceneDesc desc = scene_path.empty() ? default_scene() : load_scene_file(scene_path);
  if (!w) {
    w = desc.render.width;
    h = desc.render.height;
  }
  const int cores = int(std::thread::hardware_concurrency());
  std::vector<double> build_s;
  std::unique_ptr<RenderScene> scene;
  for (int r = 0; r < repeat; ++r) {
    scene.reset();
    scene = build_render_scene(desc, desc.camera, w, h);
    build_s.push_back(scene->stats().bvh_s);
  }
  const auto& st = scene->stats();
  const Camera cam(desc.camera, w, h);
  RenderSettings s;
  s.spp = spp;
  s.max_depth = desc.render.max_depth;
  s.seed = desc.render.seed;
  s.filter = desc.render.filter;

  auto render_mrays = [&](int threads) {
    s.threads = threads;
    const RenderResult res = render_image(*scene, cam, w, h, s);
    return std::make_pair(res.rays / res.seconds * 1e-6, res.rays);
  };
  const long long rays = render_mrays(cores).second;  // warm-up, and the ray count
  const RayBatch batch = make_rays(*scene, cam, w, h, size_t(std::min<long long>(rays, 4'000'000)));
  // Renderer and raw Embree alternate within each repetition, so that both see the same
  // machine load; the ratio is taken per repetition and its median reported.
  std::vector<double> ren_n, ren_1, raw_n, raw_1, ratio, ratio_1;
  for (int r = 0; r < repeat; ++r) {
    ren_n.push_back(render_mrays(cores).first);
    raw_n.push_back(raw_embree_mrays(scene->embree_scene(), batch, cores));
    ren_1.push_back(render_mrays(1).first);
    raw_1.push_back(raw_embree_mrays(scene->embree_scene(), batch, 1));
    ratio.push_back(ren_n.back() / raw_n.back());
    ratio_1.push_back(ren_1.back() / raw_1.back());
  }
  const double renderer_n = median(ren_n), renderer_1 = median(ren_1), raw = median(raw_n), raw1 = median(raw_1);
  const double bytes = double(st.geometry_bytes + st.embree_bytes);
  std::printf("scene                    %s\n", scene_path.empty() ? "<default scene>" : scene_path.c_str());
  std::printf("resolution, spp          %dx%d, %d spp, %d threads\n", w, h, spp, cores);
  std::printf("triangles                %lld (diced %lld)\n", st.triangles, st.diced_triangles);
  std::printf("BVH build (median)       %.3f s\n", median(build_s));
  std::printf("bytes per triangle       %.1f (geometry %.1f MB + Embree %.1f MB)\n", bytes / std::max(1LL, st.triangles),
              st.geometry_bytes / 1048576.0, st.embree_bytes / 1048576.0);
  std::printf("renderer                 %.2f Mrays/s (%d threads), %.2f Mrays/s (1 thread)\n", renderer_n, cores, renderer_1);
  std::printf("raw rtcIntersect1        %.2f Mrays/s (%d threads), %.2f Mrays/s (1 thread)\n", raw, cores, raw1);
  std::printf("renderer / raw Embree    %.2f (%d threads), %.2f (1 thread); medians of per-repetition ratios\n", median(ratio),
              cores, median(ratio_1));
  std::printf("thread scaling 1 -> %d   renderer %.2fx, raw Embree %.2fx\n", cores, renderer_n / renderer_1, raw / raw1);
  if (!json_out.empty()) {
    nlohmann::json j = {{"scene", scene_path},
                        {"triangles", st.triangles},
                        {"bvh_build_s", median(build_s)},
                        {"bytes_per_triangle", bytes / std::max(1LL, st.triangles)},
                        {"renderer_mrays", renderer_n},
                        {"renderer_mrays_1thread", renderer_1},
                        {"raw_embree_mrays", raw},
                        {"raw_embree_mrays_1thread", raw1},
                        {"ratio_renderer_over_raw", median(ratio)},
                        {"ratio_renderer_over_raw_1thread", median(ratio_1)},
                        {"thread_scaling", renderer_n / renderer_1},
                        {"threads", cores}};
    std::ofstream(json_out) << j.dump(2) << "\n";
  }
  return 0;
}
