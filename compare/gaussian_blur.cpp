#include "compare/gaussian_blur.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace phellem {

std::vector<double> gaussian_kernel(double sigma_px) {
  const int r = int(std::ceil(4 * sigma_px));  // radius ⌈4σ⌉ (plan §2)
  std::vector<double> k(size_t(2 * r + 1));
  double sum = 0;
  for (int i = -r; i <= r; ++i) sum += k[size_t(i + r)] = std::exp(-0.5 * (i * i) / (sigma_px * sigma_px));
  for (double& v : k) v /= sum;
  return k;
}

int border_index(int i, int n, BlurBorder border) {
  if (i >= 0 && i < n) return i;
  if (border == BlurBorder::clamp) return i < 0 ? 0 : n - 1;
  // Mirrored with the edge pixel repeated: period 2n, the second half reversed.
  const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
  return m < n ? m : 2 * n - 1 - m;
}

std::vector<double> gaussian_blur(const std::vector<double>& in, int width, int height, double sigma_px,
                                  BlurBorder border) {
  if (in.size() != size_t(width) * size_t(height)) throw std::invalid_argument("gaussian_blur: size mismatch");
  if (!(sigma_px > 0) || width == 0 || height == 0) return in;
  const std::vector<double> k = gaussian_kernel(sigma_px);
  const int r = int(k.size() / 2);
  const size_t w = size_t(width);
  std::vector<double> tmp(in.size()), out(in.size());
  // Separable: columns first (each output row is a weighted sum of whole input rows, so the
  // inner loop runs over contiguous memory), then rows. Rows in parallel.
  tbb::parallel_for(0, height, [&](int y) {
    double* o = &tmp[size_t(y) * w];
    const double* c = &in[size_t(y) * w];
    for (size_t x = 0; x < w; ++x) o[x] = k[size_t(r)] * c[x];
    for (int j = 1; j <= r; ++j) {
      const double* up = &in[size_t(border_index(y - j, height, border)) * w];
      const double* dn = &in[size_t(border_index(y + j, height, border)) * w];
      const double kj = k[size_t(r + j)];
      for (size_t x = 0; x < w; ++x) o[x] += kj * (up[x] + dn[x]);
    }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 8), [&](const tbb::blocked_range<int>& rows) {
    std::vector<double> buf(w + 2 * size_t(r));  // the row with ⌈4σ⌉ border pixels each side
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const double* t = &tmp[size_t(y) * w];
      for (int x = -r; x < width + r; ++x) buf[size_t(x + r)] = t[border_index(x, width, border)];
      double* o = &out[size_t(y) * w];
      const double* b = buf.data() + r;
      for (size_t x = 0; x < w; ++x) o[x] = k[size_t(r)] * b[x];
      for (int j = 1; j <= r; ++j) {
        const double kj = k[size_t(r + j)];
        const double* left = b - j;
        const double* right = b + j;
        for (size_t x = 0; x < w; ++x) o[x] += kj * (left[x] + right[x]);
      }
    }
  });
  return out;
}

}  // namespace phellem
