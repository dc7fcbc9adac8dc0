#include "bark/geometry/procedural_meshes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "util/random.h"

namespace phellem::bark {

namespace {
constexpr double kPi = 3.141592653589793;

// Two triangles per quad of a grid of (cols + 1) × (rows + 1) vertices stored row by row,
// the diagonals alternating so that the grid has no preferred direction.
void grid_triangles(TriMesh& m, int cols, int rows) {
  auto id = [&](int i, int j) { return uint32_t(j * (cols + 1) + i); };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
}
}  // namespace

TriMesh jittered_sheet(int nx, int ny, double width, double height, double jitter, uint64_t seed) {
  TriMesh m;
  const double hx = width / nx, hy = height / ny;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      double x = i * hx, y = j * hy;
      if (i > 0 && i < nx && j > 0 && j < ny) {
        StreamRng rng(seed, uint64_t(j) * uint64_t(nx + 1) + uint64_t(i), 0);
        x += jitter * hx * rng.symmetric();
        y += jitter * hy * rng.symmetric();
      }
      m.positions.emplace_back(x, y, 0.0);
      m.uvs.emplace_back(x / width, y / height);
    }
  grid_triangles(m, nx, ny);
  return m;
}

TriMesh icosphere(int subdivisions, double radius) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> p = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& v : p) v.normalize();
  std::vector<std::array<uint32_t, 3>> f = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                            {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      auto [it, fresh] = mid.try_emplace({key.first, key.second}, uint32_t(p.size()));
      if (fresh) p.push_back((p[a] + p[b]).normalized());
      return it->second;
    };
    std::vector<std::array<uint32_t, 3>> g;
    for (const auto& tri : f) {
      const uint32_t a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
      g.push_back({tri[0], a, c});
      g.push_back({tri[1], b, a});
      g.push_back({tri[2], c, b});
      g.push_back({a, b, c});
    }
    f.swap(g);
  }
  TriMesh m;
  for (const auto& v : p) {
    m.positions.push_back(radius * v);
    m.uvs.emplace_back(0.5 + std::atan2(v.z(), v.x()) / (2 * kPi), std::acos(std::clamp(v.y(), -1.0, 1.0)) / kPi);
  }
  m.triangles = f;
  return m;
}

TriMesh cylinder_mesh(double radius, double height, int around, int along, double jitter, uint64_t seed) {
  return revolved_mesh([radius](double) { return radius; }, height, around, along, jitter, seed);
}

TriMesh log_mesh(double radius, double height, int around, int along, double jitter, uint64_t seed) {
  TriMesh m = cylinder_mesh(radius, height, around, along, jitter, seed);
  const int rings = std::max(1, int(std::lround(around / (2 * kPi))));  // ring spacing ≈ the side's spacing
  for (int end = 0; end < 2; ++end) {
    const double y = end ? height : 0.0;
    const Eigen::Vector3d up(0, end ? 1.0 : -1.0, 0);
    // Ring 0 is the side's edge row (its vertices i + row · (around + 1), i < around).
    std::vector<uint32_t> outer;
    for (int i = 0; i < around; ++i) outer.push_back(uint32_t(i + (end ? along : 0) * (around + 1)));
    for (int k = 1; k <= rings; ++k) {
      const double f = 1.0 - double(k) / rings;
      std::vector<uint32_t> inner;
      const int n = k == rings ? 1 : std::max(3, int(std::lround(around * f)));
      for (int i = 0; i < n; ++i) {
        const double th = 2 * kPi * (i + 0.5) / n;  // half a step past the outer ring's first vertex
        inner.push_back(uint32_t(m.positions.size()));
        m.positions.emplace_back(radius * f * std::cos(th), y, -radius * f * std::sin(th));
        m.uvs.emplace_back(th / (2 * kPi), (end ? 1.0 : 0.0) + up.y() * (1 - f) * radius / height);
      }
      // Zip the two rings together by angle: both lists of angles unwrapped to increase from
      // their first vertex (outer at 0, inner just past it), one turn each.
      auto unwrapped = [&](const std::vector<uint32_t>& ring) {
        std::vector<double> a;
        for (uint32_t v : ring) {
          double x = std::atan2(-m.positions[v].z(), m.positions[v].x());
          while (!a.empty() && x < a.back()) x += 2 * kPi;
          while (a.empty() && x < 0) x += 2 * kPi;
          a.push_back(x);
        }
        a.push_back(a.front() + 2 * kPi);
        return a;
      };
      const std::vector<double> A = unwrapped(outer), B = unwrapped(inner);
      const size_t na = outer.size(), nb = inner.size();
      for (size_t i = 0, j = 0; i < na || j < nb;) {
        std::array<uint32_t, 3> t;
        if (j == nb || (i < na && A[i + 1] <= B[j + 1])) {
          t = {outer[i], outer[(i + 1) % na], inner[j % nb]};
          ++i;
        } else {
          t = {outer[i % na], inner[(j + 1) % nb], inner[j]};
          ++j;
        }
        const Eigen::Vector3d nrm = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
        if (nrm.dot(up) < 0) std::swap(t[1], t[2]);
        if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) m.triangles.push_back(t);
      }
      outer = inner;
    }
  }
  return m;
}

TriMesh vase_mesh(double radius, double height, int around, int along, double jitter, uint64_t seed) {
  return revolved_mesh(
      [radius](double t) { return radius * (0.55 + 0.45 * std::sin(kPi * std::min(1.0, 1.15 * t)) + 0.25 * t * t); }, height,
      around, along, jitter, seed);
}

TriMesh revolved_mesh(const std::function<double(double)>& radius_at, double height, int around, int along, double jitter,
                      uint64_t seed) {
  TriMesh m;
  const double dt = 2 * kPi / around, dy = height / along;
  // Vertices (i, j), i in [0, around) (welded around), plus seam copies at i = around for UVs.
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i <= around; ++i) {
      const int iw = i % around;
      double th = iw * dt, y = j * dy;
      if (j > 0 && j < along) {
        StreamRng rng(seed, uint64_t(j) * uint64_t(around) + uint64_t(iw), 0);
        th += jitter * dt * rng.symmetric();
        y += jitter * dy * rng.symmetric();
      }
      const double radius = radius_at(y / height);
      m.positions.emplace_back(radius * std::cos(th), y, -radius * std::sin(th));
      m.uvs.emplace_back(double(i) / around, y / height);
    }
  grid_triangles(m, around, along);  // the seam copies at i = around weld to i = 0
  return m;
}

TriMesh torus_knot(int p, int q, double radius, double tube, int segments, int sides) {
  auto curve = [&](double t) {
    const double r = radius * (2 + std::cos(q * t)) / 3;
    return Eigen::Vector3d(r * std::cos(p * t), radius * std::sin(q * t) / 3, r * std::sin(p * t));
  };
  TriMesh m;
  for (int s = 0; s < segments; ++s) {
    const double t = 2 * kPi * s / segments, e = 1e-4;
    const Eigen::Vector3d c = curve(t), T = (curve(t + e) - curve(t - e)).normalized();
    Eigen::Vector3d N = (curve(t + e) + curve(t - e) - 2 * c);
    N = (N - N.dot(T) * T).normalized();
    const Eigen::Vector3d B = T.cross(N);
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * kPi * k / sides;
      m.positions.push_back(c + tube * (std::cos(a) * N + std::sin(a) * B));
      m.uvs.emplace_back(double(s) / segments, double(k) / sides);
    }
  }
  for (int s = 0; s < segments; ++s)
    for (int k = 0; k < sides; ++k) {
      const uint32_t a = uint32_t(s * sides + k), b = uint32_t(((s + 1) % segments) * sides + k);
      const uint32_t c = uint32_t(((s + 1) % segments) * sides + (k + 1) % sides), d = uint32_t(s * sides + (k + 1) % sides);
      m.triangles.push_back({a, c, b});
      m.triangles.push_back({a, d, c});
    }
  return m;
}

}  // namespace phellem::bark
