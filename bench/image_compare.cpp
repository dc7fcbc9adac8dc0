// Compares two renders of the same scene (bench/run_cycles_comparison.sh): reads the RGB of
// each EXR (Phellem's beauty.R/G/B or a plain R/G/B), and prints one JSON object:
//   rel_l1   Σ|a − b| / Σ|b| over pixels and channels (the mean relative difference, robust
//            to dark pixels),
//   rmse     sqrt(mean (a − b)²),
//   mean_a, mean_b   mean values (a brightness bias shows here first).
//
//   phellem_bench_compare A.exr B.exr
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

bool read_rgb(const std::string& path, std::vector<float>* rgb, int* w, int* h) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    std::fprintf(stderr, "phellem_bench_compare: error: %s: %s\n", path.c_str(), OIIO::geterror().c_str());
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  int idx[3];
  for (int c = 0; c < 3; ++c) {
    const char* names[2][3] = {{"beauty.R", "beauty.G", "beauty.B"}, {"R", "G", "B"}};
    idx[c] = spec.channelindex(names[0][c]);
    if (idx[c] < 0) idx[c] = spec.channelindex(names[1][c]);
    if (idx[c] < 0) {
      std::fprintf(stderr, "phellem_bench_compare: error: %s: no R/G/B or beauty.R/G/B channels\n", path.c_str());
      return false;
    }
  }
  *w = spec.width;
  *h = spec.height;
  std::vector<float> all(size_t(*w) * *h * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data())) {
    std::fprintf(stderr, "phellem_bench_compare: error: %s: %s\n", path.c_str(), in->geterror().c_str());
    return false;
  }
  rgb->resize(size_t(*w) * *h * 3);
  for (size_t p = 0; p < size_t(*w) * *h; ++p)
    for (int c = 0; c < 3; ++c) (*rgb)[p * 3 + c] = all[p * spec.nchannels + idx[c]];
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: phellem_bench_compare A.exr B.exr\n");
    return 2;
  }
  std::vector<float> a, b;
  int wa = 0, ha = 0, wb = 0, hb = 0;
  if (!read_rgb(argv[1], &a, &wa, &ha) || !read_rgb(argv[2], &b, &wb, &hb)) return 2;
  if (wa != wb || ha != hb) {
    std::fprintf(stderr, "phellem_bench_compare: error: %s: %dx%d differs from %s: %dx%d\n", argv[1], wa, ha, argv[2], wb, hb);
    return 2;
  }
  double abs_diff = 0, abs_b = 0, sq = 0, sum_a = 0, sum_b = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = double(a[i]) - double(b[i]);
    abs_diff += std::abs(d);
    abs_b += std::abs(double(b[i]));
    sq += d * d;
    sum_a += a[i];
    sum_b += b[i];
  }
  const double n = double(a.size());
  std::printf("{\"rel_l1\": %.6f, \"rmse\": %.6g, \"mean_a\": %.6g, \"mean_b\": %.6g}\n", abs_diff / std::max(abs_b, 1e-30),
              std::sqrt(sq / n), sum_a / n, sum_b / n);
  return 0;
}
