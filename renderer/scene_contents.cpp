#include "renderer/scene_contents.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <map>

#include "bark/growth/face_origin.h"
#include "io/mesh_io.h"
#include "scene/displacement.h"
#include "scene/mesh_source.h"
#include "scene/object_meshes.h"
#include "scene/tree_surface.h"
#include "util/errors.h"

namespace phellem {

namespace {

std::shared_ptr<MeshData> padded(MeshData m) {
  // Embree reads vertex buffers with 16-byte loads: keep one spare element after the end.
  m.positions.reserve(m.positions.size() + 1);
  return std::make_shared<MeshData>(std::move(m));
}

// An image displacement is looked up at the texture coordinates: a mesh without them cannot take one.
void require_texcoords(const ObjectDesc& o, const MeshData& m) {
  if (o.displacement.type == DisplacementDesc::Type::Image && m.uvs.empty())
    throw UserError(o.where.file, o.where.path + "/displacement",
                    "an image displacement is looked up at the mesh's texture coordinates, and " +
                        (o.file.empty() ? std::string("this mesh") : printable(o.file)) + " has none (export it with UVs)");
}

const ObjectBark& bark_of(const BarkResults& bark, size_t oi, const ObjectDesc& o) {
  const ObjectBark* b = bark.find(oi);
  if (!b)
    throw std::logic_error("object " + std::to_string(oi) + " (" + o.where.path +
                           "): bark not simulated before the render scene");
  return *b;
}

// Stress bark (mesh or tree): the cracked mesh, displaced by its cracks' V-profiles as real
// geometry, diced only where the cracks reach.
DicingJob stress_job(const SceneDesc& desc, const ObjectDesc& o, const ObjectBark& bark, int mat, int object_id) {
  const bark::CrackedMesh& cracked = *bark.cracked;
  MeshData base = to_mesh_data(cracked.mesh);
  if (o.type == ObjectType::Mesh) require_texcoords(o, base);
  base.texture_levels = bark.texture_levels;  // a grown surface's (sec. 4.6)
  compute_vertex_normals(base, true);  // one normal per position: seams shade (and displace) alike
  std::shared_ptr<const bark::CrackBarkSurface> surface = crack_surface(o, cracked);
  DicingJob j;
  j.material = mat;
  j.object_id = object_id;
  j.base = std::make_shared<MeshData>(std::move(base));
  // A mesh's own procedural displacement adds to the cracks (a tree's is already in its mesh);
  // it reaches everywhere, so the dicing is then uniform.
  const bool extra = o.type == ObjectType::Mesh && o.displacement.type != DisplacementDesc::Type::None;
  const DisplacementFn own = extra ? make_displacement(o.displacement) : DisplacementFn{};
  j.bark_disp = [surface, own](const Vec2f& uv, const Vec3f& p, const Vec3f& n, Vec4f* params) {
    bark::SurfacePoint sp;
    sp.position = p;
    sp.normal = n;
    const bark::BarkDisplacement d = surface->displace(sp);
    if (params) *params = d.attributes;
    return (own ? own(uv, p) : 0.0f) + d.offset;
  };
  if (desc.render.tessellation.crack_aware && !extra)
    j.refine = [surface](const Vec3f& a, const Vec3f& b) { return surface->reaches(a, b); };
  j.bark = surface;
  return j;
}

// The faces of `m` with each material as their own mesh (vertices renumbered), in the order
// of the materials.
std::vector<std::pair<int, MeshData>> split_by_material(const MeshData& m, const std::vector<int>& face_material) {
  std::map<int, MeshData> parts;
  std::map<int, std::vector<uint32_t>> renumber;
  for (size_t f = 0; f < face_material.size(); ++f) {
    MeshData& part = parts[face_material[f]];
    std::vector<uint32_t>& to = renumber[face_material[f]];
    if (to.empty()) to.assign(m.positions.size(), UINT32_MAX);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = m.indices[3 * f + size_t(k)];
      if (to[v] == UINT32_MAX) {
        to[v] = uint32_t(part.positions.size());
        part.positions.push_back(m.positions[v]);
        if (!m.normals.empty()) part.normals.push_back(m.normals[v]);
        if (!m.uvs.empty()) part.uvs.push_back(m.uvs[v]);
        if (!m.texture_levels.empty()) part.texture_levels.push_back(m.texture_levels[v]);
      }
      part.indices.push_back(to[v]);
    }
  }
  std::vector<std::pair<int, MeshData>> out;
  for (auto& [mat, part] : parts) {
    part.material = mat;
    out.emplace_back(mat, std::move(part));
  }
  return out;
}

}  // namespace

SceneContents load_scene_contents(const SceneDesc& desc, const BarkResults& bark, TextureStore& textures) {
  SceneContents c;
  // Materials: the scene's, then a default grey, then those of mesh files as they load.
  for (const auto& m : desc.materials) c.materials.push_back(compile_material(m, textures));
  const int default_material = int(c.materials.size());
  MaterialDesc grey;
  grey.name = "<default>";
  c.materials.push_back(compile_material(grey, textures));

  auto add_mesh = [&](MeshData m, int material, int object_id) {
    ScenePiece p;
    p.kind = ScenePiece::Kind::Mesh;
    p.mesh = padded(std::move(m));
    p.material = material;
    p.object_id = object_id;
    c.pieces.push_back(std::move(p));
  };
  auto add_job = [&](int material, int object_id, ParametricSurface surface, std::shared_ptr<const MeshData> base,
                     DisplacementFn disp, std::shared_ptr<const bark::BarkSurface> b) {
    DicingJob j;
    j.material = material;
    j.object_id = object_id;
    j.surface = std::move(surface);
    j.base = std::move(base);
    j.disp = std::move(disp);
    j.bark = std::move(b);
    c.jobs.push_back(std::move(j));
  };

  std::map<std::string, int> prototype_of_file;
  std::map<std::string, std::pair<LoadedModel, int>> models;  // file -> (model, first material index)
  auto model_of = [&](const std::string& file) -> const std::pair<LoadedModel, int>& {
    auto it = models.find(file);
    if (it == models.end()) {
      LoadedModel model = load_mesh_file(file);
      const int first = int(c.materials.size());
      for (const auto& md : model.materials) c.materials.push_back(compile_material(md, textures));
      it = models.emplace(file, std::make_pair(std::move(model), first)).first;
    }
    return it->second;
  };
  // A grown mesh file without a scene material keeps its parts' materials: each grown face
  // takes the material of the input face nearest to it (bark/growth/face_origin.h); empty when
  // the scene names a material or the file gives every part the same one.
  auto grown_face_materials = [&](const ObjectDesc& o, int default_material, const bark::TriMesh& grown) {
    std::vector<int> out;
    if (!o.growth || o.procedural || o.type != ObjectType::Mesh || !o.material.empty()) return out;
    const auto& [model, first] = model_of(o.file);
    std::vector<int> input_material;  // per input face, in object_trimesh's order (meshes in file order)
    for (const MeshData& m : model.meshes)
      input_material.insert(input_material.end(), m.triangle_count(), m.material >= 0 ? first + m.material : default_material);
    if (input_material.empty() ||
        std::all_of(input_material.begin(), input_material.end(), [&](int k) { return k == input_material[0]; })) {
      if (!input_material.empty()) out.assign(grown.triangles.size(), input_material[0]);
      return out;
    }
    for (uint32_t f : bark::nearest_input_faces(model_trimesh(model, o), grown)) out.push_back(input_material[f]);
    return out;
  };
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& o = desc.objects[oi];
    const int object_id = int(oi) + 1;
    const int mat = o.material.empty() ? default_material : desc.find_material(o.material);
    switch (o.type) {
      case ObjectType::Sphere: {
        if (c.materials[mat].emissive()) {  // area lights are triangles
          add_mesh(sphere_mesh(o.center, o.radius), mat, object_id);
          break;
        }
        ScenePiece p;
        p.kind = ScenePiece::Kind::Sphere;
        p.center = o.center;
        p.radius = o.radius;
        p.material = mat;
        p.object_id = object_id;
        c.pieces.push_back(std::move(p));
        break;
      }
      case ObjectType::Plane:
        add_mesh(plane_mesh(o), mat, object_id);
        break;
      case ObjectType::Patch:
        add_job(mat, object_id, patch_surface(o, make_displacement(o.displacement)), nullptr, nullptr, nullptr);
        break;
      case ObjectType::Tree: {
        if (o.stress_bark && !(o.growth && !o.growth->cracks)) {
          c.jobs.push_back(stress_job(desc, o, bark_of(bark, oi, o), mat, object_id));
          break;
        }
        if (o.growth) {  // the joined surface of its trunk and branches at the last step (world space)
          const ObjectBark& b = bark_of(bark, oi, o);
          MeshData w = to_mesh_data(*b.grown);
          w.texture_levels = b.texture_levels;
          compute_vertex_normals(w, true);  // seams cut for the UVs shade as one surface
          add_mesh(std::move(w), mat, object_id);
          break;
        }
        const DisplacementFn disp = make_displacement(o.tree.displacement);
        if (!o.tree.strip_bark) {
          for (auto& part : build_tree(o.tree, disp)) add_job(mat, object_id, part.surface, nullptr, nullptr, nullptr);
          break;
        }
        // Strip bark: the fracture depth displaces the surface inwards (true geometry) and the
        // dressed field shades it through the parts' (u, v), kept per vertex.
        const auto& surfaces = bark_of(bark, oi, o).strip_parts;
        auto parts = build_tree(o.tree, [&](size_t k) -> DisplacementFn {
          if (k >= surfaces.size()) return disp;
          std::shared_ptr<const bark::FieldBarkSurface> b = surfaces[k];
          return [b, disp](const Vec2f& uv, const Vec3f& p) {
            bark::SurfacePoint sp;
            sp.param = Eigen::Vector2d(uv.x(), uv.y() / b->length());
            sp.position = p;
            return disp(uv, p) + b->displace(sp).offset;
          };
        });
        for (size_t k = 0; k < parts.size(); ++k) {
          parts[k].surface.keep_params = true;
          add_job(mat, object_id, parts[k].surface, nullptr, nullptr, k < surfaces.size() ? surfaces[k] : nullptr);
        }
        break;
      }
      case ObjectType::Mesh: {
        if (o.stress_bark && !(o.growth && !o.growth->cracks)) {
          const ObjectBark& b = bark_of(bark, oi, o);
          DicingJob job = stress_job(desc, o, b, mat, object_id);
          const std::vector<int> face_mat = o.growth ? grown_face_materials(o, default_material, b.cracked->mesh) : std::vector<int>{};
          if (face_mat.empty()) {
            c.jobs.push_back(std::move(job));
            break;
          }
          // One job per material, sharing the cracks (the displacement is a function of position,
          // so the parts meet without a gap).
          for (auto& [part_mat, part] : split_by_material(*job.base, face_mat)) {
            DicingJob pj = job;
            pj.material = part_mat;
            pj.base = std::make_shared<MeshData>(std::move(part));
            c.jobs.push_back(std::move(pj));
          }
          break;
        }
        if (o.procedural || o.growth) {
          // A grown mesh is the surface of its last step (world space, as object_trimesh's).
          bark::TriMesh made;  // a procedural mesh's; a grown one is read where it is, not copied
          const bark::TriMesh& t = o.growth ? *bark_of(bark, oi, o).grown : (made = object_trimesh(o));
          MeshData w = to_mesh_data(t);
          if (o.growth) w.texture_levels = bark_of(bark, oi, o).texture_levels;
          compute_vertex_normals(w, o.growth != nullptr);  // a grown mesh's seams cut for the UVs shade as one surface
          const std::vector<int> face_mat = grown_face_materials(o, default_material, t);
          std::vector<std::pair<int, MeshData>> parts;
          if (face_mat.empty())
            parts.emplace_back(mat, std::move(w));
          else
            parts = split_by_material(w, face_mat);
          for (auto& [part_mat, part] : parts) {
            require_texcoords(o, part);
            if (o.displacement.type != DisplacementDesc::Type::None)
              add_job(part_mat, object_id, {}, std::make_shared<MeshData>(std::move(part)), make_displacement(o.displacement),
                      nullptr);
            else
              add_mesh(std::move(part), part_mat, object_id);
          }
          break;
        }
        const auto& [model, first_mat] = model_of(o.file);
        auto resolve = [&](const MeshData& m) {
          if (!o.material.empty()) return mat;
          return m.material >= 0 ? first_mat + m.material : default_material;
        };
        bool flatten = o.displacement.type != DisplacementDesc::Type::None;
        for (const auto& m : model.meshes) flatten = flatten || c.materials[resolve(m)].emissive();
        if (flatten) {  // displaced or emissive: the meshes in world space
          const Mat3f nrm = o.transform.matrix.topLeftCorner<3, 3>().inverse().transpose();
          for (const auto& m : model.meshes) {
            MeshData w = m;
            for (auto& p : w.positions) p = transform_point(o.transform.matrix, p);
            for (auto& n : w.normals) n = (nrm * n).normalized();
            for (auto& t : w.tangents) t.head<3>() = transform_vector(o.transform.matrix, t.head<3>()).normalized();
            if (w.normals.empty()) compute_vertex_normals(w);
            require_texcoords(o, w);
            if (o.displacement.type != DisplacementDesc::Type::None)
              add_job(resolve(m), object_id, {}, std::make_shared<MeshData>(std::move(w)), make_displacement(o.displacement),
                      nullptr);
            else
              add_mesh(std::move(w), resolve(m), object_id);
          }
          break;
        }
        // Instanced: one prototype per file, shared by every object that uses it.
        auto pit = prototype_of_file.find(o.file);
        if (pit == prototype_of_file.end()) {
          MeshPrototype proto;
          for (const auto& m : model.meshes) {
            proto.meshes.push_back(padded(m));
            proto.materials.push_back(m.material >= 0 ? first_mat + m.material : default_material);
            proto.triangles += m.triangle_count();
          }
          c.prototypes.push_back(std::move(proto));
          pit = prototype_of_file.emplace(o.file, int(c.prototypes.size() - 1)).first;
        }
        ScenePiece p;
        p.kind = ScenePiece::Kind::Instance;
        p.prototype = pit->second;
        p.xf = o.transform.matrix;
        p.material_override = o.material.empty() ? -1 : mat;
        p.object_id = object_id;
        c.pieces.push_back(std::move(p));
        break;
      }
    }
  }
  return c;
}

}  // namespace phellem
