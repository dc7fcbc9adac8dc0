#include "bark/stress/stress_patterns.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "util/random.h"

namespace phellem::bark {

namespace {
constexpr double kPi = 3.141592653589793;

Eigen::Vector3d centroid(const StressMesh& m, FaceId f) {
  const auto vs = m.vertices(f);
  return (m.point(vs[0]) + m.point(vs[1]) + m.point(vs[2])) / 3.0;
}

Eigen::Vector2d centroid_uv(const StressMesh& m, FaceId f) {
  const auto cs = m.corners(f);
  return (m.uv(cs[0]) + m.uv(cs[1]) + m.uv(cs[2])) / 3.0;
}

// Bilinear sample of channel c at (u, v); u and v wrap (UV space tiles).
double sample(const StressImage& img, double u, double v, int c) {
  const double x = (u - std::floor(u)) * img.width - 0.5, y = (v - std::floor(v)) * img.height - 0.5;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  auto at = [&](int i, int j) {
    i = ((i % img.width) + img.width) % img.width;
    j = ((j % img.height) + img.height) % img.height;
    return double(img.values[(size_t(j) * size_t(img.width) + size_t(i)) * size_t(img.channels) + size_t(c)]);
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

// World directions of increasing u and v on face f (unit), from its corner UVs.
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> uv_tangents(const StressMesh& m, FaceId f) {
  const auto vs = m.vertices(f);
  const auto cs = m.corners(f);
  Eigen::Matrix<double, 3, 2> E;
  E.col(0) = m.point(vs[1]) - m.point(vs[0]);
  E.col(1) = m.point(vs[2]) - m.point(vs[0]);
  Eigen::Matrix2d D;
  D.col(0) = m.uv(cs[1]) - m.uv(cs[0]);
  D.col(1) = m.uv(cs[2]) - m.uv(cs[0]);
  if (!(std::abs(D.determinant()) > 1e-300)) return std::nullopt;
  const Eigen::Matrix<double, 3, 2> J = E * D.inverse();  // [∂p/∂u ∂p/∂v]
  if (!(J.col(0).norm() > 0) || !(J.col(1).norm() > 0)) return std::nullopt;
  return std::pair{J.col(0).normalized(), J.col(1).normalized()};
}

// Point q projected to the nearest face (closest centroid; faces are small next to strokes).
FaceId nearest_face(const std::vector<Eigen::Vector3d>& centroids, const Eigen::Vector3d& q) {
  double best = std::numeric_limits<double>::infinity();
  size_t bi = 0;
  for (size_t k = 0; k < centroids.size(); ++k)
    if (const double d = (centroids[k] - q).squaredNorm(); d < best) {
      best = d;
      bi = k;
    }
  return FaceId(static_cast<SurfaceMesh::size_type>(bi));
}

bool inside_uv(const StressMesh& m, FaceId f, const Eigen::Vector2d& q) {
  const auto cs = m.corners(f);
  const Eigen::Vector2d a = m.uv(cs[0]), b = m.uv(cs[1]), c = m.uv(cs[2]);
  auto cross = [](const Eigen::Vector2d& x, const Eigen::Vector2d& y) { return x.x() * y.y() - x.y() * y.x(); };
  const double d1 = cross(b - a, q - a), d2 = cross(c - b, q - b), d3 = cross(a - c, q - c);
  return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
}
}  // namespace

std::pair<Eigen::Vector3d, Eigen::Vector3d> horizontal_vertical(const Eigen::Vector3d& n) {
  Eigen::Vector3d h = Eigen::Vector3d::UnitY().cross(n);
  if (h.norm() < 1e-6) h = Eigen::Vector3d::UnitX() - n.x() * n;  // a horizontal face: x is "horizontal"
  h.normalize();
  return {h, n.cross(h).normalized()};
}

std::vector<FaceId> stroke_faces(const StressMesh& m, const StressStroke& s) {
  const SurfaceMesh& g = m.mesh();
  std::vector<FaceId> out;
  std::vector<Eigen::Vector3d> centroids;
  double mean_edge = 0;
  size_t edges = 0;
  for (EdgeId e : g.edges()) {
    mean_edge += (m.point(g.vertex(e, 0)) - m.point(g.vertex(e, 1))).norm();
    ++edges;
  }
  mean_edge /= double(std::max<size_t>(1, edges));
  if (!s.in_uv) {
    centroids.reserve(g.number_of_faces());
    for (FaceId f : g.faces()) centroids.push_back(centroid(m, f));
  }
  // Walk the polyline in steps of a quarter of a face (3D) or of 1/4096 of the UV square.
  for (size_t k = 0; k + 1 < s.points.size(); ++k) {
    const Eigen::Vector3d a = s.points[k], b = s.points[k + 1];
    const double step = s.in_uv ? 1.0 / 4096 : 0.25 * mean_edge;
    const int n = std::max(1, int(std::ceil((b - a).norm() / step)));
    for (int i = 0; i <= n; ++i) {
      const Eigen::Vector3d q = a + (b - a) * (double(i) / n);
      FaceId f = SurfaceMesh::null_face();
      if (s.in_uv) {
        if (!out.empty() && inside_uv(m, out.back(), q.head<2>())) continue;
        for (FaceId c : g.faces())
          if (inside_uv(m, c, q.head<2>())) {
            f = c;
            break;
          }
      } else {
        f = nearest_face(centroids, q);
      }
      if (f != SurfaceMesh::null_face() && (out.empty() || out.back() != f)) out.push_back(f);
    }
  }
  return out;
}

Eigen::Matrix2d face_curvature(const StressMesh& m, FaceId f) {
  const FaceState& s = m.face(f);
  const auto vs = m.vertices(f);
  Eigen::Matrix<double, 3, 2> dn = Eigen::Matrix<double, 3, 2>::Zero();
  for (int j = 0; j < 3; ++j) dn += m.vertex_normal(vs[size_t(j)]) * s.beta.row(j).leftCols<2>();
  const Eigen::Matrix2d k = s.frame.transpose() * dn;
  return 0.5 * (k + k.transpose());
}

// Growth: a surface pushed outward by δ stretches each tangent direction by δ times its normal
// curvature (an offset surface's strain is δ·II), so the tension follows II: a tube of any
// orientation is pulled around its girth and cracks along its length, like a trunk under the
// "horizontal" pattern; a saddle is compressed along its concave direction; a flat mesh gets
// no stress. The magnitude is s·II / max(κ₁, κ̄), κ₁ the face's largest principal curvature
// and κ̄ the median of κ₁ over the faces: s wherever the surface bends at least as much as
// usual, so the thin branches of a tree are not cracked first (bark tears with the relative
// growth of the girth, which the tree does not concentrate on its thinnest limbs), and
// proportionally less on flatter parts.
namespace {
std::vector<Eigen::Matrix2d> growth_stress(const StressMesh& m, double s) {
  const SurfaceMesh& g = m.mesh();
  std::vector<Eigen::Matrix2d> k;
  std::vector<double> largest;
  for (FaceId f : g.faces()) {
    k.push_back(face_curvature(m, f));
    largest.push_back(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(k.back(), Eigen::EigenvaluesOnly).eigenvalues()[1]);
  }
  if (largest.empty()) return k;
  std::vector<double> sorted = largest;
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (size_t f = 0; f < k.size(); ++f) {
    const double scale = std::max(largest[f], median);
    k[f] = scale > 0 ? Eigen::Matrix2d(s / scale * k[f]) : Eigen::Matrix2d::Zero();
  }
  return k;
}
}  // namespace

void initialize_stress(StressMesh& m, const StressParams& p) {
  const SurfaceMesh& g = m.mesh();
  const double s = p.magnitude;
  const std::vector<Eigen::Matrix2d> growth =
      p.pattern == StressPattern::Growth ? growth_stress(m, s) : std::vector<Eigen::Matrix2d>{};
  for (FaceId f : g.faces()) {
    FaceState& st = m.face(f);
    const auto [h, v] = horizontal_vertical(st.normal);
    Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
    switch (p.pattern) {
      case StressPattern::UniformTension:
      case StressPattern::Image:
        w = s * (st.frame * st.frame.transpose());
        break;
      case StressPattern::Horizontal:
        w = s * h * h.transpose();
        break;
      case StressPattern::Vertical:
        w = s * v * v.transpose();
        break;
      case StressPattern::Mixed:
        w = s * (h * h.transpose() + p.mix_ratio * v * v.transpose());
        break;
      case StressPattern::Growth:
        w = st.frame * growth[f.idx()] * st.frame.transpose();
        break;
      case StressPattern::Strokes:
        break;
    }
    if (!p.image.empty() && m.has_uvs()) {
      const Eigen::Vector2d uv = centroid_uv(m, f);
      if (p.image.channels == 1) {
        w *= sample(p.image, uv.x(), uv.y(), 0);
      } else if (const auto t = uv_tangents(m, f)) {
        const auto& [tu, tv] = *t;
        const double suu = sample(p.image, uv.x(), uv.y(), 0), svv = sample(p.image, uv.x(), uv.y(), 1),
                     suv = sample(p.image, uv.x(), uv.y(), 2);
        w = s * (suu * tu * tu.transpose() + svv * tv * tv.transpose() + suv * (tu * tv.transpose() + tv * tu.transpose()));
      }
    }
    m.set_world_stress(f, w);
    if (p.random_rotation > 0) {  // RR: rotate the tensor in its plane by up to ±RR·π/2
      StreamRng rng(p.seed ^ 0x52520000ULL, f.idx(), 0);
      const double a = p.random_rotation * 0.5 * kPi * rng.symmetric();
      const Eigen::Matrix2d R = Eigen::Rotation2Dd(a).toRotationMatrix();
      st.sigma = R * st.sigma * R.transpose();
    }
  }
  // Strokes (sec. 3.3): the direction from each face to its n previous and next faces along
  // the stroke, averaged; the stress is the outer product of the in-plane orthogonal
  // direction, so the crack runs along the stroke. Later strokes overwrite earlier ones.
  double mean_edge = 0;
  for (EdgeId e : g.edges()) mean_edge += (m.point(g.vertex(e, 0)) - m.point(g.vertex(e, 1))).norm();
  mean_edge /= double(std::max<size_t>(1, g.number_of_edges()));
  std::vector<Eigen::Vector3d> centres;
  centres.reserve(g.number_of_faces());
  for (FaceId f : g.faces()) centres.push_back(centroid(m, f));
  for (const StressStroke& stroke : p.strokes) {
    const std::vector<FaceId> faces = stroke_faces(m, stroke);
    std::vector<Eigen::Vector3d> dirs(faces.size(), Eigen::Vector3d::Zero());
    for (size_t k = 0; k < faces.size(); ++k) {
      const Eigen::Vector3d& ck = centres[faces[k].idx()];
      for (int j = 1; j <= std::max(1, stroke.smoothing); ++j) {
        if (k + size_t(j) < faces.size()) dirs[k] += (centres[faces[k + size_t(j)].idx()] - ck).normalized();
        if (k >= size_t(j)) dirs[k] += (ck - centres[faces[k - size_t(j)].idx()]).normalized();
      }
    }
    // The brush: each face near the stroke takes the direction of the nearest crossed face.
    const double radius = stroke.radius > 0 ? stroke.radius : 2 * mean_edge;
    for (FaceId f : g.faces()) {
      const Eigen::Vector3d& c = centres[f.idx()];
      double best = radius * radius;
      size_t nearest = faces.size();
      for (size_t k = 0; k < faces.size(); ++k)
        if (const double d = (centres[faces[k].idx()] - c).squaredNorm(); d <= best) {
          best = d;
          nearest = k;
        }
      if (nearest == faces.size()) continue;
      FaceState& st = m.face(f);
      Eigen::Vector3d dir = dirs[nearest] - dirs[nearest].dot(st.normal) * st.normal;
      if (!(dir.norm() > 0)) continue;
      const Eigen::Vector3d o = st.normal.cross(dir.normalized());
      m.set_world_stress(f, s * stroke.magnitude * o * o.transpose());
    }
  }
}

}  // namespace phellem::bark
