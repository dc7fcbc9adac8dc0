// The fit's relief stage on a geometry already fitted: reads a `phellem fit` report.json's
// parameters, rebuilds the candidate, and runs compare/fit_relief on the photo at the
// evaluation scale, printing what it found and its time.
//   phellem_bench_fit_relief PHOTO PX_PER_CM REPORT_JSON [MAX_EVALS] [SEEDS]
// Other modes (docs/fit.md):
//   RELIEF_GRID=1   a 36-point grid of reliefs (depth_ratio × detail × shoulder_width) instead,
//                   every statistic printed;
//   SCALE_CHECK=1   the fitted candidate (with its fitted relief) scored at 5 and at 10 px/cm
//                   per seed; DEPTH_SHAPE=u|v|r and MAX_DEPTH=M override its depth profile.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "compare/common_scale.h"
#include "compare/fit_objective.h"
#include "compare/fit_relief.h"
#include "io/height_image.h"

using namespace phellem;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s PHOTO PX_PER_CM REPORT_JSON [MAX_EVALS] [SEEDS]\n", argv[0]);
    return 2;
  }
  const double s = std::stod(argv[2]);
  std::ifstream in(argv[3]);
  const nlohmann::json report = nlohmann::json::parse(in);
  const int max_evals = argc > 4 ? std::stoi(argv[4]) : 80;
  const int n_seeds = argc > 5 ? std::stoi(argv[5]) : 4;
  HeightImage img = read_height_image(argv[1]);
  const HeightField photo{img.width, img.height, s, std::move(img.z)};
  const HeightField coarse = resample(photo, s, s, 5.0);
  const FissureStats target = analyse_fissures(coarse, nullptr, argv[1]).stats;
  const FitSpace space = strip_fit_space();
  std::vector<double> x;
  for (const FitParameter& row : space.table) x.push_back(row.normalized(report["fit"]["parameters"][row.key].get<double>()));
  const FitCandidate c = space.candidate(x);
  std::vector<uint64_t> seeds;
  for (int k = 0; k < n_seeds; ++k) seeds.push_back(fit_simulation_seed(1, k));
  if (std::getenv("SCALE_CHECK")) {  // the fitted candidate's score at 5 and at 10 px/cm, per seed
    FitCandidate g = c;
    const auto& rel = report["fit"]["relief"];
    if (rel.value("ridges", false)) {
      g.strips.relief.ridges = true;
      for (const FitParameter& row : relief_fit_rows()) row.apply(rel["parameters"][row.key].get<double>(), g);
    }
    if (const char* v = std::getenv("DEPTH_SHAPE")) g.strips.depth.shape = v[0] == 'v' ? bark::DepthProfileShape::V : v[0] == 'r' ? bark::DepthProfileShape::Round : bark::DepthProfileShape::U;
    if (const char* v = std::getenv("MAX_DEPTH")) g.strips.depth.max_depth = std::atof(v);
    const FissureStats full_t = analyse_fissures(photo, nullptr, argv[1]).stats;
    for (int k = 0; k < n_seeds; ++k) {
      if (k == 0) {
        const FitScore t = score_candidate(g, target, {coarse.width, coarse.height, coarse.px_per_cm}, seeds[0]);
        const FitScore u = score_candidate(g, full_t, {photo.width, photo.height, photo.px_per_cm}, seeds[0]);
        std::printf("photo:");
        for (size_t i = 0; i < t.comparison.core.size(); ++i)
          std::printf(" %s %.2f/%.2f", t.comparison.core[i].name.c_str(), t.comparison.core[i].a, u.comparison.core[i].a);
        std::printf("\n");
      }
      const FitScore a = score_candidate(g, target, {coarse.width, coarse.height, coarse.px_per_cm}, seeds[size_t(k)]);
      const FitScore b = score_candidate(g, full_t, {photo.width, photo.height, photo.px_per_cm}, seeds[size_t(k)]);
      std::printf("seed %d: 5 px/cm score %.3f emd %.2f | 10 px/cm score %.3f emd %.2f |", k, a.comparison.score,
                  a.comparison.orientation_emd_deg, b.comparison.score, b.comparison.orientation_emd_deg);
      for (size_t i = 0; i < a.comparison.core.size(); ++i)
        std::printf(" %s %.2f/%.2f", a.comparison.core[i].name.c_str(), a.comparison.core[i].b, b.comparison.core[i].b);
      std::printf("\n");
      std::fflush(stdout);
    }
    return 0;
  }
  if (std::getenv("RELIEF_GRID")) {  // a coarse grid instead of the search, every statistic printed
    for (double dr : {1.0, 1.5, 2.5, 5.0})
      for (double det : {0.0, 0.3, 0.7})
        for (double sw : {0.006, 0.015, 0.03}) {
          FitCandidate g = c;
          g.strips.relief.ridges = true;
          g.strips.relief.depth_ratio = dr;
          g.strips.relief.detail = det;
          g.strips.relief.shoulder_width = sw;
          const FitScore f = score_candidate(g, target, {coarse.width, coarse.height, coarse.px_per_cm}, seeds[0]);
          std::printf("dr %.1f detail %.1f shoulder %.3f: f %.3f score %.3f emd %.2f |", dr, det, sw, f.f, f.comparison.score,
                      f.comparison.orientation_emd_deg);
          for (const auto& d : f.comparison.core) std::printf(" %s %.2f(%.2f)", d.name.c_str(), d.difference, d.b);
          std::printf("\n");
          std::fflush(stdout);
        }
    return 0;
  }
  ReliefFitOptions o;
  o.max_evals = max_evals;
  const auto t0 = std::chrono::steady_clock::now();
  const ReliefFitResult r = fit_relief(c.strips, target, {coarse.width, coarse.height, coarse.px_per_cm}, seeds, o);
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("without relief %.4f, with %.4f (ridges %d: depth_ratio %.3f shoulder %.4f detail %.2f size %.4f walls %.2f), %d evals, %.1fs\n",
              r.f_off, r.f, int(r.look.enabled && r.look.ridges), r.look.depth_ratio, r.look.shoulder_width, r.look.detail, r.look.detail_size,
              r.look.wall_noise, r.evaluations, t);
}
