// Meshes out as glTF 2.0 binary (.glb, through tinygltf): one primitive per part, each with
// a metallic-roughness material of its base colour, so the file opens in Blender as is.
// Written atomically; a failure is a UserError naming the file.
#pragma once

#include <string>
#include <vector>

#include "renderer/math.h"
#include "renderer/mesh.h"

namespace phellem {

struct GlbPart {
  std::string name;   // material name (e.g. "epidermis", "fracture")
  MeshData mesh;      // positions, normals, uvs (optional), indices
  Color base_color{0.5f, 0.5f, 0.5f};
  float roughness = 0.8f;
};

void write_glb(const std::string& path, const std::string& mesh_name, const std::vector<GlbPart>& parts);

}  // namespace phellem
