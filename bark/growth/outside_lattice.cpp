#include "bark/growth/outside_lattice.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "bark/growth/triangle_tree.h"

namespace phellem::bark {

using namespace triangle_tree;

namespace {

constexpr double kNudge = 0.01;

// Three values in [−1, 1) from a lattice point's index and its level (splitmix64).
Eigen::Vector3d nudge(uint64_t index, uint64_t level) {
  uint64_t x = index * 0x9E3779B97F4A7C15ull ^ level;
  Eigen::Vector3d v;
  for (int k = 0; k < 3; ++k) {
    x += 0x9E3779B97F4A7C15ull;
    uint64_t z = x;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    v[k] = double(z >> 11) / double(1ull << 52) - 1.0;
  }
  return v;
}

}  // namespace

std::vector<Eigen::Vector3d> outside_lattice(const std::vector<const TriMesh*>& meshes, const Eigen::Vector3d& lo,
                                             const Eigen::Vector3d& hi, double spacing) {
  std::vector<Eigen::Vector3d> out;
  Triangles triangles;
  for (const TriMesh* m : meshes)
    for (const auto& t : m->triangles)
      triangles.emplace_back(cgal(m->positions[t[0]]), cgal(m->positions[t[1]]), cgal(m->positions[t[2]]));
  if (triangles.empty() || !(spacing > 0)) return out;
  Tree tree(triangles.cbegin(), triangles.cend());
  tree.build();
  tree.accelerate_distance_queries();
  const Eigen::Vector3d extent = hi - lo;
  for (double h = spacing;; h *= 2) {
    const bool coarsest = 4 * h > extent.minCoeff();
    // A body-centred cubic lattice (the corners i·h from lo and the cube centres (i + ½)·h),
    // whose Delaunay tetrahedra are well shaped (a plain cubic lattice's are cospherical
    // eights: slivers); the centres of one level are corners of the next finer one, so the
    // levels nest and no two points come closer than `spacing`/2·√3.
    for (const double off : {0.0, 0.5}) {
      Eigen::Vector3i count;  // points (1 + i + off)·h, at least h/2 inside every face
      for (int k = 0; k < 3; ++k) count[k] = std::max(0, int(std::floor((extent[k] - 0.5 * h) / h - off)));
      const size_t n = size_t(count.x()) * size_t(count.y()) * size_t(count.z());
      auto point = [&](size_t i) {
        const size_t x = i % size_t(count.x()), y = (i / size_t(count.x())) % size_t(count.y()),
                     z = i / (size_t(count.x()) * size_t(count.y()));
        return Eigen::Vector3d(lo + h * Eigen::Vector3d(1 + off + double(x), 1 + off + double(y), 1 + off + double(z)));
      };
      std::vector<uint8_t> keep(n, 0);
      tbb::parallel_for(size_t(0), n, [&](size_t i) {
        const double d2 = CGAL::to_double(tree.squared_distance(cgal(point(i))));
        keep[i] = d2 >= h * h && (coarsest || d2 < 4 * h * h);
      });
      // Each point nudged by up to kNudge × h on each axis (a hash of its lattice index): a
      // lattice is full of coplanar and cospherical points, which trip TetGen's symbolic
      // perturbation (an assertion, not an error, in Debian's 1.5.0) once a grown interface
      // happens to share their planes.
      for (size_t i = 0; i < n; ++i)
        if (keep[i]) out.push_back(point(i) + kNudge * h * nudge(uint64_t(i) * 2 + uint64_t(off > 0), uint64_t(h * 1e9)));
    }
    if (coarsest) break;
  }
  return out;
}

}  // namespace phellem::bark
