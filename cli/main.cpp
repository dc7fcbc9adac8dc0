// phellem: command-line entry point. Typed errors from every module are caught here once:
// UserError -> exit 2, anything else -> exit 1.
#include <sys/resource.h>

#include <OpenImageIO/imageio.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli/compare.h"
#include "cli/frame_sequence.h"
#include "cli/fit.h"
#include "cli/growth.h"
#include "cli/memory_check.h"
#include "cli/options.h"
#include "cli/outputs.h"
#include "cli/preview.h"
#include "cli/slice.h"
#include "cli/render_job.h"
#include "cli/simulate.h"
#include "io/image_output.h"
#include "renderer/integrator.h"
#include "renderer/render_scene.h"
#include "scene/scene_parser.h"
#include "util/errors.h"
#include "util/output_set.h"
#include "util/temp_files.h"
#include "util/thread_probe.h"

namespace phellem {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double peak_rss_mb() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return double(ru.ru_maxrss) / 1024.0;
}

int run_render(const cli::Options& o) {
  check_view(o);
  OutputSet out;
  expect_outputs(o, out);
  const auto t0 = Clock::now();
  Loaded l = load(o);
  expect_scene_inputs(l.desc, out);
  const double t_load = since(t0);
  const auto t1 = Clock::now();
  const BarkResults bark = simulate_bark(l.desc, !o.quiet);
  const auto scene = build_render_scene(l.desc, bark, l.desc.camera, l.width, l.height, !o.quiet);
  const double t_build = since(t1);
  const Camera camera(l.desc.camera, l.width, l.height);
  RenderResult res = render_image(*scene, camera, l.width, l.height, l.settings);
  const std::string exr = render_exr_path(o);
  if (!exr.empty()) out.write("-o", exr, [&](const std::string& tmp) { write_exr(res.film, tmp, exr_camera(camera)); });
  if (!o.png.empty())
    out.write("--png", o.png,
              [&](const std::string& tmp) { write_png(res.film, tmp, o.view.empty() ? default_view() : o.view); });
  const double total = since(t0);
  const auto& gs = scene->stats();
  if (!o.quiet)
    std::fprintf(stderr, "phellem: %dx%d, %d spp, %lld triangles (%lld diced), %.2f Mrays/s, %.1fs total\n", l.width, l.height,
                 l.settings.spp, gs.triangles, gs.diced_triangles, res.rays / res.seconds * 1e-6, total);
  if (res.invalid_samples > 0)
    std::fprintf(stderr, "phellem: warning: %lld samples had non-finite radiance and were discarded\n", res.invalid_samples);
  if (!o.stats.empty()) {
    nlohmann::json j;
    j["spp"] = l.settings.spp;
    j["resolution"] = {l.width, l.height};
    j["time_s"] = {
        {"total", total},  {"load", t_load},       {"build", t_build}, {"bark", bark.seconds}, {"tessellate", gs.tessellate_s},
        {"bvh", gs.bvh_s}, {"render", res.seconds}};
    j["rays"] = res.rays;
    j["mrays_per_s"] = res.rays / res.seconds * 1e-6;
    j["triangles"] = gs.triangles;
    j["unique_triangles"] = gs.unique_triangles;
    j["diced_triangles"] = gs.diced_triangles;
    j["diced_mb"] = gs.diced_bytes / 1048576.0;
    j["geometry_mb"] = gs.geometry_bytes / 1048576.0;
    j["embree_mb"] = gs.embree_bytes / 1048576.0;
    j["dicing_scale"] = gs.dicing_scale;
    j["peak_rss_mb"] = peak_rss_mb();
    j["threads"] = l.settings.threads > 0 ? l.settings.threads : int(std::thread::hardware_concurrency());
    j["invalid_samples"] = res.invalid_samples;
    write_json_output(out, "--stats", o.stats, j);
  }
  out.commit();
  return 0;
}

int run_turntable(const cli::Options& o) {
  check_view(o);
  check_frame_outputs(o);
  OutputSet out;
  expect_outputs(o, out);
  Loaded l = load(o);
  expect_scene_inputs(l.desc, out);
  // Geometry is diced once, for the first frame's camera, so it does not crawl.
  const BarkResults bark = simulate_bark(l.desc, !o.quiet);
  const auto scene = build_render_scene(l.desc, bark, l.desc.camera, l.width, l.height, !o.quiet);
  const int frames = *o.frames;
  const float degrees = o.degrees.value_or(360.0f);
  for (int f = 0; f < frames; ++f) {
    const Camera camera(Camera::orbit(l.desc.camera, degrees * float(f) / float(frames)), l.width, l.height);
    render_frame(o, l, *scene, camera, f, frames, out);
  }
  if (!o.mp4.empty()) encode_mp4(o, out);
  out.commit();
  return 0;
}

}  // namespace

}  // namespace phellem

int main(int argc, char** argv) {
  using namespace phellem;
  remove_temp_files_on_termination();
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
    std::cout << cli::usage();
    return 0;
  }
  if (!args.empty() && args[0] == "--version") {
    std::cout << "phellem 0.1.0\n";
    return 0;
  }
  std::string input = "<command line>";  // the file errors without a file of their own are reported at
  try {
    if (!args.empty() && args[0] == "compare") return run_compare(std::vector<std::string>(args.begin() + 1, args.end()));
    const cli::Options o = cli::parse(args);
    if (!o.scene.empty()) input = o.scene;
    if (o.threads) {
      require_startable_threads("--threads", *o.threads);
      static tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(*o.threads));
    }
    // OpenImageIO's own pool only decodes images: more threads than cores would not pay.
    OIIO::attribute("threads", o.threads ? std::min<int>(*o.threads, int(std::thread::hardware_concurrency())) : 0);
    if (o.memory_estimate) return run_memory_estimate(o);
    if (o.command == "simulate") return run_simulate(o);
    if (o.command == "growth") return run_growth(o);
    if (o.command == "fit") return run_fit(o);
    if (o.command == "preview") return run_preview(o);
    if (o.command == "slice") return run_slice(o);
    return o.command == "render" ? run_render(o) : run_turntable(o);
  } catch (const UserError& e) {
    std::cerr << "phellem: error: " << printable(e.what()) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // Memory is estimated per stage before work starts (cli/memory_check.h); this is a process
    // whose allowance (ulimit -v, a container) is below what the machine reports.
    std::cerr << "phellem: error: " << printable(input)
              << ": memory: ran out of memory; this process may use less than the run needs (see `ulimit -v`): "
                 "lower the sizes (--res, the scene's resolutions) or --threads, or check with --memory-estimate\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "phellem: internal error: " << printable(e.what()) << "\n";
    return 1;
  }
}
