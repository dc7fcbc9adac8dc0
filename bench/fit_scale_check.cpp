// Do fit scores at a reduced evaluation scale track those at the photo's scale? For N random
// strip candidates, the objective (score + EMD/90) against a photo at its own scale and at a
// coarser one, with the wall time of each; prints the rows and their rank correlation.
//   phellem_bench_fit_scale PHOTO PX_PER_CM [N] [EVAL_PX_PER_CM]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>

#include "compare/common_scale.h"
#include "compare/fit_objective.h"
#include "io/height_image.h"
#include "util/random.h"

using namespace phellem;

static std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<size_t> idx(v.size());
  std::iota(idx.begin(), idx.end(), size_t(0));
  std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (size_t i = 0; i < idx.size(); ++i) r[idx[i]] = double(i);
  return r;
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s PHOTO PX_PER_CM [N] [EVAL_PX_PER_CM]\n", argv[0]);
    return 2;
  }
  const double s = std::stod(argv[2]);
  const int n = argc > 3 ? std::stoi(argv[3]) : 12;
  const double se = argc > 4 ? std::stod(argv[4]) : 5.0;
  HeightImage img = read_height_image(argv[1]);
  HeightField photo{img.width, img.height, s, std::move(img.z)};
  const HeightField coarse = resample(photo, s, s, se);
  const FissureStats full_t = analyse_fissures(photo, nullptr, argv[1]).stats;
  const FissureStats coarse_t = analyse_fissures(coarse, nullptr, argv[1]).stats;
  const FitSpace space = strip_fit_space();
  StreamRng rng(42, 0, 0);
  std::vector<double> a, b;
  using Clock = std::chrono::steady_clock;
  for (int k = 0; k < n; ++k) {
    std::vector<double> x = k < int(space.starts.size()) ? space.starts[size_t(k)] : std::vector<double>(space.dimension());
    if (k >= int(space.starts.size()))
      for (double& v : x) v = rng.uniform();
    const FitCandidate c = space.candidate(x);
    const auto t0 = Clock::now();
    const FitScore f = score_candidate(c, full_t, {photo.width, photo.height, s}, 3);
    const auto t1 = Clock::now();
    const FitScore g = score_candidate(c, coarse_t, {coarse.width, coarse.height, coarse.px_per_cm}, 3);
    const auto t2 = Clock::now();
    std::printf("%2d  full %.3f (score %.3f emd %5.1f) %.2fs   coarse %.3f (score %.3f emd %5.1f) %.2fs\n", k, f.f,
                f.comparison.score, f.comparison.orientation_emd_deg, std::chrono::duration<double>(t1 - t0).count(), g.f,
                g.comparison.score, g.comparison.orientation_emd_deg, std::chrono::duration<double>(t2 - t1).count());
    if (std::getenv("FIT_VERBOSE"))
      for (const auto& d : g.comparison.core) std::printf("      %-18s photo %8.3f  fit %8.3f  diff %.3f\n", d.name.c_str(), d.a, d.b, d.difference);
    a.push_back(f.f);
    b.push_back(g.f);
  }
  const auto ra = ranks(a), rb = ranks(b);
  double d2 = 0;
  for (size_t i = 0; i < ra.size(); ++i) d2 += (ra[i] - rb[i]) * (ra[i] - rb[i]);
  const double N = double(ra.size());
  std::printf("Spearman rank correlation full vs %.1f px/cm: %.3f\n", se, 1 - 6 * d2 / (N * (N * N - 1)));
  return 0;
}
