#include "bark/dressing/bark_relief.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/noise.h"

namespace phellem::bark {

namespace {

constexpr double kFar = 1e30;  // squared distance standing for "no fissure"

// Felzenszwalb & Huttenlocher 2012, "Distance Transforms of Sampled Functions", Algorithm 1:
// the lower envelope of parabolas (x − q·h)² + f(q) over samples spaced h apart.
void edt_1d(const std::vector<double>& f, double h, std::vector<double>& d) {
  const int n = int(f.size());
  std::vector<int> v(size_t(n), 0);
  std::vector<double> z(size_t(n) + 1, 0);
  d.assign(size_t(n), kFar);
  int k = -1;
  auto meet = [&](int q, int p) {  // where the parabolas of q and p intersect (in samples)
    return ((f[size_t(q)] / (h * h) + double(q) * q) - (f[size_t(p)] / (h * h) + double(p) * p)) / (2.0 * (q - p));
  };
  for (int q = 0; q < n; ++q) {
    if (f[size_t(q)] >= kFar) continue;
    if (k < 0) {
      v[0] = q;
      z[0] = -kFar;
      z[1] = kFar;
      k = 0;
      continue;
    }
    double s = meet(q, v[size_t(k)]);
    while (s <= z[size_t(k)]) s = meet(q, v[size_t(--k)]);  // z[0] = −∞ stops it
    ++k;
    v[size_t(k)] = q;
    z[size_t(k)] = s;
    z[size_t(k) + 1] = kFar;
  }
  if (k < 0) return;
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[size_t(j) + 1] < q) ++j;
    const double dq = (q - v[size_t(j)]) * h;
    d[size_t(q)] = dq * dq + f[size_t(v[size_t(j)])];
  }
}

double percentile(std::vector<double> x, double p) {
  const size_t i = std::min(x.size() - 1, size_t(p * double(x.size() - 1) + 0.5));
  std::nth_element(x.begin(), x.begin() + long(i), x.end());
  return x[i];
}

// Fissure (opening ≥ 0.5) and ridge (no fissure among the 8 neighbours) pixels.
void classify(const FractureField& f, std::vector<size_t>* fissure, std::vector<size_t>* ridge) {
  auto fis = [&](int x, int y) { return f.opening[f.index((x + f.width) % f.width, std::clamp(y, 0, f.height - 1))] >= 0.5f; };
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      if (fis(x, y)) {
        fissure->push_back(f.index(x, y));
        continue;
      }
      bool near = false;
      for (int dy = -1; dy <= 1 && !near; ++dy)
        for (int dx = -1; dx <= 1 && !near; ++dx) near = fis(x + dx, y + dy);
      if (!near) ridge->push_back(f.index(x, y));
    }
}

// Every `stride`-th entry, at most ~100k (percentiles of a bisection stay cheap).
std::vector<size_t> thin(const std::vector<size_t>& p) {
  const size_t stride = std::max<size_t>(1, p.size() / 100000);
  std::vector<size_t> out;
  for (size_t i = 0; i < p.size(); i += stride) out.push_back(p[i]);
  return out;
}

double ratio_of(const std::vector<double>& ridge_depth, const std::vector<double>& fissure_depth) {
  if (ridge_depth.empty() || fissure_depth.empty()) return 0;
  const double spread = percentile(ridge_depth, 0.9) - percentile(ridge_depth, 0.1);
  if (!(spread > 0)) return 0;
  // Heights are −depth: median ridge − median fissure height = median fissure − median ridge depth.
  return (percentile(fissure_depth, 0.5) - percentile(ridge_depth, 0.5)) / spread;
}

// Zero mean, unit RMS over `pixels` (all when empty).
void standardize(std::vector<float>& n, const std::vector<size_t>& pixels) {
  double s = 0, s2 = 0, c = 0;
  auto add = [&](size_t p) { s += n[p], s2 += double(n[p]) * n[p], ++c; };
  if (pixels.empty())
    for (size_t p = 0; p < n.size(); ++p) add(p);
  else
    for (size_t p : pixels) add(p);
  if (c == 0) return;
  const double mean = s / c, rms = std::sqrt(std::max(0.0, s2 / c - mean * mean));
  for (float& v : n) v = rms > 0 ? float((v - mean) / rms) : 0.0f;
}

}  // namespace

float tileable_fbm(double x, double y, double size, double period_x, double period_y, uint32_t seed) {
  double sum = 0, norm = 0, amp = 1;
  for (int o = 0; o < 4; ++o, amp *= 0.5) {
    const double cell = size / double(1 << o);
    // Cells fitted to a whole number per period: the lattice wraps exactly (util/noise.h).
    const int64_t nx = period_x > 0 ? std::max<int64_t>(1, std::llround(period_x / cell)) : 0;
    const int64_t ny = period_y > 0 ? std::max<int64_t>(1, std::llround(period_y / cell)) : 0;
    const double cx = nx > 0 ? period_x / double(nx) : cell, cy = ny > 0 ? period_y / double(ny) : cell;
    sum += amp * (2.0 * tileable_value_noise(x / cx, y / cy, seed + 7919u * uint32_t(o), nx, ny) - 1.0);
    norm += amp;
  }
  return float(sum / norm);
}

double depth_ratio(const FractureField& f) {
  std::vector<size_t> fis, rid;
  classify(f, &fis, &rid);
  std::vector<double> fd, rd;
  for (size_t p : fis) fd.push_back(f.depth[p]);
  for (size_t p : rid) rd.push_back(f.depth[p]);
  return ratio_of(rd, fd);
}

std::vector<float> fissure_distance(const FractureField& f) {
  const int W = f.width, H = f.height;
  const double dx = f.circumference / W, dy = f.length / H;
  std::vector<double> cols(size_t(W) * H);
  tbb::parallel_for(0, W, [&](int x) {
    std::vector<double> g(static_cast<size_t>(H)), d;
    for (int y = 0; y < H; ++y) g[size_t(y)] = f.opening[f.index(x, y)] >= 0.5f ? 0.0 : kFar;
    edt_1d(g, dy, d);
    for (int y = 0; y < H; ++y) cols[f.index(x, y)] = d[size_t(y)];
  });
  std::vector<float> out(size_t(W) * H);
  tbb::parallel_for(0, H, [&](int y) {
    // Around θ the row is periodic: three periods side by side, the middle one kept.
    std::vector<double> g(size_t(3 * W)), d;
    for (int i = 0; i < 3 * W; ++i) g[size_t(i)] = cols[f.index(i % W, y)];
    edt_1d(g, dx, d);
    for (int x = 0; x < W; ++x) {
      const double d2 = d[size_t(W + x)];
      out[f.index(x, y)] = d2 >= kFar * 0.5 ? std::numeric_limits<float>::infinity() : float(std::sqrt(d2));
    }
  });
  return out;
}

void roughen_walls(FractureField& f, const ReliefLook& look) {
  const int W = f.width, H = f.height;
  const double C = f.circumference, L = f.length;
  std::vector<size_t> inside;
  for (size_t p = 0; p < f.depth.size(); ++p)
    if (f.depth[p] > 0) inside.push_back(p);
  std::vector<float> wall(f.depth.size(), 0.0f);
  tbb::parallel_for(0, H, [&](int y) {
    for (int x = 0; x < W; ++x)
      wall[f.index(x, y)] = tileable_fbm((x + 0.5) / W * C, (y + 0.5) / H * L, look.wall_size, C, 0, look.seed + 1);
  });
  standardize(wall, inside);
  for (size_t p : inside) f.depth[p] = std::max(0.0f, f.depth[p] * (1.0f + float(look.wall_noise) * wall[p]));
}

namespace {
constexpr double kMaxReliefPerDepth = 2.0;
}  // namespace

ReliefResult apply_relief(FractureField& f, const ReliefLook& look, const DepthProfile& profile) {
  ReliefResult res;
  if (!look.enabled || f.width <= 0 || f.height <= 0) return res;
  const int W = f.width, H = f.height;
  const double C = f.circumference, L = f.length;
  const size_t n = size_t(W) * H;
  if (!look.ridges) {
    if (look.wall_noise > 0) roughen_walls(f, look);
    return res;
  }
  std::vector<size_t> fis, rid;
  classify(f, &fis, &rid);

  if (look.wall_noise > 0) roughen_walls(f, look);  // × (1 + 0 · n) is the identity
  std::vector<float> detail(n, 0.0f), drop(n);
  const bool with_detail = look.detail > 0;  // without, the fbm is multiplied by 0: skip it
  const std::vector<float> dist = fissure_distance(f);
  tbb::parallel_for(0, H, [&](int y) {
    const double s = (y + 0.5) / H * L;
    for (int x = 0; x < W; ++x) {
      const double a = (x + 0.5) / W * C;
      const size_t p = f.index(x, y);
      if (with_detail) detail[p] = tileable_fbm(a, s, look.detail_size, C, 0, look.seed + 2);
      const double t = std::min(1.0, double(dist[p]) / look.shoulder_width);
      drop[p] = float((1 - t) * (1 - t));  // the parabolic shoulder, 1 at the lip
    }
  });
  if (with_detail) standardize(detail, {});

  // The unit ridge relief: shoulder + detail, each with a P90 − P10 of about 1 (0.39 = 1/2.56,
  // the P90 − P10 of a unit normal). The shoulder merges into the fissure wall: the depth is
  // the deeper of the wall and the shoulder (continuous at the lip, where the wall is 0).
  std::vector<float> shoulder(n), fine(n);
  for (size_t p = 0; p < n; ++p) {
    shoulder[p] = float((1 - look.detail) * drop[p]);
    fine[p] = float(look.detail * 0.39 * detail[p]);
  }
  auto relief_depth = [&](size_t p, double k) { return std::max(double(f.depth[p]), k * shoulder[p]) + k * fine[p]; };

  const std::vector<size_t> fs = thin(fis), rs = thin(rid);
  auto ratio_at = [&](double k) {
    std::vector<double> fd, rd;
    fd.reserve(fs.size()), rd.reserve(rs.size());
    for (size_t p : fs) fd.push_back(relief_depth(p, k));
    for (size_t p : rs) rd.push_back(relief_depth(p, k));
    return ratio_of(rd, fd);
  };
  double k = profile.max_depth / look.depth_ratio;
  if (!fs.empty() && !rs.empty()) {
    // The ratio falls as the relief grows (fissure depth / ridge spread): geometric bisection.
    // At most twice the deepest fissure: a ratio out of reach must not raise ridges by
    // decimetres (kMaxReliefPerDepth).
    double lo = 1e-6 * profile.max_depth, hi = kMaxReliefPerDepth * profile.max_depth;
    if (ratio_at(hi) >= look.depth_ratio) {
      k = hi;
    } else {
      for (int i = 0; i < 48; ++i) {
        const double mid = std::sqrt(lo * hi);
        (ratio_at(mid) > look.depth_ratio ? lo : hi) = mid;
      }
      k = std::sqrt(lo * hi);
    }
  }
  for (size_t p = 0; p < n; ++p) f.depth[p] = float(relief_depth(p, k));
  res.scale = k;
  res.ratio = depth_ratio(f);
  return res;
}

}  // namespace phellem::bark
