// Meshes out as glTF 2.0 binary (.glb, through tinygltf): one mesh whose parts share its
// vertices, one primitive per part, each with a metallic-roughness material of its base
// colour, so the file opens in Blender as is. Written atomically; a failure is a UserError
// naming the file.
#pragma once

#include <string>
#include <vector>

#include "bark/geometry/mesh_data.h"
#include "util/math.h"

namespace phellem {

struct GlbPart {
  std::string name;               // material name (e.g. "epidermis", "fracture")
  std::vector<uint32_t> indices;  // #F×3 into the mesh's vertices (lines: #E×2)
  Color base_color{0.5f, 0.5f, 0.5f};
  float roughness = 0.8f;
  bool lines = false;  // a LINES primitive (e.g. crack edges) instead of triangles
};

struct GlbMesh {
  MeshData vertices;  // positions, normals, uvs (optional); its indices are not written
  // Application-specific per-vertex scalars (glTF custom attributes: names start with "_").
  std::vector<std::pair<std::string, std::vector<float>>> scalars;
  // ... and per-vertex 3-vectors (VEC3 custom attributes, e.g. a painted _GROWTH_DIRECTION).
  std::vector<std::pair<std::string, std::vector<Vec3f>>> vectors;
  std::vector<GlbPart> parts;
  size_t triangle_count() const {
    size_t n = 0;
    for (const GlbPart& p : parts)
      if (!p.lines) n += p.indices.size() / 3;
    return n;
  }
};

void write_glb(const std::string& path, const std::string& mesh_name, const GlbMesh& mesh);

}  // namespace phellem
