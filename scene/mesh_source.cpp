#include "scene/mesh_source.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bark/geometry/branch_junction.h"
#include "bark/geometry/procedural_meshes.h"
#include "bark/geometry/tube_junctions.h"
#include "io/mesh_io.h"
#include "scene/displacement.h"
#include "scene/tree_surface.h"
#include "util/errors.h"

namespace phellem {

bark::BranchJunctionParams branch_junction_params(const ProceduralMeshDesc& p) {
  bark::BranchJunctionParams b;
  b.radius = p.radius;
  b.height = p.height;
  b.branch_radius = p.branch_radius > 0 ? double(p.branch_radius) : 0.6 * double(p.radius);
  b.branch_length = p.branch_length > 0 ? double(p.branch_length) : 4.0 * double(p.radius);
  b.branch_angle_deg = p.branch_angle_deg;
  b.branch_height = p.branch_height;
  b.triangles = p.triangles;
  b.jitter = p.jitter;
  b.seed = p.seed;
  return b;
}

ProceduralMeshDesc coarse_procedural(const ProceduralMeshDesc& p, int at_most) {
  ProceduralMeshDesc c = p;
  c.triangles = std::min(p.triangles, at_most);
  if (p.shape == "branch_junction")
    c.triangles = std::max(c.triangles, std::min(p.triangles, bark::branch_junction_least_triangles(branch_junction_params(p))));
  return c;
}

bark::TriMesh procedural_trimesh(const ProceduralMeshDesc& p) {
  const uint64_t seed = p.seed;
  const double n = std::max(20, p.triangles);
  if (p.shape == "branch_junction") return bark::branch_junction_mesh(branch_junction_params(p));
  if (p.shape == "trunk" || p.shape == "vase" || p.shape == "log") {
    // Quads about square: along / around ≈ height / circumference.
    const double aspect = p.height / (2 * double(kPi) * p.radius);
    const int around = std::max(3, int(std::lround(std::sqrt(n / 2 / aspect))));
    const int along = std::max(1, int(std::lround(n / 2 / around)));
    if (p.shape == "log") return bark::log_mesh(p.radius, p.height, around, along, p.jitter, seed);
    return p.shape == "trunk" ? bark::cylinder_mesh(p.radius, p.height, around, along, p.jitter, seed)
                              : bark::vase_mesh(p.radius, p.height, around, along, p.jitter, seed);
  }
  if (p.shape == "sheet") {
    const int k = std::max(1, int(std::lround(std::sqrt(n / 2))));
    return bark::jittered_sheet(k, k, p.height, p.height, p.jitter, seed);
  }
  if (p.shape == "sphere") {
    int s = 0;
    while (20.0 * std::pow(4.0, s + 1) <= n && s < 9) ++s;
    return bark::icosphere(s, p.radius);
  }
  // Torus knot (2, 3): rings of `sides` vertices, segments along the tube ≈ its length / spacing.
  const double length = 2 * double(kPi) * p.radius * 2.2;  // about the knot's length
  const int sides = std::max(3, int(std::lround(std::sqrt(n / 2 * 2 * double(kPi) * p.tube / length))));
  const int segments = std::max(3, int(std::lround(n / 2 / sides)));
  return bark::torus_knot(2, 3, p.radius, p.tube, segments, sides);
}

DicingParams tree_mesh_dicing(const ObjectDesc& o) {
  DicingParams d;
  d.screen_space = false;
  if (o.stress_bark && o.stress_bark->preprocess.edge_length > 0)
    d.target = o.stress_bark->preprocess.edge_length;
  else if (o.growth && o.growth->settings.edge_max > 0)
    d.target = o.growth->settings.edge_max / 1.5;  // the band's default maximum is 1.5 × the input's mean edge
  else
    d.target = 2 * double(kPi) * o.tree.radius.front() / 100;
  return d;
}

bark::TriMesh object_trimesh(const ObjectDesc& o) { return object_trimesh(o, {}, nullptr); }

namespace {

// The mesh moved into the scene by the object's transform.
bark::TriMesh transformed(bark::TriMesh t, const ObjectDesc& o) {
  const Eigen::Matrix4d T = o.transform.matrix.cast<double>();
  for (auto& p : t.positions) p = (T * p.homogeneous()).hnormalized();
  return t;
}

}  // namespace

bark::TriMesh model_trimesh(const LoadedModel& model, const ObjectDesc& o) {
  bark::TriMesh t;
  for (const MeshData& m : model.meshes) {
    const uint32_t base = uint32_t(t.positions.size());
    for (const Vec3f& p : m.positions) t.positions.push_back(p.cast<double>());
    for (size_t k = 0; k < m.positions.size(); ++k)
      t.uvs.push_back(m.uvs.size() == m.positions.size() ? Eigen::Vector2d(m.uvs[k].cast<double>()) : Eigen::Vector2d::Zero());
    for (size_t k = 0; k + 2 < m.indices.size(); k += 3)
      t.triangles.push_back({base + m.indices[k], base + m.indices[k + 1], base + m.indices[k + 2]});
  }
  return transformed(std::move(t), o);
}

bark::TriMesh object_trimesh(const ObjectDesc& o, const std::vector<AttributeRequest>& attributes,
                             std::vector<std::vector<float>>* values) {
  if (!attributes.empty() && (o.type != ObjectType::Mesh || o.procedural || !values))
    throw std::logic_error("object_trimesh: a vertex attribute needs a mesh file");
  bark::TriMesh t;
  if (o.type == ObjectType::Tree) {
    // The trunk and branches (with the tree's own displacement), each diced in object space
    // (tree_mesh_dicing).
    const std::vector<TreePart> parts = build_tree(o.tree, make_displacement(o.tree.displacement));
    const DicingParams d = tree_mesh_dicing(o);
    long long estimate = 0;
    for (const TreePart& part : parts) estimate += estimate_triangles(part.surface, d);
    if (estimate > 20'000'000)
      throw UserError(o.where.file, o.where.path + "/bark/preprocess/edge_length",
                      "an edge length of " + std::to_string(d.target) + " m would dice the tree into about " +
                          std::to_string(estimate) + " triangles; at most 20000000 are allowed");
    // Each part diced on its own, then joined at the branchings into one surface, so cracks
    // can run from the trunk into a branch.
    std::vector<bark::TriMesh> tubes;
    std::vector<int> parent;
    for (const TreePart& part : parts) {
      const MeshData m = dice(part.surface, d);
      bark::TriMesh& tube = tubes.emplace_back();
      for (const Vec3f& p : m.positions) tube.positions.push_back(p.cast<double>());
      for (size_t k = 0; k < m.positions.size(); ++k)
        tube.uvs.push_back(m.uvs.size() == m.positions.size() ? Eigen::Vector2d(m.uvs[k].cast<double>())
                                                              : Eigen::Vector2d::Zero());
      for (size_t k = 0; k + 2 < m.indices.size(); k += 3)
        tube.triangles.push_back({m.indices[k], m.indices[k + 1], m.indices[k + 2]});
      parent.push_back(part.parent);
    }
    bark::JoinedTubes joined = bark::join_tubes(tubes, parent);
    // A growing tree must be one closed surface: a branch kept apart would overlap its parent.
    if (o.growth && !joined.not_joined.empty())
      throw UserError(o.where.file, o.where.path + "/branches",
                      joined.not_joined.front() + "; a growing tree needs every branch joined to its parent");
    for (const std::string& why : joined.not_joined)
      std::fprintf(stderr, "phellem: warning: %s: %s: %s; cracks stop at that junction\n", o.where.file.c_str(),
                   o.where.path.c_str(), why.c_str());
    return std::move(joined.mesh);  // trees carry no transform
  }
  if (o.procedural) {
    return transformed(procedural_trimesh(*o.procedural), o);
  }
  LoadedModel model = load_mesh_file(o.file, attributes);
  t = model_trimesh(model, o);
  if (values) *values = std::move(model.attributes);
  const Eigen::Matrix3f L = o.transform.matrix.topLeftCorner<3, 3>();
  for (size_t k = 0; k < attributes.size(); ++k) {
    if (!attributes[k].vec3) continue;
    std::vector<float>& a = (*values)[k];
    for (size_t v = 0; v + 2 < a.size(); v += 3) {
      const Eigen::Vector3f d = L * Eigen::Vector3f(a[v], a[v + 1], a[v + 2]);
      for (int c = 0; c < 3; ++c) a[v + size_t(c)] = d[c];
    }
  }
  return t;
}

MeshData to_mesh_data(const bark::TriMesh& t) {
  MeshData m;
  for (const auto& p : t.positions) m.positions.push_back(p.cast<float>());
  for (const auto& u : t.uvs) m.uvs.push_back(u.cast<float>());
  for (const auto& tri : t.triangles) m.indices.insert(m.indices.end(), tri.begin(), tri.end());
  return m;
}

}  // namespace phellem
