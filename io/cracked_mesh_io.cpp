#include "io/cracked_mesh_io.h"

#include <cmath>

#include "io/gltf_reader.h"
#include "io/gltf_writer.h"

namespace phellem {

void write_cracked_glb(const std::string& path, const std::string& name, const bark::CrackedMesh& c,
                       const std::vector<std::pair<std::string, std::vector<float>>>& extra) {
  GlbMesh glb;
  MeshData& v = glb.vertices;
  const size_t n = c.mesh.positions.size();
  for (const auto& p : c.mesh.positions) v.positions.push_back(p.cast<float>());
  for (const auto& t : c.mesh.uvs) v.uvs.push_back(t.cast<float>());
  for (const auto& t : c.mesh.triangles) v.indices.insert(v.indices.end(), t.begin(), t.end());
  compute_vertex_normals(v);
  std::vector<float> component(n), dx(n), dy(n), dz(n);
  for (size_t k = 0; k < n; ++k) {
    component[k] = float(c.component[k]);
    dx[k] = c.displacement[k].x();
    dy[k] = c.displacement[k].y();
    dz[k] = c.displacement[k].z();
  }
  glb.scalars = {{"_CRACK_WIDTH", c.crack_width},
                 {"_CRACK_COMPONENT", component},
                 {"_DISPLACEMENT_X", dx},
                 {"_DISPLACEMENT_Y", dy},
                 {"_DISPLACEMENT_Z", dz}};
  glb.scalars.insert(glb.scalars.end(), extra.begin(), extra.end());
  GlbPart bark{"bark", v.indices, Color(0.45f, 0.36f, 0.27f), 0.8f};
  GlbPart cracks{"cracks", {}, Color(0.05f, 0.03f, 0.02f), 1.0f};
  cracks.lines = true;
  for (const auto& e : c.crack_edges) cracks.indices.insert(cracks.indices.end(), e.begin(), e.end());
  glb.parts = {bark, cracks};
  write_glb(path, name, glb);
}

bark::CrackedMesh read_cracked_glb(const std::string& path) {
  const tinygltf::Model model = open_gltf(path);
  GltfReader rd(model, path);
  if (model.meshes.size() != 1)
    rd.fail("meshes", "a cracked mesh file holds exactly one mesh, found " + std::to_string(model.meshes.size()));
  const tinygltf::Mesh& mesh = model.meshes[0];
  bark::CrackedMesh out;
  bool have_triangles = false;
  for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
    const tinygltf::Primitive& prim = mesh.primitives[pi];
    const std::string where = "meshes[0].primitives[" + std::to_string(pi) + "]";
    auto attr = [&](const char* key) {
      const auto it = prim.attributes.find(key);
      if (it == prim.attributes.end())
        rd.fail(where + ".attributes", std::string("missing ") + key + " (not a Phellem cracked mesh?)");
      return it->second;
    };
    if (prim.indices < 0) rd.fail(where + ".indices", "missing");
    const std::vector<uint32_t> idx = rd.indices(prim.indices, where + ".indices");
    if (prim.mode == TINYGLTF_MODE_LINE) {
      if (idx.size() % 2) rd.fail(where + ".indices", "a LINES primitive needs an even number of indices");
      for (size_t k = 0; k < idx.size(); k += 2) out.crack_edges.push_back({idx[k], idx[k + 1]});
      continue;
    }
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;
    if (have_triangles) rd.fail(where, "a second triangle primitive; a cracked mesh has one");
    have_triangles = true;
    const std::vector<float> p = rd.floats(attr("POSITION"), 3, where + ".attributes.POSITION");
    const size_t n = p.size() / 3;
    const std::vector<float> width = rd.floats(attr("_CRACK_WIDTH"), 1, where + ".attributes._CRACK_WIDTH");
    const std::vector<float> comp = rd.floats(attr("_CRACK_COMPONENT"), 1, where + ".attributes._CRACK_COMPONENT");
    const std::vector<float> dx = rd.floats(attr("_DISPLACEMENT_X"), 1, where + ".attributes._DISPLACEMENT_X");
    const std::vector<float> dy = rd.floats(attr("_DISPLACEMENT_Y"), 1, where + ".attributes._DISPLACEMENT_Y");
    const std::vector<float> dz = rd.floats(attr("_DISPLACEMENT_Z"), 1, where + ".attributes._DISPLACEMENT_Z");
    for (const auto* a : {&width, &comp, &dx, &dy, &dz})
      if (a->size() != n) rd.fail(where + ".attributes", "custom attributes must have one value per position");
    for (size_t k = 0; k < n; ++k) {
      out.mesh.positions.emplace_back(p[3 * k], p[3 * k + 1], p[3 * k + 2]);
      out.crack_width.push_back(width[k]);
      if (comp[k] != std::floor(comp[k]) || comp[k] < -1)
        rd.fail(where + ".attributes._CRACK_COMPONENT", "must hold integers >= -1");
      out.component.push_back(int32_t(comp[k]));
      out.displacement.emplace_back(dx[k], dy[k], dz[k]);
    }
    if (const auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
      const std::vector<float> t = rd.uvs(it->second, where + ".attributes.TEXCOORD_0");
      if (t.size() != 2 * n) rd.fail(where + ".attributes.TEXCOORD_0", "must have one value per position");
      for (size_t k = 0; k < n; ++k) out.mesh.uvs.emplace_back(t[2 * k], 1.0 - t[2 * k + 1]);  // glTF's v points down
    }
    if (idx.size() % 3) rd.fail(where + ".indices", "a triangle primitive needs a multiple of 3 indices");
    for (size_t k = 0; k < idx.size(); k += 3) out.mesh.triangles.push_back({idx[k], idx[k + 1], idx[k + 2]});
  }
  if (!have_triangles) rd.fail("meshes[0]", "has no triangle primitive");
  const size_t n = out.mesh.positions.size();
  for (const auto& t : out.mesh.triangles)
    for (uint32_t k : t)
      if (k >= n) rd.fail("meshes[0]", "a triangle index is out of range");
  for (const auto& e : out.crack_edges)
    if (e[0] >= n || e[1] >= n) rd.fail("meshes[0]", "a crack edge index is out of range");
  return out;
}

}  // namespace phellem
