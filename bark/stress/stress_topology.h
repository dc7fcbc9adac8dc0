// StressTopology: the connectivity the model's per-iteration passes need (forces, separation
// tensors, relaxation), flattened out of the half-edge mesh once per iteration, after the
// crack step (the only step that changes the mesh). Each face's corner i is "slot" 3f + i.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bark/stress/stress_mesh.h"

namespace phellem::bark {

struct StressTopology {
  std::vector<std::array<uint32_t, 3>> face_vertices;  // per face, in StressMesh::vertices(f) order
  std::vector<uint32_t> vertex_begin;                  // #V + 1: vertex v's slots are [begin[v], begin[v+1])
  std::vector<uint32_t> vertex_slots;                  // slots grouped by vertex, increasing within each

  static StressTopology build(const StressMesh& m);
  size_t faces() const { return face_vertices.size(); }
  size_t vertices() const { return vertex_begin.empty() ? 0 : vertex_begin.size() - 1; }
};

}  // namespace phellem::bark
