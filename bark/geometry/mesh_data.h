// MeshData: an indexed triangle mesh with the per-vertex attributes the renderer shades with.
#pragma once

#include <cstdint>
#include <vector>

#include "util/math.h"

namespace phellem {

struct MeshData {
  std::vector<Vec3f> positions;     // #V
  std::vector<Vec3f> normals;       // #V or empty (then the geometric normal shades)
  std::vector<Vec2f> uvs;           // #V or empty
  std::vector<Vec4f> tangents;      // #V or empty: xyz tangent along +u, w = bitangent sign
  std::vector<Vec4f> params;        // #V or empty: (u, v) ∈ [0,1]² of a diced parametric surface (bark lookups)
  std::vector<float> displacement;  // #V or empty (diced surfaces only): offset along the base normal, m
  // #V or empty: a grown surface's texture cell levels along u and v (bark/growth/texture_cells.h):
  // its textures repeat 2^level times over the same UVs, so their cells keep their size.
  std::vector<Vec2f> texture_levels;
  std::vector<uint32_t> indices;    // #F×3, counter-clockwise seen from the front
  int material = -1;                // index into the render scene's materials; -1: object's

  size_t triangle_count() const { return indices.size() / 3; }
  size_t memory_bytes() const {
    return positions.capacity() * sizeof(Vec3f) + normals.capacity() * sizeof(Vec3f) + uvs.capacity() * sizeof(Vec2f) +
           params.capacity() * sizeof(Vec4f) + displacement.capacity() * sizeof(float) +
           texture_levels.capacity() * sizeof(Vec2f) + tangents.capacity() * sizeof(Vec4f) +
           indices.capacity() * sizeof(uint32_t);
  }
};

// Area-weighted vertex normals from the faces (used after displacement). With
// `weld_by_position`, vertices at the same position (split at a UV seam) share one normal
// from all their faces: the surface is smooth across the seam.
void compute_vertex_normals(MeshData& mesh, bool weld_by_position = false);
// The same normals for positions and indices held apart.
std::vector<Vec3f> vertex_normals(const std::vector<Vec3f>& positions, const std::vector<uint32_t>& indices,
                                  bool weld_by_position = false);
// Per-vertex tangents from UVs (for normal maps); no-op without UVs.
void compute_tangents(MeshData& mesh);

}  // namespace phellem
