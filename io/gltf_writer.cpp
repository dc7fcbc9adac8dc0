#include "io/gltf_writer.h"

#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>

#include "util/atomic_file.h"
#include "util/checked_write.h"
#include "util/errors.h"

namespace phellem {

namespace {

// Appends `bytes` to the single buffer as a new view and returns its index.
int add_view(tinygltf::Model& model, const void* data, size_t bytes, int target) {
  auto& buf = model.buffers[0].data;
  while (buf.size() % 4) buf.push_back(0);
  const size_t offset = buf.size();
  buf.resize(offset + bytes);
  std::memcpy(buf.data() + offset, data, bytes);
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = offset;
  v.byteLength = bytes;
  v.target = target;
  model.bufferViews.push_back(v);
  return int(model.bufferViews.size() - 1);
}

int add_accessor(tinygltf::Model& model, int view, int component, int type, size_t count, std::vector<double> min = {},
                 std::vector<double> max = {}) {
  tinygltf::Accessor a;
  a.bufferView = view;
  a.componentType = component;
  a.type = type;
  a.count = count;
  a.minValues = std::move(min);
  a.maxValues = std::move(max);
  model.accessors.push_back(a);
  return int(model.accessors.size() - 1);
}

}  // namespace

void write_glb(const std::string& path, const std::string& mesh_name, const GlbMesh& glb) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "phellem";
  model.buffers.emplace_back();
  tinygltf::Mesh mesh;
  mesh.name = mesh_name;
  // The vertex attributes, written once and shared by every part's primitive.
  const MeshData& m = glb.vertices;
  const size_t n = m.positions.size();
  std::map<std::string, int> attributes;
  std::vector<double> lo{1e30, 1e30, 1e30}, hi{-1e30, -1e30, -1e30};
  for (const Vec3f& p : m.positions)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], double(p[k]));
      hi[k] = std::max(hi[k], double(p[k]));
    }
  attributes["POSITION"] = add_accessor(model, add_view(model, m.positions.data(), n * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n, lo, hi);
  if (m.normals.size() == n)
    attributes["NORMAL"] = add_accessor(model, add_view(model, m.normals.data(), n * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  if (m.uvs.size() == n) {
    // glTF puts the texture origin at the top left: v is flipped.
    std::vector<Vec2f> uv(m.uvs);
    for (auto& t : uv) t.y() = 1.0f - t.y();
    attributes["TEXCOORD_0"] = add_accessor(model, add_view(model, uv.data(), n * 8, TINYGLTF_TARGET_ARRAY_BUFFER),
                                            TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n);
  }
  for (const auto& [name, values] : glb.scalars) {
    if (name.empty() || name[0] != '_' || values.size() != n) throw std::logic_error("write_glb: bad custom attribute " + name);
    attributes[name] = add_accessor(model, add_view(model, values.data(), n * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, n);
  }
  for (const auto& [name, values] : glb.vectors) {
    if (name.empty() || name[0] != '_' || values.size() != n) throw std::logic_error("write_glb: bad custom attribute " + name);
    attributes[name] = add_accessor(model, add_view(model, values.data(), n * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  }
  for (const GlbPart& part : glb.parts) {
    if (part.indices.empty()) continue;
    tinygltf::Material mat;
    mat.name = part.name;
    mat.pbrMetallicRoughness.baseColorFactor = {part.base_color[0], part.base_color[1], part.base_color[2], 1.0};
    mat.pbrMetallicRoughness.metallicFactor = 0.0;
    mat.pbrMetallicRoughness.roughnessFactor = part.roughness;
    mat.doubleSided = false;
    model.materials.push_back(mat);
    tinygltf::Primitive prim;
    prim.mode = part.lines ? TINYGLTF_MODE_LINE : TINYGLTF_MODE_TRIANGLES;
    prim.material = int(model.materials.size() - 1);
    prim.attributes = attributes;
    prim.indices =
        add_accessor(model, add_view(model, part.indices.data(), part.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, part.indices.size());
    mesh.primitives.push_back(prim);
  }
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = mesh_name;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  // Encoded in memory: tinygltf's own file writer reports success when it could not write.
  std::ostringstream bytes_out;
  tinygltf::TinyGLTF gltf;
  if (!gltf.WriteGltfSceneToStream(&model, bytes_out, false, true)) throw UserError(path, "write", "cannot encode the glTF binary");
  const std::string bytes = std::move(bytes_out).str();
  write_atomically(path, [&](const std::string& tmp) { write_file_checked(path, tmp, bytes); });
}

}  // namespace phellem
