#include "compare/lit_statistics.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>

#include "compare/cielab.h"
#include "compare/gaussian_blur.h"
#include "compare/percentile.h"
#include "util/errors.h"

namespace phellem {
namespace {

constexpr double kRad = std::numbers::pi / 180;

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Rec. ITU-R BT.709-6, item 3.2: Y = 0.2126 R + 0.7152 G + 0.0722 B (linear).
double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

// Every refusal, each message saying what was found and what is allowed. Masked pixels are
// not checked: they are never read.
void check(const LitImage& im, const std::string& name, const LitParams& p) {
  auto fail = [&](const std::string& what) { throw UserError(name, "", what); };
  if (im.width <= 0 || im.height <= 0 || im.rgb.empty())
    fail("the image is empty (" + std::to_string(im.width) + "×" + std::to_string(im.height) + " px)");
  const size_t n = size_t(im.width) * size_t(im.height);
  if (im.rgb.size() != 3 * n)
    fail("the image has " + std::to_string(im.rgb.size()) + " RGB floats; " + std::to_string(im.width) + "×" +
         std::to_string(im.height) + " px needs " + std::to_string(3 * n));
  if (!im.valid.empty() && im.valid.size() != n)
    fail("the mask has " + std::to_string(im.valid.size()) + " pixels; the image has " + std::to_string(n));
  if (!std::isfinite(im.px_per_cm) || im.px_per_cm < p.min_px_per_cm)
    fail("the scale is " + fmt(im.px_per_cm) + " px/cm; the lit statistics need at least " + fmt(p.min_px_per_cm) +
         " px/cm (the finest contrast scale, " + fmt(p.contrast_sigma_cm[0]) + " cm, must be ≥ 1 px)");
  if (im.width < p.min_side_px || im.height < p.min_side_px)
    fail("the image is " + std::to_string(im.width) + "×" + std::to_string(im.height) + " px; the lit statistics need at least " +
         std::to_string(p.min_side_px) + " px on each side");
  size_t valid = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!im.valid.empty() && !im.valid[i]) continue;
    ++valid;
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(im.rgb[3 * i + size_t(c)]))
        fail("pixel (" + std::to_string(i % size_t(im.width)) + ", " + std::to_string(i / size_t(im.width)) + ") is " +
             fmt(im.rgb[3 * i + size_t(c)]) + " in channel " + std::string(1, "RGB"[c]) +
             "; every valid pixel must be finite (mask it out to skip it)");
  }
  if (valid < size_t(p.min_valid_pixels))
    fail("the mask keeps " + std::to_string(valid) + " of " + std::to_string(n) + " pixels; the lit statistics need at least " +
         std::to_string(p.min_valid_pixels) + " valid pixels");
}

// G(σ)∗(v·m) / G(σ)∗m, the blur of the valid values alone (Knutsson & Westin 1993, "Normalized
// and differential convolution", CVPR, sec. 3): masked pixels weigh nothing. `m` empty = all
// valid: a plain blur. `v` must be 0 where m = 0 (never NaN).
std::vector<float> masked_blur(const std::vector<float>& v, const std::vector<float>& m, int w, int h, double sigma) {
  if (m.empty()) return gaussian_blur(v, w, h, sigma);
  std::vector<float> vm(v.size());
  for (size_t i = 0; i < v.size(); ++i) vm[i] = v[i] * m[i];
  std::vector<float> num, den;
  tbb::parallel_invoke([&] { num = gaussian_blur(vm, w, h, sigma); }, [&] { den = gaussian_blur(m, w, h, sigma); });
  for (size_t i = 0; i < num.size(); ++i) num[i] = den[i] > 1e-6f ? num[i] / den[i] : 0.f;
  return num;
}

// A raster and its per-pixel weight (the valid fraction; empty = all 1).
struct Grid {
  int w = 0, h = 0;
  std::vector<float> v, m;
};

// d×d box averages of the valid values, weighted by the valid fraction of each block (blocks
// beyond the border are cut and count their missing pixels as invalid).
Grid decimate(const Grid& g, int d) {
  if (d == 1) return g;
  Grid o{(g.w + d - 1) / d, (g.h + d - 1) / d, {}, {}};
  std::vector<double> sum(size_t(o.w) * size_t(o.h), 0.0), cnt(sum.size(), 0.0);
  for (int y = 0; y < g.h; ++y)
    for (int x = 0; x < g.w; ++x) {
      const size_t i = size_t(y) * size_t(g.w) + size_t(x), j = size_t(y / d) * size_t(o.w) + size_t(x / d);
      const double wt = g.m.empty() ? 1.0 : g.m[i];
      sum[j] += wt * g.v[i];
      cnt[j] += wt;
    }
  o.v.resize(sum.size());
  o.m.resize(sum.size());
  for (size_t j = 0; j < sum.size(); ++j) {
    o.v[j] = cnt[j] > 0 ? float(sum[j] / cnt[j]) : 0.f;
    o.m[j] = float(cnt[j] / (double(d) * d));
  }
  return o;
}

// The std over the valid pixels of the difference-of-Gaussians band G(σ)∗ℓ − G(2σ)∗ℓ (σ in px).
// Scales with σ ≥ 2·min_sigma_px are measured on the grid decimated by d = 2^k, the largest with
// σ/d ≥ min_sigma_px, each blur's σ reduced by the box's own variance (d² − 1)/12 (Burt &
// Adelson 1983: a band-pass level needs no more samples than its band); the box's zeros at
// multiples of 1/d cycles/px keep aliases out of the band.
double dog_contrast(const Grid& full, double sigma_px, double min_sigma_px) {
  int d = 1;
  while (sigma_px / (2 * d) >= min_sigma_px) d *= 2;
  const Grid g = decimate(full, d);
  auto decimated_sigma = [&](double s) { return std::sqrt(std::max(s * s - (double(d) * d - 1) / 12, 0.25)) / d; };
  std::vector<float> fine, coarse;
  tbb::parallel_invoke([&] { fine = masked_blur(g.v, g.m, g.w, g.h, decimated_sigma(sigma_px)); },
                       [&] { coarse = masked_blur(g.v, g.m, g.w, g.h, decimated_sigma(2 * sigma_px)); });
  double sw = 0, s1 = 0, s2 = 0;
  for (size_t i = 0; i < fine.size(); ++i) {
    const double wt = g.m.empty() ? 1.0 : g.m[i], b = double(fine[i]) - coarse[i];
    sw += wt;
    s1 += wt * b;
    s2 += wt * b * b;
  }
  if (sw <= 0) return 0;
  const double mean = s1 / sw;
  return std::sqrt(std::max(s2 / sw - mean * mean, 0.0));
}

// The edge-direction histogram of G(σ)∗ℓ, weighted by the gradient magnitude (central
// differences, one-sided on the border; only at valid pixels). Rows in parallel, each row's
// sums kept apart and added in row order (reproducible).
void orientation(const Grid& l, const std::vector<uint8_t>& valid, double sigma_px, LitStatistics& s) {
  const std::vector<float> ls = masked_blur(l.v, l.m, l.w, l.h, sigma_px);
  const int w = l.w, h = l.h;
  constexpr size_t kRow = kOrientationHistogramBins + 3;  // the bins, Σ|∇ℓ|, Σ|∇ℓ|·cos 2θ, Σ|∇ℓ|·sin 2θ
  std::vector<double> rows(size_t(h) * kRow, 0.0);
  auto at = [&](int x, int y) { return double(ls[size_t(y) * size_t(w) + size_t(x)]); };
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y) {
      double* row = &rows[size_t(y) * kRow];
      const int y0 = std::max(y - 1, 0), y1 = std::min(y + 1, h - 1);
      for (int x = 0; x < w; ++x) {
        if (!valid.empty() && !valid[size_t(y) * size_t(w) + size_t(x)]) continue;
        const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, w - 1);
        const double gx = (at(x1, y) - at(x0, y)) / std::max(x1 - x0, 1);
        const double gy = -(at(x, y1) - at(x, y0)) / std::max(y1 - y0, 1);  // rows run down: y up is −row
        const double mag2 = gx * gx + gy * gy;
        if (mag2 <= 0) continue;
        const double mag = std::sqrt(mag2);
        // The edge runs across the gradient: θ = φ + 90°, φ = atan2(gy, gx), so
        // e^{2iθ} = −(gx + i·gy)²/|∇|²: cos 2θ = (gy² − gx²)/|∇|², sin 2θ = −2·gx·gy/|∇|².
        double theta = std::atan2(gy, gx) / kRad + 90;  // in (−90°, 270°]
        if (theta >= 180) theta -= 180;
        if (theta < 0) theta += 180;
        const int bin = int((theta + 5) / 10) % kOrientationHistogramBins;  // bins centred on 0°, 10°, …
        row[bin] += mag;
        row[kOrientationHistogramBins] += mag;
        row[kOrientationHistogramBins + 1] += (gy * gy - gx * gx) / mag;
        row[kOrientationHistogramBins + 2] += -2 * gx * gy / mag;
      }
    }
  });
  std::vector<double> sum(kRow, 0.0);
  for (int y = 0; y < h; ++y)
    for (size_t k = 0; k < kRow; ++k) sum[k] += rows[size_t(y) * kRow + k];
  const double total = sum[kOrientationHistogramBins];
  if (total <= 0) return;
  for (int k = 0; k < kOrientationHistogramBins; ++k) s.orientation_hist[size_t(k)] = sum[size_t(k)] / total;
  const std::complex<double> axial(sum[kOrientationHistogramBins + 1], sum[kOrientationHistogramBins + 2]);
  s.orientation_anisotropy = std::abs(axial) / total;
  double mean = 0.5 * std::arg(axial) / kRad;
  if (mean < 0) mean += 180;
  s.orientation_mean_deg = mean >= 180 ? mean - 180 : mean;
}

LitColour colour(const LitImage& im, double exposure) {
  const size_t n = size_t(im.width) * size_t(im.height);
  std::vector<float> L(n), a(n), b(n);
  std::vector<uint8_t> keep(n, 1);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!im.valid.empty() && !im.valid[i]) {
        keep[i] = 0;
        continue;
      }
      const Eigen::Vector3d lab =
          linear_rec709_to_lab(exposure * Eigen::Vector3d(im.rgb[3 * i], im.rgb[3 * i + 1], im.rgb[3 * i + 2]));
      L[i] = float(lab[0]);
      a[i] = float(lab[1]);
      b[i] = float(lab[2]);
    }
  });
  if (!im.valid.empty()) {
    size_t k = 0;
    for (size_t i = 0; i < n; ++i)
      if (keep[i]) L[k] = L[i], a[k] = a[i], b[k] = b[i], ++k;
    L.resize(k), a.resize(k), b.resize(k);
  }
  const MeanStd ml = mean_std(L), ma = mean_std(a), mb = mean_std(b);
  LitColour c;
  c.L_mean = ml.mean, c.a_mean = ma.mean, c.b_mean = mb.mean;
  c.L_std = ml.std, c.a_std = ma.std, c.b_std = mb.std;
  c.chroma = std::hypot(c.a_mean, c.b_mean);
  c.hue_deg = std::atan2(c.b_mean, c.a_mean) / kRad;
  if (c.hue_deg < 0) c.hue_deg += 360;
  return c;
}

}  // namespace

LitStatistics lit_statistics(const LitImage& im, const std::string& name, const LitParams& p) {
  check(im, name, p);
  const int w = im.width, h = im.height;
  const size_t n = size_t(w) * size_t(h);
  auto ok = [&](size_t i) { return im.valid.empty() || im.valid[i]; };

  LitStatistics s;
  s.width = w, s.height = h, s.px_per_cm = im.px_per_cm;
  std::vector<float> Y(n, 0.f);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1 << 14), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i)
      if (ok(i)) Y[i] = float(luminance(&im.rgb[3 * i]));
  });
  std::vector<float> Y_valid;
  Y_valid.reserve(n);
  for (size_t i = 0; i < n; ++i)
    if (ok(i)) Y_valid.push_back(Y[i]);
  s.valid_pixels = int(Y_valid.size());
  const double M = median(Y_valid);
  if (!(M > 0))
    throw UserError(name, "",
                    "the median luminance of the valid pixels is " + fmt(M) +
                        " (half of them or more are black or negative); nothing to measure relative to it");
  s.median_luminance = M;

  // ℓ = ln(max(Y, floor·M)/M): log-luminance relative to the median, so k·RGB changes nothing.
  Grid l{w, h, std::vector<float>(n, 0.f), {}};
  if (!im.valid.empty()) l.m.assign(im.valid.begin(), im.valid.end());
  const double floor_Y = p.luminance_floor_ratio * M, black_Y = p.near_black_ratio * M;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1 << 14), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i)
      if (ok(i)) l.v[i] = float(std::log(std::max(double(Y[i]), floor_Y) / M));
  });
  std::vector<float> l_valid;
  l_valid.reserve(Y_valid.size());
  size_t black = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!ok(i)) continue;
    if (Y[i] < black_Y) ++black;
    l_valid.push_back(l.v[i]);
  }
  s.near_black_share = double(black) / double(Y_valid.size());
  const std::vector<double> q = percentiles(l_valid, std::vector<double>(p.percentiles.begin(), p.percentiles.end()));
  std::copy(q.begin(), q.end(), s.log_luminance_percentiles.begin());

  const double scale = im.px_per_cm;
  tbb::parallel_invoke([&] { orientation(l, im.valid, p.gradient_sigma_cm * scale, s); },
                       [&] { s.bands = octave_band_power(l.v, im.valid, w, h, scale); },
                       [&] {
                         for (int k = 0; k < kLitContrastScales; ++k)
                           s.local_contrast[size_t(k)] =
                               dog_contrast(l, p.contrast_sigma_cm[size_t(k)] * scale, p.contrast_min_sigma_px);
                       },
                       [&] { s.colour = colour(im, p.colour_median_Y / M); });
  return s;
}

}  // namespace phellem
