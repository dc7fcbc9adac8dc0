#include "compare/distance_transform.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace phellem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Felzenszwalb & Huttenlocher 2012, Algorithm 1 (DT(f)): the lower envelope of the parabolas
// (q − p)² + f(p) rooted at the finite samples, then read at every q. f and d have n entries;
// v, fv (n) and z (n + 1) are scratch.
void distance_1d(const double* f, double* d, int n, std::vector<int>& v, std::vector<double>& z,
                 std::vector<double>& fv) {
  int k = -1;
  for (int q = 0; q < n; ++q) {
    const double fq = f[q];
    if (fq == kInf) continue;  // no parabola at +inf samples
    if (k < 0) {
      k = 0;
      v[0] = q;
      fv[0] = fq;
      z[0] = -kInf;
      z[1] = kInf;
      continue;
    }
    double s;
    // Intersection of the parabolas rooted at q and at v[k] (eq. in §2.1 of the paper).
    while ((s = ((fq + double(q) * q) - (fv[size_t(k)] + double(v[size_t(k)]) * v[size_t(k)])) /
                (2.0 * q - 2.0 * v[size_t(k)])) <= z[size_t(k)])
      --k;  // z[0] = −inf stops the loop at k = 0
    ++k;
    v[size_t(k)] = q;
    fv[size_t(k)] = fq;
    z[size_t(k)] = s;
    z[size_t(k) + 1] = kInf;
  }
  if (k < 0) {
    for (int q = 0; q < n; ++q) d[q] = kInf;
    return;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[size_t(k) + 1] < q) ++k;
    const double dq = q - v[size_t(k)];
    d[q] = dq * dq + fv[size_t(k)];
  }
}

}  // namespace

// The 2-D squared transform is the 1-D one along rows, then along columns (F&H 2012, §2.2).
std::vector<double> euclidean_distance_transform(const std::vector<uint8_t>& mask, int width, int height) {
  if (mask.size() != size_t(width) * size_t(height)) throw std::invalid_argument("euclidean_distance_transform: size mismatch");
  const size_t w = size_t(width);
  std::vector<double> f(mask.size()), g(mask.size());
  for (size_t i = 0; i < mask.size(); ++i) f[i] = mask[i] ? kInf : 0.0;
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 16), [&](const tbb::blocked_range<int>& rows) {
    std::vector<int> v(w);
    std::vector<double> z(w + 1), fv(w);
    for (int y = rows.begin(); y < rows.end(); ++y) distance_1d(&f[size_t(y) * w], &g[size_t(y) * w], width, v, z, fv);
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, width, 16), [&](const tbb::blocked_range<int>& cols) {
    const size_t h = size_t(height);
    std::vector<int> v(h);
    std::vector<double> z(h + 1), fv(h), col(h), out(h);
    for (int x = cols.begin(); x < cols.end(); ++x) {
      for (size_t y = 0; y < h; ++y) col[y] = g[y * w + size_t(x)];  // gathered: the strided pass stays cache-friendly
      distance_1d(col.data(), out.data(), height, v, z, fv);
      for (size_t y = 0; y < h; ++y) f[y * w + size_t(x)] = std::sqrt(out[y]);
    }
  });
  return f;
}

}  // namespace phellem
