#include "cli/fit_memory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare/strip_patch.h"
#include "scene/memory_budget.h"

namespace phellem {

namespace {

// ---- Measured costs -------------------------------------------------------------------------
// Peak RSS (`/usr/bin/time -v`, Release, 2 threads) of `phellem fit PHOTO --scale 10 --model
// strips --max-evals 2` on crops of bark_brown_01 (the choice at the final scale is the peak: two
// patches at once): 256² 181 MB, 512² 261 MB, 1024² 557 MB. A least-squares fit of base + per
// photo pixel + 2 × per simulated texel (the patch and its 5 cm margin) gives these three, and
// the estimate below gives 557 MB at 1024². Stress (no choice stage): 256² 160 MB, 512² 177 MB,
// which the same costs overestimate by 10–40 % (it was not measured beyond 512²).
constexpr double kBaseBytes = 144e6;
// Per pixel of the photo, held from start to end: its heights as read, at the photo's scale,
// at the evaluation and final scales, and their statistics.
constexpr double kPhotoBytesPerPixel = 127;
// Per texel of a simulated patch with its margin: the fracture field and its rasterization
// (strips) or the cracked sheet's profile sampling (stress), the height field and its statistics.
constexpr double kStripBytesPerTexel = 111;
constexpr double kStressBytesPerTexel = 111;
// The report's statistics of the fitted patch (cli/compare.cpp: 101 bytes a pixel measured).
constexpr double kAnalysisBytesPerPixel = 110;

std::string size_text(const PatchSize& s) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%d×%d px at %.3g px/cm", s.width, s.height, s.px_per_cm);
  return buf;
}

// Pixels of a patch with the margin simulated around it (compare/strip_patch.h; the stress
// patch's margin is the same 5 cm).
double texels(const PatchSize& s) {
  const double margin = std::ceil(kStripPatchMarginM * 100 * s.px_per_cm);
  return (s.width + 2 * margin) * (s.height + 2 * margin);
}

double pixels(const PatchSize& s) { return double(s.width) * double(s.height); }

}  // namespace

MemoryEstimate estimate_fit_memory(const FitMemoryRequest& r) {
  const std::string advice = "fit a smaller crop of the photo (now " + size_text(r.full) + "), or raise --memory-limit";
  const double per_texel = r.stress ? kStressBytesPerTexel : kStripBytesPerTexel;
  const MemoryItem base{"the program itself", kBaseBytes, "", "", ""};
  const MemoryItem photo{"the photo at its scales and its statistics", pixels(r.full) * kPhotoBytesPerPixel, r.photo,
                         "HEIGHT_IMAGE", advice};
  auto patches = [&](const std::string& what, const PatchSize& s, int n) {
    return MemoryItem{std::to_string(n) + " " + what + " (" + size_text(s) + " and a 5 cm margin) and their statistics",
                      n * texels(s) * per_texel, r.photo, "HEIGHT_IMAGE", advice};
  };
  MemoryEstimate e;
  e.moments.push_back({"searching", {base, photo, patches("simulated patches", r.eval, r.search_parallel)}});
  e.moments.push_back({"scoring the best points at the final scale",
                       {base, photo, patches("simulated patches", r.final, r.final_parallel)}});
  MemoryItem last = patches("patch", r.full, 1);
  last.what = "the fitted patch (" + size_text(r.full) + " and a 5 cm margin) and the compare report of it and the photo";
  last.bytes += pixels(r.full) * kAnalysisBytesPerPixel;  // the patch's statistics in the report
  e.moments.push_back({"writing the fitted patch and its report", {base, photo, last}});
  return e;
}

void check_fit_memory(const FitMemoryRequest& r, const std::string& memory_limit) {
  check_memory(estimate_fit_memory(r), memory_budget(memory_limit));
}

}  // namespace phellem
