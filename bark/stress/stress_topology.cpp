#include "bark/stress/stress_topology.h"

namespace phellem::bark {

StressTopology StressTopology::build(const StressMesh& m) {
  const SurfaceMesh& g = m.mesh();
  StressTopology t;
  const size_t nf = g.number_of_faces(), nv = g.number_of_vertices();
  t.face_vertices.resize(nf);
  t.vertex_begin.assign(nv + 1, 0);
  for (size_t f = 0; f < nf; ++f) {
    const auto vs = m.vertices(FaceId(static_cast<SurfaceMesh::size_type>(f)));
    for (int i = 0; i < 3; ++i) {
      t.face_vertices[f][size_t(i)] = uint32_t(vs[size_t(i)].idx());
      ++t.vertex_begin[vs[size_t(i)].idx() + 1];
    }
  }
  for (size_t v = 0; v < nv; ++v) t.vertex_begin[v + 1] += t.vertex_begin[v];
  t.vertex_slots.resize(3 * nf);
  std::vector<uint32_t> fill(t.vertex_begin.begin(), t.vertex_begin.end() - 1);
  for (size_t f = 0; f < nf; ++f)  // increasing slots per vertex
    for (size_t i = 0; i < 3; ++i) t.vertex_slots[fill[t.face_vertices[f][i]]++] = uint32_t(3 * f + i);
  return t;
}

}  // namespace phellem::bark
