// Calibration of `phellem compare --lit` on the two reference scans (issue 44 item 2). Not a
// test: the tests build their own bark. Each scan (height + albedo) is rendered under the lit
// rig at a common scale, and the lit score is printed for
//   the halves of one scan (left/right, top/bottom)          the same-look band
//   Bark Brown vs Pine                                         clearly higher
//   a scan vs itself with relief × 3, its albedo replaced by its mean, its fissure floors black
//                                                              each detected, in words
//
//   phellem_bench_lit_calibration [reference/photos folder] [px/cm, default 5] [relief m, default 0.03] [spp, default 16]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "compare/compare_inputs.h"
#include "compare/lit_score.h"
#include "lookdev/lit_rig.h"
#include "lookdev/lit_variants.h"
#include "util/errors.h"

namespace {

using namespace phellem;

LitSubject scan(const std::string& dir, const std::string& height, const std::string& albedo, double px_per_cm, double relief,
                const std::string& label) {
  CompareSource src{label, dir + "/" + height, 10.0, dir + "/" + albedo};
  const PreparedInput in = at_scale(load_input(src), px_per_cm);
  LitSubject s;
  s.label = label;
  s.height = in.field;
  for (float& z : s.height.z) z = float(z * relief);
  s.albedo = in.albedo;
  return s;
}

struct Bench {
  LitRig rig;
  LitStatistics measure(const LitSubject& s) const {
    const auto t0 = std::chrono::steady_clock::now();
    const LitRender r = render_lit(s, rig);
    const LitStatistics st = lit_statistics(r.image, s.label);
    std::fprintf(stderr, "  rendered %-28s %4d×%-4d px in %5.1f s\n", s.label.c_str(), r.image.width, r.image.height,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return st;
  }
  void row(const char* what, const LitStatistics& ref, const LitStatistics& cand) const {
    const LitComparison c = compare_lit(ref, cand);
    std::printf("  %-34s score %.3f  %-9s [", what, c.score, c.verdict.c_str());
    for (const LitGroupScore& g : c.groups) std::printf(" %s %.2f", g.group.c_str(), g.score);
    std::printf(" ]");
    for (const std::string& w : c.words) std::printf(" \"%s\"", w.c_str());
    std::printf("\n");
    std::fflush(stdout);
  }
};

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "/work/shared/reference/photos";
  const double s = argc > 2 ? std::atof(argv[2]) : 5.0;
  const double relief = argc > 3 ? std::atof(argv[3]) : 0.03;
  Bench b;
  b.rig.spp = argc > 4 ? std::atoi(argv[4]) : 16;
  try {
    const LitSubject brown = scan(dir, "bark_brown_01_polyhaven_disp.jpg", "bark_brown_01_polyhaven.jpg", s, relief, "brown");
    const LitSubject pine = scan(dir, "pine_bark_polyhaven_disp.png", "pine_bark_polyhaven.jpg", s, relief, "pine");
    std::printf("lit calibration at %g px/cm, relief %g m, %d spp, sun %g° elevation%s\n", s, relief, b.rig.spp,
                b.rig.sun_elevation_deg, b.rig.sky ? " + sky" : "");
    LitStatistics full[2];
    int k = 0;
    for (const LitSubject* scan : {&brown, &pine}) {
      const std::string& n = scan->label;
      full[k] = b.measure(*scan);
      b.row((n + " left/right halves").c_str(), b.measure(half_of(*scan, true, false)), b.measure(half_of(*scan, true, true)));
      b.row((n + " top/bottom halves").c_str(), b.measure(half_of(*scan, false, false)), b.measure(half_of(*scan, false, true)));
      b.row((n + " relief x3").c_str(), full[k], b.measure(with_relief_scaled(*scan, 3.0)));
      b.row((n + " albedo -> its mean").c_str(), full[k], b.measure(with_mean_albedo(*scan)));
      b.row((n + " fissure floors black").c_str(), full[k], b.measure(with_black_fissure_floors(*scan)));
      ++k;
    }
    b.row("brown vs pine", full[0], full[1]);
    b.row("pine vs brown", full[1], full[0]);
  } catch (const UserError& e) {
    std::fprintf(stderr, "lit_calibration: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
