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

namespace {

// Row y of the column pass: c[x] = Σ_j k_j·in(x, y + j), each tap weighing the sum of its two
// mirrored rows (the kernel is symmetric). Whole rows at a time: contiguous inner loops.
template <class T>
void column_pass(const std::vector<T>& in, int width, int height, int y, const std::vector<T>& k, BlurBorder border, T* c) {
  const size_t w = size_t(width);
  const int r = int(k.size() / 2);
  const T* mid = &in[size_t(y) * w];
  for (size_t x = 0; x < w; ++x) c[x] = k[size_t(r)] * mid[x];
  for (int j = 1; j <= r; ++j) {
    const T* up = &in[size_t(border_index(y - j, height, border)) * w];
    const T* dn = &in[size_t(border_index(y + j, height, border)) * w];
    const T kj = k[size_t(r + j)];
    for (size_t x = 0; x < w; ++x) c[x] += kj * (up[x] + dn[x]);
  }
}

template <class T>
std::vector<T> kernel_as(double sigma_px) {
  const std::vector<double> k = gaussian_kernel(sigma_px);
  return std::vector<T>(k.begin(), k.end());
}

}  // namespace

template <class T>
std::vector<T> gaussian_blur(const std::vector<T>& in, int width, int height, double sigma_px, BlurBorder border) {
  if (in.size() != size_t(width) * size_t(height)) throw std::invalid_argument("gaussian_blur: size mismatch");
  if (!(sigma_px > 0) || width == 0 || height == 0) return in;
  const std::vector<T> k = kernel_as<T>(sigma_px);
  const int r = int(k.size() / 2);
  const size_t w = size_t(width);
  std::vector<T> out(in.size());
  // Separable, both passes fused per output row (no full-image temporary): the column pass sums
  // whole input rows into one line (contiguous inner loops, the 2r + 1 rows stay in cache), the
  // line is extended by r border pixels each side, and the row pass reads it. The kernel is
  // symmetric, so each tap weighs the sum of its two mirrored samples. Rows in parallel.
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 4), [&](const tbb::blocked_range<int>& rows) {
    std::vector<T> line(w + 2 * size_t(r));
    T* c = line.data() + r;  // c[-r .. width + r)
    for (int y = rows.begin(); y < rows.end(); ++y) {
      column_pass(in, width, height, y, k, border, c);
      for (int x = -r; x < 0; ++x) c[x] = c[border_index(x, width, border)];
      for (int x = width; x < width + r; ++x) c[x] = c[border_index(x, width, border)];
      T* o = &out[size_t(y) * w];
      for (size_t x = 0; x < w; ++x) o[x] = k[size_t(r)] * c[x];
      for (int j = 1; j <= r; ++j) {
        const T kj = k[size_t(r + j)];
        const T* left = c - j;
        const T* right = c + j;
        for (size_t x = 0; x < w; ++x) o[x] += kj * (left[x] + right[x]);
      }
    }
  });
  return out;
}

template <class T>
std::vector<T> gaussian_blur_columns(const std::vector<T>& in, int width, int height, double sigma_px, BlurBorder border) {
  if (in.size() != size_t(width) * size_t(height)) throw std::invalid_argument("gaussian_blur_columns: size mismatch");
  if (!(sigma_px > 0) || width == 0 || height == 0) return in;
  const std::vector<T> k = kernel_as<T>(sigma_px);
  std::vector<T> out(in.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 4), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) column_pass(in, width, height, y, k, border, &out[size_t(y) * size_t(width)]);
  });
  return out;
}

template <class T>
T gaussian_blur_row_at(const T* row, int width, int x, const std::vector<T>& k, BlurBorder border) {
  const int r = int(k.size() / 2);
  T o = k[size_t(r)] * row[x];
  for (int j = 1; j <= r; ++j)
    o += k[size_t(r + j)] * (row[border_index(x - j, width, border)] + row[border_index(x + j, width, border)]);
  return o;
}

template std::vector<float> gaussian_blur_columns(const std::vector<float>&, int, int, double, BlurBorder);
template float gaussian_blur_row_at(const float*, int, int, const std::vector<float>&, BlurBorder);
template std::vector<float> gaussian_blur(const std::vector<float>&, int, int, double, BlurBorder);
template std::vector<double> gaussian_blur(const std::vector<double>&, int, int, double, BlurBorder);

}  // namespace phellem
