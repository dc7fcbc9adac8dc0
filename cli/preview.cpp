#include "cli/preview.h"

#include <OpenImageIO/imageio.h>

#include <chrono>
#include <cstdio>

#include "cli/outputs.h"
#include "cli/render_job.h"
#include "io/image_file.h"
#include "preview/gl_context.h"
#include "preview/preview_renderer.h"
#include "preview/preview_scene.h"
#include "preview/preview_window.h"
#include "preview/view_file.h"

#include "scene/bark_results.h"
#include "util/errors.h"
#include "util/output_set.h"

namespace phellem {

namespace {

constexpr float kSnapshotEdgePx = 2.0f;


void write_image(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type, const void* data,
                 const std::vector<std::string>& names = {}) {
  OIIO::ImageSpec spec(w, h, channels, type);
  if (!names.empty()) spec.channelnames = names;
  if (type == OIIO::TypeDesc::FLOAT) spec.attribute("compression", "zip");
  spec.attribute("Software", "Phellem preview");
  write_image_file(path, path, spec, type, data);
}

}  // namespace

int run_preview(const cli::Options& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (o.png.empty()) {
    Loaded l = load(o);
    const BarkResults bark = simulate_bark(l.desc, !o.quiet);
    preview::WindowOptions w;
    w.start = t0;
    w.width = l.width;
    w.height = l.height;
    w.frames = o.frames.value_or(0);
    if (o.edge_px) w.edge_px = float(*o.edge_px);
    w.max_level = o.max_level.value_or(64);
    w.save_camera = [&](const CameraDesc& c) {
      try {
        return preview::write_view_scene(o.scene, c);
      } catch (const std::exception& e) {
        return std::string("nothing (") + e.what() + ")";
      }
    };
    const preview::WindowStats st = preview::run_window(preview::build_preview_scene(l.desc, bark), l.desc.camera, w);
    if (!o.quiet)
      std::fprintf(stderr, "phellem: preview: %d frames, median %.1f ms a frame, %lld triangles in the last, first frame %.0f ms after the start\n",
                   st.frames, st.median_ms, st.triangles, st.first_frame_ms);
    return 0;
  }
  OutputSet out;
  out.expect_file("--snapshot", o.png);
  if (!o.exr.empty()) out.expect_file("-o", o.exr);
  if (!o.scene.empty()) out.expect_input("SCENE", o.scene);
  Loaded l = load(o);
  expect_scene_inputs(l.desc, out);
  const BarkResults bark = simulate_bark(l.desc, !o.quiet);
  std::string why;
  auto gl = preview::HeadlessGl::create(&why);
  if (!gl) throw std::runtime_error("no OpenGL 4.5 context for the preview: " + why);
  const int max_size = gl->max_framebuffer_size();
  if (l.width > max_size || l.height > max_size)
    throw UserError("", o.width ? "--res" : "render.resolution",
                    "the preview's OpenGL (" + gl->renderer() + ") draws at most " + std::to_string(max_size) + "×" +
                        std::to_string(max_size) + " pixels; asked for " + std::to_string(l.width) + "×" +
                        std::to_string(l.height));
  const preview::PreviewScene scene = preview::build_preview_scene(l.desc, bark);
  preview::PreviewRenderer renderer(scene);
  preview::PreviewSettings settings;
  settings.max_level = std::min(o.max_level.value_or(settings.max_level), gl->max_tessellation_level());
  // A snapshot is one frame: finer micro-edges than the interactive default.
  const float edge = o.edge_px ? float(*o.edge_px) : kSnapshotEdgePx;
  settings.target_far_px *= edge / settings.target_near_px;
  settings.target_near_px = edge;
  const CameraModel camera(l.desc.camera, l.width, l.height);
  const preview::PreviewFrame f = renderer.render(camera, settings);
  out.write("--snapshot", o.png, [&](const std::string& tmp) {
    std::vector<uint8_t> rgb(size_t(f.width) * size_t(f.height) * 3);
    for (size_t p = 0; p < rgb.size() / 3; ++p)
      for (int c = 0; c < 3; ++c) rgb[3 * p + size_t(c)] = f.rgba[4 * p + size_t(c)];
    write_image(tmp, f.width, f.height, 3, OIIO::TypeDesc::UINT8, rgb.data());
  });
  if (!o.exr.empty())
    out.write("-o", o.exr, [&](const std::string& tmp) {
      std::vector<float> px(size_t(f.width) * size_t(f.height) * 3);
      for (size_t p = 0; p < px.size() / 3; ++p) {
        px[3 * p] = f.mask[p];
        px[3 * p + 1] = f.crack_depth[p];
        px[3 * p + 2] = f.distance[p];
      }
      write_image(tmp, f.width, f.height, 3, OIIO::TypeDesc::FLOAT, px.data(), {"crack.mask", "crack.depth", "depth.Z"});
    });
  out.commit();
  if (!o.quiet)
    std::fprintf(stderr, "phellem: preview %dx%d on %s: %lld triangles (%zu patches), %.1f ms a frame, %.1fs total\n", f.width,
                 f.height, gl->renderer().c_str(), f.primitives, scene.triangles(), f.milliseconds,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return 0;
}

}  // namespace phellem
