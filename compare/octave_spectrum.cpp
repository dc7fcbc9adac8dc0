#include "compare/octave_spectrum.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace phellem {
namespace {

// The smallest even n' ≥ n whose only prime factors are 2, 3 and 5: kissfft is O(n log n)
// on those and O(n²) on a large prime factor.
int smooth_size(int n) {
  for (int m = std::max(2, n + (n & 1));; m += 2) {
    int r = m;
    for (int p : {2, 3, 5})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

// Tukey (cosine-tapered) window sampled at pixel centres: 1 in the middle, a half Hann taper
// over kTaper of the side at each end (Harris 1978, "On the use of windows for harmonic
// analysis with the DFT", Proc. IEEE 66(1), sec. V.E, α = 2·kTaper). It removes the border
// discontinuity of a non-periodic render (which would leak power as 1/f² into every band) while
// keeping most of the pixels: a Hann window over the whole side keeps (3/8)² ≈ 14 % of the
// image's energy in 2-D and makes the low bands noisy; this one keeps 0.84² ≈ 71 %.
constexpr double kTaper = 0.125;
std::vector<double> tukey(int n) {
  std::vector<double> w(static_cast<size_t>(n), 1.0);
  const double taper = kTaper * n;
  for (int i = 0; i < n; ++i) {
    const double d = std::min(i + 0.5, n - i - 0.5);  // distance to the nearer end
    if (d < taper) w[size_t(i)] = 0.5 - 0.5 * std::cos(std::numbers::pi * d / taper);
  }
  return w;
}

}  // namespace

std::vector<SpectrumBand> octave_bands(int width, int height, double px_per_cm) {
  std::vector<SpectrumBand> bands;
  if (width <= 0 || height <= 0 || !(px_per_cm > 0)) return bands;
  const double lowest = kMinCyclesAcross * px_per_cm / std::min(width, height), nyquist = px_per_cm / 2;
  for (int k = int(std::ceil(std::log2(lowest))); std::ldexp(1.0, k + 1) <= nyquist; ++k)
    bands.push_back({std::ldexp(1.0, k), std::ldexp(1.0, k + 1), 0});
  return bands;
}

std::vector<SpectrumBand> octave_band_power(const std::vector<float>& values, const std::vector<uint8_t>& valid, int width,
                                            int height, double px_per_cm) {
  const size_t w = size_t(width), n = w * size_t(height);
  if (values.size() != n || (!valid.empty() && valid.size() != n))
    throw std::invalid_argument("octave_band_power: size mismatch");
  std::vector<SpectrumBand> bands = octave_bands(width, height, px_per_cm);
  if (bands.empty()) return bands;

  const std::vector<double> wx = tukey(width), wy = tukey(height);
  auto ok = [&](size_t i) { return valid.empty() || valid[i]; };
  // Subtract the window-weighted mean, so that no DC leaks into the lowest band.
  double sum = 0, sum_w = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * w + size_t(x);
      if (!ok(i)) continue;
      const double wt = wx[size_t(x)] * wy[size_t(y)];
      sum += wt * values[i];
      sum_w += wt;
    }
  const double mean = sum_w > 0 ? sum / sum_w : 0;

  const int W = smooth_size(width), H = smooth_size(height), half = W / 2 + 1;
  using C = std::complex<float>;
  std::vector<C> spec(size_t(H) * size_t(half), C(0, 0));  // rows ≥ height stay 0 (zero padding)
  tbb::enumerable_thread_specific<Eigen::FFT<float>> ffts([] {
    Eigen::FFT<float> f;
    f.SetFlag(Eigen::FFT<float>::HalfSpectrum);
    return f;
  });
  // Rows: real → half spectrum (kx = 0 … W/2).
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 8), [&](const tbb::blocked_range<int>& r) {
    Eigen::FFT<float>& fft = ffts.local();
    std::vector<float> row(size_t(W), 0.f);
    std::vector<C> out;
    for (int y = r.begin(); y < r.end(); ++y) {
      for (int x = 0; x < width; ++x) {
        const size_t i = size_t(y) * w + size_t(x);
        row[size_t(x)] = ok(i) ? float(wx[size_t(x)] * wy[size_t(y)] * (values[i] - mean)) : 0.f;
      }
      fft.fwd(out, row);
      std::copy(out.begin(), out.end(), spec.begin() + std::ptrdiff_t(size_t(y) * size_t(half)));
    }
  });
  // Columns: complex → complex, then the power of each bin into its octave. The other half of
  // the plane mirrors this one (a real image: F(−k) = conj F(k)), so 0 < kx < W/2 counts twice.
  const double k0 = std::log2(bands.front().lo_cycles_per_cm);
  const size_t nb = bands.size();
  std::vector<double> column_power(size_t(half) * nb, 0.0);  // summed in a fixed order below: reproducible
  tbb::parallel_for(tbb::blocked_range<int>(0, half, 4), [&](const tbb::blocked_range<int>& r) {
    Eigen::FFT<float>& fft = ffts.local();
    std::vector<C> col(static_cast<size_t>(H)), out;
    for (int kx = r.begin(); kx < r.end(); ++kx) {
      for (int y = 0; y < H; ++y) col[size_t(y)] = spec[size_t(y) * size_t(half) + size_t(kx)];
      fft.fwd(out, col);
      double* p = &column_power[size_t(kx) * nb];
      const double fx = double(kx) / W * px_per_cm, mult = (kx == 0 || 2 * kx == W) ? 1 : 2;
      for (int ky = 0; ky < H; ++ky) {
        const double fy = double(ky <= H / 2 ? ky : ky - H) / H * px_per_cm;
        const double f = std::hypot(fx, fy);
        if (f <= 0) continue;
        const int b = int(std::floor(std::log2(f) - k0));
        if (b >= 0 && b < int(nb)) p[b] += mult * std::norm(out[size_t(ky)]);
      }
    }
  });
  std::vector<double> total_power(nb, 0.0);
  for (int kx = 0; kx < half; ++kx)
    for (size_t b = 0; b < nb; ++b) total_power[b] += column_power[size_t(kx) * nb + b];
  double total = 0;
  for (double p : total_power) total += p;
  if (total > 0)
    for (size_t b = 0; b < bands.size(); ++b) bands[b].share = total_power[b] / total;
  return bands;
}

}  // namespace phellem
