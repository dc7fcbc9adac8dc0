#include "compare/distance_transform.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace phellem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Felzenszwalb & Huttenlocher 2012, Algorithm 1 (DT(f)): the lower envelope of the parabolas
// (q − p)² + f(p) rooted at the finite samples, then read at every q. f and d have n entries;
// v, fv (n) and z (n + 1) are scratch.
void distance_1d(const double* f, double* d, int n, std::vector<int>& v, std::vector<double>& z, std::vector<double>& fv) {
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

// The 2-D squared transform is a 1-D transform along columns, then along rows (F&H 2012, §2.2;
// the order is free). Along a column the input is binary (0 or +inf), so its 1-D transform is the
// squared distance to the nearest background pixel of the column: one downward and one upward
// sweep over whole rows (contiguous, no column gathering). The row pass is Algorithm 1.
std::vector<double> euclidean_distance_transform(const std::vector<uint8_t>& mask, int width, int height) {
  if (mask.size() != size_t(width) * size_t(height)) throw std::invalid_argument("euclidean_distance_transform: size mismatch");
  const size_t w = size_t(width);
  constexpr int32_t kNone = std::numeric_limits<int32_t>::max() / 2;  // no background above/below yet
  std::vector<int32_t> column(mask.size());                           // pixels to the nearest background pixel of the column
  for (int y = 0; y < height; ++y) {
    const uint8_t* m = &mask[size_t(y) * w];
    int32_t* d = &column[size_t(y) * w];
    const int32_t* above = y > 0 ? d - w : nullptr;
    for (size_t x = 0; x < w; ++x) d[x] = m[x] ? (above ? std::min(above[x] + 1, kNone) : kNone) : 0;
  }
  for (int y = height - 2; y >= 0; --y) {
    int32_t* d = &column[size_t(y) * w];
    const int32_t* below = d + w;
    for (size_t x = 0; x < w; ++x) d[x] = std::min(d[x], below[x] + 1);
  }
  std::vector<double> out(mask.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 16), [&](const tbb::blocked_range<int>& rows) {
    std::vector<int> v(w);
    std::vector<double> z(w + 1), fv(w), f(w);
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const int32_t* d = &column[size_t(y) * w];
      for (size_t x = 0; x < w; ++x) f[x] = d[x] >= kNone ? kInf : double(d[x]) * double(d[x]);
      double* o = &out[size_t(y) * w];
      distance_1d(f.data(), o, width, v, z, fv);
      for (size_t x = 0; x < w; ++x) o[x] = std::sqrt(o[x]);
    }
  });
  return out;
}

}  // namespace phellem
