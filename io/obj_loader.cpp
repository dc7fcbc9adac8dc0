#include <tiny_obj_loader.h>

#include <filesystem>

#include "util/errors.h"
#include "io/mesh_io.h"

namespace phellem {

LoadedModel load_obj(const std::string& path) {
  tinyobj::ObjReaderConfig cfg;
  cfg.triangulate = true;
  cfg.mtl_search_path = std::filesystem::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, cfg)) {
    std::string e = reader.Error();
    while (!e.empty() && e.back() == '\n') e.pop_back();
    throw UserError(path, "read", "invalid OBJ: " + (e.empty() ? std::string("unreadable file") : e));
  }
  const auto& attrib = reader.GetAttrib();
  LoadedModel out;
  for (size_t i = 0; i < reader.GetMaterials().size(); ++i) {
    const auto& m = reader.GetMaterials()[i];
    MaterialDesc d;
    d.name = m.name;
    d.where = {path, "material " + m.name};
    d.type = MaterialType::Diffuse;
    d.base_color = Color(m.diffuse[0], m.diffuse[1], m.diffuse[2]).max(0.0f).min(1.0f);
    if (!m.diffuse_texname.empty()) {
      d.base_color_texture.file = (std::filesystem::path(cfg.mtl_search_path) / m.diffuse_texname).string();
      if (!std::filesystem::is_regular_file(d.base_color_texture.file))
        throw UserError(path, "material " + m.name + ": map_Kd", "texture not found: " + d.base_color_texture.file);
    }
    out.materials.push_back(d);
  }
  const size_t nv = attrib.vertices.size() / 3;
  for (size_t si = 0; si < reader.GetShapes().size(); ++si) {
    const auto& shape = reader.GetShapes()[si];
    const std::string where = "shape " + (shape.name.empty() ? std::to_string(si) : shape.name);
    MeshData md;
    md.material = shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids[0];
    const bool has_n = !attrib.normals.empty(), has_t = !attrib.texcoords.empty();
    for (const auto& idx : shape.mesh.indices) {
      if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= nv) throw UserError(path, where, "vertex index out of range");
      const float* p = &attrib.vertices[3 * idx.vertex_index];
      md.positions.emplace_back(p[0], p[1], p[2]);
      if (has_n && idx.normal_index >= 0 && size_t(idx.normal_index) < attrib.normals.size() / 3) {
        const float* n = &attrib.normals[3 * idx.normal_index];
        md.normals.emplace_back(Vec3f(n[0], n[1], n[2]).normalized());
      }
      if (has_t && idx.texcoord_index >= 0 && size_t(idx.texcoord_index) < attrib.texcoords.size() / 2) {
        const float* t = &attrib.texcoords[2 * idx.texcoord_index];
        md.uvs.emplace_back(t[0], t[1]);
      }
      md.indices.push_back(uint32_t(md.indices.size()));
    }
    if (md.normals.size() != md.positions.size()) md.normals.clear();
    if (md.uvs.size() != md.positions.size()) md.uvs.clear();
    for (const auto& p : md.positions)
      if (!p.allFinite()) throw UserError(path, where, "non-finite vertex position");
    if (md.normals.empty()) compute_vertex_normals(md);
    compute_tangents(md);
    if (!md.indices.empty()) out.meshes.push_back(std::move(md));
  }
  if (out.meshes.empty()) throw UserError(path, "faces", "the file contains no faces");
  return out;
}

}  // namespace phellem
