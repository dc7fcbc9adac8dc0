// Mesh files in: glTF 2.0 (.gltf/.glb, through tinygltf) and Wavefront OBJ (tinyobjloader).
// Node hierarchies are flattened into the returned meshes; materials come along.
#pragma once

#include <string>
#include <vector>

#include "bark/geometry/mesh_data.h"
#include "io/material_desc.h"

namespace phellem {

// A vertex attribute to read besides the geometry (glTF only), by name (e.g. "COLOR_0" or a
// custom "_GROWTH_SPEED"): the first component of any SCALAR to VEC4 accessor, or with `vec3`
// a VEC3 direction, turned by its node's transform like a position's offset.
struct AttributeRequest {
  std::string name;
  bool vec3 = false;
};

// The largest texture coordinate accepted (in OBJ and glTF files alike). Textures repeat every
// unit, and a float holds 24 bits: at 1e6 the spacing between floats is 1/16 of a repeat, so
// a lookup there lands only on one of 16 places in the texture; beyond, the texture is noise.
inline constexpr float kMaxUv = 1e6f;

struct LoadedModel {
  std::vector<MeshData> meshes;         // material indexes `materials` (-1: none)
  std::vector<MaterialDesc> materials;  // from the file (glTF PBR / OBJ MTL)
  // Per attribute asked for: its values over the vertices of every mesh in order (1 or 3 a vertex).
  std::vector<std::vector<float>> attributes;
};

// Every problem is a UserError naming the file and the glTF element (e.g.
// "meshes[0].primitives[1].indices") or OBJ line.
// `attributes`: vertex attributes every triangle primitive must carry (glTF; an OBJ file has
// none and is refused), read into LoadedModel::attributes.
LoadedModel load_mesh_file(const std::string& path, const std::vector<AttributeRequest>& attributes = {});
LoadedModel load_gltf(const std::string& path, const std::vector<AttributeRequest>& attributes = {});
LoadedModel load_obj(const std::string& path);

}  // namespace phellem
