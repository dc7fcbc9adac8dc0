#include "bark/growth/face_origin.h"

#include <stdexcept>

#include <tbb/parallel_for.h>

#include "bark/growth/triangle_tree.h"

namespace phellem::bark {

std::vector<uint32_t> nearest_input_faces(const TriMesh& input, const TriMesh& grown) {
  using namespace triangle_tree;
  if (input.triangles.empty()) throw std::invalid_argument("nearest_input_faces: the input has no faces");
  Triangles tris;
  tris.reserve(input.triangles.size());
  for (const auto& f : input.triangles)
    tris.emplace_back(cgal(input.positions[f[0]]), cgal(input.positions[f[1]]), cgal(input.positions[f[2]]));
  Tree tree(tris.begin(), tris.end());
  tree.accelerate_distance_queries();
  std::vector<uint32_t> out(grown.triangles.size());
  tbb::parallel_for(size_t(0), out.size(), [&](size_t k) {
    const auto& f = grown.triangles[k];
    const Eigen::Vector3d c = (grown.positions[f[0]] + grown.positions[f[1]] + grown.positions[f[2]]) / 3.0;
    out[k] = uint32_t(tree.closest_point_and_primitive(cgal(c)).second - tris.cbegin());
  });
  return out;
}

}  // namespace phellem::bark
