// Mesh files in: glTF 2.0 (.gltf/.glb, through tinygltf) and Wavefront OBJ (tinyobjloader).
// Node hierarchies are flattened into the returned meshes; materials come along.
#pragma once

#include <string>
#include <vector>

#include "bark/geometry/mesh_data.h"
#include "io/material_desc.h"

namespace phellem {

struct LoadedModel {
  std::vector<MeshData> meshes;         // material indexes `materials` (-1: none)
  std::vector<MaterialDesc> materials;  // from the file (glTF PBR / OBJ MTL)
  // Per mesh, per vertex: the first component of the vertex attribute asked for by name (glTF
  // only, e.g. "COLOR_0" or a custom "_GROWTH_SPEED"), or with `attribute_vec3` its three
  // components (a VEC3 direction, turned by the node's transform like a position's offset);
  // empty when none was asked for.
  std::vector<std::vector<float>> attribute;
};

// Every problem is a UserError naming the file and the glTF element (e.g.
// "meshes[0].primitives[1].indices") or OBJ line.
// `attribute`: a vertex attribute every triangle primitive must carry (glTF; an OBJ file has
// none and is refused), read into LoadedModel::attribute.
LoadedModel load_mesh_file(const std::string& path, const std::string& attribute = {}, bool attribute_vec3 = false);
LoadedModel load_gltf(const std::string& path, const std::string& attribute = {}, bool attribute_vec3 = false);
LoadedModel load_obj(const std::string& path);

}  // namespace phellem
