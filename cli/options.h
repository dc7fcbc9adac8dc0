// Command-line parsing for `phellem`: strict, every mistake is a UserError (exit 2).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace phellem::cli {

struct Options {
  std::string command;
  std::string scene;  // empty: embedded default scene
  std::string exr, png, stats, mp4;
  bool png_frames = false;  // turntable --png
  std::optional<int> spp, threads, frames, width, height;
  std::optional<uint64_t> seed;
  std::optional<float> degrees;
  std::string view;
  bool quiet = false;
  bool no_mesh = false;          // simulate: skip the .glb bark meshes
  std::string memory_limit;      // --memory-limit SIZE (empty: PHELLEM_MEMORY_LIMIT or 3/4 of physical memory)
  bool memory_estimate = false;  // --memory-estimate: print the estimate and stop
  std::optional<double> time_limit;  // --time-limit DURATION in seconds: the longest growth started (cli/memory_check.h)
  // fit: HEIGHT_IMAGE (in `scene`), --scale PX_PER_CM, --albedo IMAGE, --model, --time-budget S, --max-evals N.
  std::optional<double> scale, time_budget;
  std::string albedo, model;
  std::string objective = "height";  // fit --objective height|lit|both
  std::optional<double> relief;      // fit --relief METRES: the photo's full height range (lit objectives)
  std::optional<long long> max_evals;
  // preview: --snapshot OUT.png (in `png`), --max-level N, --edge-px P, --frames N (window: quit after N frames).
  std::optional<int> max_level;
  std::optional<double> edge_px;
  // slice: --object NAME, --plane AXIS=VALUE (axis 0 x, 1 y, 2 z; −1 not given).
  std::string object;
  int plane_axis = -1;
  double plane_value = 0;
};

Options parse(const std::vector<std::string>& args);
std::string usage();

}  // namespace phellem::cli
