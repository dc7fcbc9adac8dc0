// Calibration of `phellem compare` against the two reference scans (issue 22; plan §3, the
// prototype's figures). Not a test: the tests build their own fields. Reads the displacement
// maps as raw code values (no colour conversion: gamma is not an affine change), channel 0, at
// a declared scale, and prints the scores the bands were set from:
//   halves of one scan (left/right, top/bottom)   band 0.03–0.13
//   Brown vs Pine                                 band 0.18–0.29
//   a scan vs itself halved and declared at half the scale   ≈ 0.03
//   a scan vs itself halved but declared at the full scale   (the cost of a 2× mismatch)
//
//   phellem_bench_compare_calibration [reference/photos folder] [px/cm, default 10]
#include <OpenImageIO/imageio.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "compare/common_scale.h"
#include "compare/compare_score.h"
#include "compare/fissure_statistics.h"

namespace {

using namespace phellem;

HeightField read_raw_heights(const std::string& path, double px_per_cm) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    std::fprintf(stderr, "compare_calibration: error: %s: %s\n", path.c_str(), OIIO::geterror().c_str());
    std::exit(2);
  }
  const OIIO::ImageSpec& spec = in->spec();
  HeightField f{spec.width, spec.height, px_per_cm, {}};
  const size_t n = size_t(spec.width) * size_t(spec.height);
  f.z.resize(n);
  // Raw code values: read in the file's integer type, then scale by hand (OIIO's FLOAT
  // conversion would be the same linear map, but this makes "no colour conversion" explicit).
  const bool wide = spec.format.size() > 1;
  bool ok = false;
  if (wide) {
    std::vector<uint16_t> v(n);
    ok = in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT16, v.data());
    for (size_t i = 0; i < n; ++i) f.z[i] = float(v[i]) / 65535.0f;
  } else {
    std::vector<uint8_t> v(n);
    ok = in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, v.data());
    for (size_t i = 0; i < n; ++i) f.z[i] = float(v[i]) / 255.0f;
  }
  if (!ok) {
    std::fprintf(stderr, "compare_calibration: error: %s: %s\n", path.c_str(), in->geterror().c_str());
    std::exit(2);
  }
  return f;
}

HeightField crop(const HeightField& f, int x0, int y0, int w, int h) {
  HeightField c{w, h, f.px_per_cm, {}};
  c.z.reserve(size_t(w) * size_t(h));
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) c.z.push_back(f.at(x, y));
  return c;
}

FissureStats stats(const HeightField& f, const std::string& name) { return analyse_fissures(f, nullptr, name).stats; }

void print_stats(const char* name, const FissureStats& s) {
  std::printf("  %-6s ff %.3f  vf %.3f  spacing %.2f ± %.2f cm  width %.2f cm  length %.1f cm  depth ratio %.2f  "
              "(mean orientation %.1f°, %d components)\n",
              name, s.fissure_fraction, s.vertical_fraction, s.spacing_h_mean, s.spacing_h_std, s.width_mean,
              s.length_median, s.depth_ratio, s.orientation_mean_deg, s.components);
}

void print_comparison(const char* what, const Comparison& c) {
  std::printf("  %-34s score %.3f  emd %5.2f°  %-10s [", what, c.score, c.orientation_emd_deg, c.verdict.c_str());
  for (const auto& d : c.core) std::printf(" %.2f", d.difference);
  std::printf(" ]\n");
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "/work/shared/reference/photos";
  const double s = argc > 2 ? std::atof(argv[2]) : 10.0;
  const auto t0 = std::chrono::steady_clock::now();
  struct Scan {
    const char* name;
    HeightField field;
    FissureStats full;
  } scans[2] = {{"brown", read_raw_heights(dir + "/bark_brown_01_polyhaven_disp.jpg", s), {}},
                {"pine", read_raw_heights(dir + "/pine_bark_polyhaven_disp.png", s), {}}};
  std::printf("compare calibration at %g px/cm (core differences in the order ff vf sp_mean sp_std width length depth)\n", s);
  for (Scan& scan : scans) {
    const HeightField& f = scan.field;
    const int w = f.width, h = f.height;
    scan.full = stats(f, scan.name);
    print_stats(scan.name, scan.full);
    const Comparison lr = compare_fissures(stats(crop(f, 0, 0, w / 2, h), "L"), stats(crop(f, w / 2, 0, w - w / 2, h), "R"));
    const Comparison tb = compare_fissures(stats(crop(f, 0, 0, w, h / 2), "T"), stats(crop(f, 0, h / 2, w, h - h / 2), "B"));
    print_comparison((std::string(scan.name) + " left/right halves").c_str(), lr);
    print_comparison((std::string(scan.name) + " top/bottom halves").c_str(), tb);
    // The same scan at half size: declared at half the scale, then (wrongly) at the full scale.
    HeightField half = resample(f, s, s, s / 2);
    const Comparison declared = compare_fissures(scan.full, stats(half, "half"));
    half.px_per_cm = s;
    const Comparison mismatch = compare_fissures(scan.full, stats(half, "half"));
    print_comparison((std::string(scan.name) + " vs half size at half scale").c_str(), declared);
    print_comparison((std::string(scan.name) + " vs half size, 2x mismatch").c_str(), mismatch);
  }
  print_comparison("brown vs pine", compare_fissures(scans[0].full, scans[1].full));
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("(%.2f s)\n", t);
  return 0;
}
