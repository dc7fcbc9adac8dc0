#include "cli/memory_check.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/slice.h"
#include "io/film.h"
#include "renderer/film_memory.h"
#include "scene/growth_time.h"
#include "scene/memory_budget.h"
#include "scene/scene_parser.h"
#include "util/errors.h"

namespace phellem {

namespace {

// The section image of `slice` (bark/growth/ring_section.cpp): RGB floats while it is painted,
// a byte mask per ring or obstacle, and the 8-bit RGB copy made at the end, 16 bytes a pixel.
constexpr double kSectionBytesPerPixel = 16;

MemoryItem section_item(int width, int height) {
  const std::string wh = std::to_string(width) + "x" + std::to_string(height);
  return {"the " + wh + " section image (RGB floats while painted, and its 8-bit copy)",
          double(width) * double(height) * kSectionBytesPerPixel, "", "--res", "lower --res (now " + wh + ")"};
}

MemoryRequest request(const cli::Options& o, const SceneDesc& desc, int width, int height) {
  MemoryRequest r;
  if (o.command == "simulate" || o.command == "slice") {
    // slice grows one object as simulate does (its --res is the section image's size).
    r.command = MemoryCommand::Simulate;
    r.field_width = o.command == "slice" ? 0 : o.width.value_or(0);
    r.field_height = o.command == "slice" ? 0 : o.height.value_or(0);
    r.meshes = !o.no_mesh && o.command == "simulate";
    if (o.command == "slice") r.section = section_item(width, height);
    return r;
  }
  r.command = o.command == "growth" ? MemoryCommand::Growth : MemoryCommand::Render;
  r.height = height;
  // render writes render.exr when given no output; frame sequences always write EXRs, and PNGs
  // with --png or for --mp4.
  const bool frames = o.command != "render";
  const bool exr = frames || !o.exr.empty() || o.png.empty();
  const bool png = frames ? o.png_frames || !o.mp4.empty() : !o.png.empty();
  const FilmMemory fm = film_memory(width, height, exr, png);
  const std::string wh = std::to_string(width) + "x" + std::to_string(height);
  r.film.bytes = fm.peak();
  r.film.what = "the " + wh + " film (" + std::to_string(Film::kChannels) + " floats a pixel in its layers" +
                (exr && png ? ", and the EXR's and the PNG's copies)"
                 : exr      ? ", and the EXR's copy)"
                            : ", and the PNG's copy)");
  if (o.width) {
    r.film.where = "--res";
    r.film.advice = "lower --res (now " + wh + ")";
  } else {
    r.film.file = desc.file;
    r.film.where = "/render/resolution";
    r.film.advice = "lower the resolution (now " + wh + "), or render it smaller with --res";
  }
  return r;
}

// The longest growth a command starts without being asked (--time-limit raises it): a run of
// hours should be a decision, not a surprise found the next morning.
constexpr double kDefaultTimeLimit = 3600;

std::string about(double vertices) {
  char s[32];
  if (vertices < 1000)
    std::snprintf(s, sizeof s, "%.0f", vertices);
  else if (vertices < 1e6)
    std::snprintf(s, sizeof s, "%.0fk", vertices / 1e3);
  else
    std::snprintf(s, sizeof s, "%.1fM", vertices / 1e6);
  return s;
}

// Prints each growth's estimate (unless --quiet) and refuses the growths together over the
// time limit, at the steps of the longest.
void check_growth_time(const cli::Options& o, const SceneDesc& desc) {
  const std::vector<GrowthTime> times = estimate_growth_times(desc);
  if (times.empty()) return;
  double total = 0;
  const GrowthTime* longest = &times.front();
  for (const GrowthTime& t : times) {
    total += t.seconds;
    if (t.seconds > longest->seconds) longest = &t;
    if (!o.quiet)
      std::cerr << "growth of " << t.object << ": about " << human_duration(t.seconds) << " for " << t.steps
                << " steps of ~" << about(t.vertices) << " interface vertices\n";
  }
  const double limit = o.time_limit.value_or(kDefaultTimeLimit);
  if (total <= limit) return;
  // A limit to suggest: the estimate with room to spare, in whole hours.
  const double hours = std::ceil(1.5 * total / 3600);
  throw UserError(longest->file, longest->where,
                  "the growth of " + longest->object + " would take about " + human_duration(longest->seconds) + " (" +
                      std::to_string(longest->steps) + " steps of ~" + about(longest->vertices) +
                      " interface vertices" + (times.size() > 1 ? "; all growths " + human_duration(total) : std::string()) +
                      "), over the time limit of " + human_duration(limit) +
                      ": lower steps, or raise the limit with --time-limit (e.g. --time-limit " +
                      std::to_string((long long)hours) + "h)");
}

}  // namespace

void check_scene_memory(const cli::Options& o, const SceneDesc& desc, int width, int height) {
  const MemoryBudget budget = memory_budget(o.memory_limit);
  check_memory(estimate_memory(desc, request(o, desc, width, height)), budget);
  check_growth_time(o, desc);
}

int run_memory_estimate(const cli::Options& o) {
  const SceneDesc desc = o.scene.empty() ? default_scene() : load_scene_file(o.scene);
  const int fallback_w = o.command == "slice" ? kSliceDefaultSize : desc.render.width;
  const int fallback_h = o.command == "slice" ? kSliceDefaultSize : desc.render.height;
  const int width = o.width.value_or(fallback_w), height = o.height.value_or(fallback_h);
  const MemoryBudget budget = memory_budget(o.memory_limit);
  const MemoryEstimate e = estimate_memory(desc, request(o, desc, width, height));
  std::cout << describe(e, budget);
  check_memory(e, budget);
  return 0;
}

}  // namespace phellem
