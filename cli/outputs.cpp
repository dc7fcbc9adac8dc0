#include "cli/outputs.h"

#include "cli/frame_sequence.h"

namespace phellem {

std::string render_exr_path(const cli::Options& o) { return o.exr.empty() && o.png.empty() ? std::string("render.exr") : o.exr; }

std::string png_frames_option(const cli::Options& o) { return o.png_frames ? "--png" : "--mp4"; }

void expect_outputs(const cli::Options& o, OutputSet& out) {
  if (!o.scene.empty()) out.expect_input("SCENE", o.scene);
  if (o.command == "render") {
    if (const std::string exr = render_exr_path(o); !exr.empty()) out.expect_file("-o", exr);
    if (!o.png.empty()) out.expect_file("--png", o.png);
    if (!o.stats.empty()) out.expect_file("--stats", o.stats);
  } else if (o.command == "slice") {
    out.expect_file("-o", o.exr);
  } else if (o.command == "simulate") {
    out.expect_folder("-o", o.exr);
    if (!o.stats.empty()) out.expect_file("--stats", o.stats);
  } else {  // turntable, growth
    const bool png = o.png_frames || !o.mp4.empty();
    for (int f = 0; f < *o.frames; ++f) {
      const std::string exr = frame_name(o.exr, f);
      out.expect_file("-o", exr);
      if (png) out.expect_file(png_frames_option(o), png_frame_name(exr));
    }
    if (!o.mp4.empty()) out.expect_file("--mp4", o.mp4);
  }
}

void expect_scene_inputs(const SceneDesc& desc, OutputSet& out) {
  for (const std::string& f : desc.files) out.expect_input(desc.file, f);
}

void write_json_output(OutputSet& out, const std::string& option, const std::string& path, const nlohmann::json& j) {
  out.write_bytes(option, path, j.dump(2) + "\n");
}

}  // namespace phellem
