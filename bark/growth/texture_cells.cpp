#include "bark/growth/texture_cells.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "bark/geometry/uv_seams.h"

namespace phellem::bark {

namespace {

// The texture Jacobian's columns ∂x/∂u, ∂x/∂v of a face and its area; false when its UVs or its
// positions are degenerate.
bool face_jacobian(const TriMesh& m, const std::array<uint32_t, 3>& f, Eigen::Vector3d* du, Eigen::Vector3d* dv, double* area) {
  const Eigen::Vector3d e1 = m.positions[f[1]] - m.positions[f[0]], e2 = m.positions[f[2]] - m.positions[f[0]];
  const Eigen::Vector2d t1 = m.uvs[f[1]] - m.uvs[f[0]], t2 = m.uvs[f[2]] - m.uvs[f[0]];
  const double det = t1.x() * t2.y() - t1.y() * t2.x();
  if (!(std::abs(det) > 1e-14)) return false;
  // [e1 e2] = J [t1 t2]  =>  J = [e1 e2] [t1 t2]^-1
  *du = (e1 * t2.y() - e2 * t1.y()) / det;
  *dv = (e2 * t1.x() - e1 * t2.x()) / det;
  *area = 0.5 * e1.cross(e2).norm();
  return du->allFinite() && dv->allFinite() && du->norm() > 0 && dv->norm() > 0 && *area > 0;
}

bool face_scale(const TriMesh& m, const std::array<uint32_t, 3>& f, Eigen::Vector2d* scale) {
  Eigen::Vector3d du, dv;
  double area;
  if (!face_jacobian(m, f, &du, &dv, &area)) return false;
  *scale = Eigen::Vector2d(du.norm(), dv.norm());
  return true;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

TextureScaleField::TextureScaleField(const TriMesh& start_in) {
  if (!start_in.has_uvs()) return;
  const TriMesh start = cut_uv_seams(start_in);
  std::vector<double> su, sv;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  for (const auto& f : start.triangles) {
    Face face;
    if (!face_scale(start, f, &face.scale)) continue;
    face.a = start.uvs[f[0]], face.b = start.uvs[f[1]], face.c = start.uvs[f[2]];
    if (!face.a.allFinite() || !face.b.allFinite() || !face.c.allFinite()) continue;
    lo = lo.cwiseMin(face.a).cwiseMin(face.b).cwiseMin(face.c);
    hi = hi.cwiseMax(face.a).cwiseMax(face.b).cwiseMax(face.c);
    su.push_back(face.scale.x());
    sv.push_back(face.scale.y());
    faces_.push_back(face);
  }
  if (faces_.empty()) return;
  median_ = Eigen::Vector2d(median_of(su), median_of(sv));
  // A uniform grid over the UV box, about one face per cell.
  const int n = std::clamp(int(std::sqrt(double(faces_.size()))), 1, 2048);
  nx_ = ny_ = n;
  lo_ = lo;
  cell_ = ((hi - lo) / double(n)).cwiseMax(Eigen::Vector2d::Constant(1e-12));
  grid_.resize(size_t(nx_) * size_t(ny_));
  for (uint32_t k = 0; k < faces_.size(); ++k) {
    const Face& f = faces_[k];
    const Eigen::Vector2d a = f.a.cwiseMin(f.b).cwiseMin(f.c), b = f.a.cwiseMax(f.b).cwiseMax(f.c);
    const int x0 = std::clamp(int((a.x() - lo_.x()) / cell_.x()), 0, nx_ - 1), x1 = std::clamp(int((b.x() - lo_.x()) / cell_.x()), 0, nx_ - 1);
    const int y0 = std::clamp(int((a.y() - lo_.y()) / cell_.y()), 0, ny_ - 1), y1 = std::clamp(int((b.y() - lo_.y()) / cell_.y()), 0, ny_ - 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) grid_[size_t(y) * size_t(nx_) + size_t(x)].push_back(k);
  }
}

const TextureScaleField::Face* TextureScaleField::containing(const Eigen::Vector2d& uv) const {
  const double fx = (uv.x() - lo_.x()) / cell_.x(), fy = (uv.y() - lo_.y()) / cell_.y();
  if (!(fx >= 0 && fy >= 0 && fx <= nx_ && fy <= ny_)) return nullptr;
  const int x = std::min(int(fx), nx_ - 1), y = std::min(int(fy), ny_ - 1);
  for (uint32_t k : grid_[size_t(y) * size_t(nx_) + size_t(x)]) {
    const Face& f = faces_[k];
    const double area = cross2(f.b - f.a, f.c - f.a);
    const double tol = -1e-9 * std::abs(area);
    const double w0 = cross2(f.b - uv, f.c - uv), w1 = cross2(f.c - uv, f.a - uv), w2 = cross2(f.a - uv, f.b - uv);
    if (area > 0 ? (w0 >= tol && w1 >= tol && w2 >= tol) : (w0 <= -tol && w1 <= -tol && w2 <= -tol)) return &f;
  }
  return nullptr;
}

Eigen::Vector2d TextureScaleField::at(const Eigen::Vector2d& uv) const {
  if (faces_.empty()) return Eigen::Vector2d::Zero();
  for (int dy : {0, -1, 1})
    for (int dx : {0, -1, 1})
      if (const Face* f = containing(uv + Eigen::Vector2d(dx, dy))) return f->scale;
  // Outside every start face (UVs that drifted past a border): the face whose UV centroid is
  // nearest, among those listed in the cell at the clamped position and its neighbours.
  const int x = std::clamp(int((uv.x() - lo_.x()) / cell_.x()), 0, nx_ - 1), y = std::clamp(int((uv.y() - lo_.y()) / cell_.y()), 0, ny_ - 1);
  const Face* best = nullptr;
  double best_d = 1e300;
  for (int yy = std::max(0, y - 1); yy <= std::min(ny_ - 1, y + 1); ++yy)
    for (int xx = std::max(0, x - 1); xx <= std::min(nx_ - 1, x + 1); ++xx)
      for (uint32_t k : grid_[size_t(yy) * size_t(nx_) + size_t(xx)]) {
        const Face& f = faces_[k];
        const double d = ((f.a + f.b + f.c) / 3.0 - uv).squaredNorm();
        if (d < best_d) best_d = d, best = &f;
      }
  return best ? best->scale : median_;
}

std::vector<Eigen::Vector2f> texture_cell_levels(const TriMesh& m, const TextureScaleField& start) {
  if (!m.has_uvs() || start.empty()) return {};
  // Per vertex, the area-weighted means of its faces' Jacobian columns (as vectors: the noise of
  // a lumpy grown surface and its carried UVs cancels, where the mean of their lengths would
  // grow with it) and of the start's scales at their UVs.
  const size_t n = m.positions.size();
  std::vector<Eigen::Vector3d> du_sum(n, Eigen::Vector3d::Zero()), dv_sum(n, Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector2d> then_sum(n, Eigen::Vector2d::Zero());
  for (const auto& f : m.triangles) {
    Eigen::Vector3d du, dv;
    double area;
    if (!face_jacobian(m, f, &du, &dv, &area)) continue;
    const Eigen::Vector2d then = start.at((m.uvs[f[0]] + m.uvs[f[1]] + m.uvs[f[2]]) / 3.0);
    if (!(then.minCoeff() > 0)) continue;
    for (uint32_t v : f) du_sum[v] += area * du, dv_sum[v] += area * dv, then_sum[v] += area * then;
  }
  std::vector<Eigen::Vector2f> out(n, Eigen::Vector2f::Zero());
  for (size_t v = 0; v < n; ++v) {
    if (!(then_sum[v].minCoeff() > 0)) continue;
    const Eigen::Vector2d level(std::log2(du_sum[v].norm() / then_sum[v].x()), std::log2(dv_sum[v].norm() / then_sum[v].y()));
    if (level.allFinite()) out[v] = level.cwiseMax(0.0).cwiseMin(kMaxTextureCellLevel).cast<float>();
  }
  return out;
}

}  // namespace phellem::bark
