#include <tiny_gltf.h>

#include <filesystem>

#include "io/gltf_reader.h"
#include "io/mesh_io.h"
#include "util/cache_dir.h"
#include "util/errors.h"
#include "util/hash.h"
#include "util/input_file.h"

namespace phellem {

namespace {

namespace fs = std::filesystem;

// The node's local transform: `matrix` (16 numbers, column-major) or translation (3),
// rotation (4, a quaternion x y z w) and scale (3). Any other count is an error, not identity.
Mat4f node_matrix(const tinygltf::Node& n, const GltfReader& rd, const std::string& where) {
  auto check = [&](const std::vector<double>& v, size_t count, const char* key) {
    if (v.empty()) return;
    if (v.size() != count)
      rd.fail(where + "." + key, "must have " + std::to_string(count) + " numbers, has " + std::to_string(v.size()));
    for (double x : v)
      if (!std::isfinite(x) || std::abs(x) > 3.4e38) rd.fail(where + "." + key, "numbers must be finite floats");
  };
  check(n.matrix, 16, "matrix");
  check(n.translation, 3, "translation");
  check(n.rotation, 4, "rotation");
  check(n.scale, 3, "scale");
  Mat4f m = Mat4f::Identity();
  if (n.matrix.size() == 16) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m(r, c) = float(n.matrix[c * 4 + r]);  // column-major
    return m;
  }
  Eigen::Affine3f a = Eigen::Affine3f::Identity();
  if (n.translation.size() == 3) a.translate(Vec3f(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
  if (n.rotation.size() == 4)
    a.rotate(
        Eigen::Quaternionf(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])).normalized());
  if (n.scale.size() == 3) a.scale(Vec3f(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
  return a.matrix();
}

// Writes an embedded image to the texture cache and returns the file name.
std::string image_file(const tinygltf::Model& m, int tex_index, const std::string& gltf_path, const std::string& where) {
  if (tex_index < 0 || size_t(tex_index) >= m.textures.size())
    throw UserError(gltf_path, where, "texture index " + std::to_string(tex_index) + " out of range");
  const int src = m.textures[tex_index].source;
  if (src < 0 || size_t(src) >= m.images.size())
    throw UserError(gltf_path, "textures[" + std::to_string(tex_index) + "].source",
                    "image index " + std::to_string(src) + " out of range");
  const tinygltf::Image& img = m.images[src];
  const std::string img_where = "images[" + std::to_string(src) + "]";
  if (!img.uri.empty() && img.uri.rfind("data:", 0) != 0) {
    const fs::path p = fs::path(gltf_path).parent_path() / img.uri;
    std::error_code ec;
    if (!fs::exists(p, ec)) throw UserError(gltf_path, img_where + ".uri", "image file not found: " + p.string());
    require_input_file(p.string(), gltf_path, img_where + ".uri", "an image");
    return p.string();
  }
  if (img.image.empty()) throw UserError(gltf_path, img_where, "image has no data");
  // Named by a hash and the size of the bytes, and reused only when it holds these very bytes.
  uint32_t h = 0x1234u;
  for (unsigned char c : img.image) h = hash_combine(h, c);
  std::string ext = ".png";
  if (img.mimeType == "image/jpeg") ext = ".jpg";
  const std::string name = "gltf_" + std::to_string(h) + "_" + std::to_string(img.image.size()) + ext;
  return cache_entry_with_bytes(name, img.image, {gltf_path, img_where});
}

// The brightest emissiveStrength accepted. The glTF extension sets no maximum, but the
// radiance a sample carries is a float: 1e6 (a white surface a million times the brightness
// of emissiveFactor 1, brighter than the sun's disc against a unit sky) times the path
// throughput and a pixel's sum of samples stays far inside a float, and nothing a user
// lights a bark scene with comes near it.
constexpr double kMaxEmissiveStrength = 1e6;

// A number of a material that the glTF 2.0 schema bounds (its material factors lie in
// [0, 1]); `lo` and `hi` are the range allowed, `range` says it in the message.
void check_factor(const GltfReader& rd, const std::string& where, double v, double lo, double hi, const char* range) {
  if (!(v >= lo && v <= hi)) rd.fail(where, "must lie in " + std::string(range) + ", found " + std::to_string(v));
}

// A number from a material extension (tinygltf keeps extensions as untyped values).
double extension_number(const GltfReader& rd, const tinygltf::Value& v, const std::string& where) {
  if (!v.IsNumber()) rd.fail(where, "must be a number");
  return v.GetNumberAsDouble();
}

// The material's factors within the ranges glTF allows, checked before any is used (a
// negative, huge or non-finite factor would render as discarded samples or nonsense).
void check_material_factors(const GltfReader& rd, const tinygltf::Material& g, const std::string& where) {
  const auto& pbr = g.pbrMetallicRoughness;
  const std::string p = where + ".pbrMetallicRoughness";
  for (size_t k = 0; k < pbr.baseColorFactor.size(); ++k)
    check_factor(rd, p + ".baseColorFactor[" + std::to_string(k) + "]", pbr.baseColorFactor[k], 0, 1, "[0, 1]");
  check_factor(rd, p + ".metallicFactor", pbr.metallicFactor, 0, 1, "[0, 1]");
  check_factor(rd, p + ".roughnessFactor", pbr.roughnessFactor, 0, 1, "[0, 1]");
  for (size_t k = 0; k < g.emissiveFactor.size(); ++k)
    check_factor(rd, where + ".emissiveFactor[" + std::to_string(k) + "]", g.emissiveFactor[k], 0, 1, "[0, 1]");
  if (auto it = g.extensions.find("KHR_materials_emissive_strength"); it != g.extensions.end() && it->second.Has("emissiveStrength")) {
    const std::string at = where + ".extensions.KHR_materials_emissive_strength.emissiveStrength";
    check_factor(rd, at, extension_number(rd, it->second.Get("emissiveStrength"), at), 0, kMaxEmissiveStrength, "[0, 1e6]");
  }
  if (auto it = g.extensions.find("KHR_materials_specular"); it != g.extensions.end()) {
    const std::string at = where + ".extensions.KHR_materials_specular";
    if (it->second.Has("specularFactor"))
      check_factor(rd, at + ".specularFactor", extension_number(rd, it->second.Get("specularFactor"), at + ".specularFactor"), 0,
                   1, "[0, 1]");
    if (it->second.Has("specularColorFactor")) {
      // KHR_materials_specular lets the colour exceed 1 (it scales F0 = 0.04): non-negative
      // and finite as a float.
      const tinygltf::Value& c = it->second.Get("specularColorFactor");
      if (!c.IsArray() || c.ArrayLen() != 3) rd.fail(at + ".specularColorFactor", "must be an array of 3 numbers");
      for (int k = 0; k < 3; ++k) {
        const std::string ck = at + ".specularColorFactor[" + std::to_string(k) + "]";
        check_factor(rd, ck, extension_number(rd, c.Get(k), ck), 0, 3.4e38, "[0, 3.4e38]");
      }
    }
  }
}

MaterialDesc convert_material(const tinygltf::Model& m, int index, const std::string& path) {
  const tinygltf::Material& g = m.materials[index];
  const std::string where = "materials[" + std::to_string(index) + "]";
  check_material_factors(GltfReader(m, path), g, where);
  MaterialDesc d;
  d.name = g.name.empty() ? where : g.name;
  d.where = {path, where};
  const auto& pbr = g.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() >= 3)
    d.base_color = Color(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]), float(pbr.baseColorFactor[2]));
  d.roughness = float(pbr.roughnessFactor);
  d.type = pbr.metallicFactor >= 0.5 ? MaterialType::Conductor : MaterialType::Bark;
  // KHR_materials_specular: F0 = 0.04 × specularFactor × specularColorFactor for the default
  // IOR 1.5; our bark/dielectric-base layer has F0 = 0.08 × specular.
  if (auto it = g.extensions.find("KHR_materials_specular"); it != g.extensions.end()) {
    double factor = 1.0, color = 1.0;
    if (it->second.Has("specularFactor")) factor = it->second.Get("specularFactor").GetNumberAsDouble();
    if (it->second.Has("specularColorFactor")) {
      const auto& c = it->second.Get("specularColorFactor");
      color = 0;
      for (int k = 0; k < 3; ++k) color = std::max(color, c.Get(k).GetNumberAsDouble());
    }
    d.specular = float(std::min(1.0, 0.5 * factor * color));
  }
  if (pbr.baseColorTexture.index >= 0) {
    d.base_color_texture.file = image_file(m, pbr.baseColorTexture.index, path, where + ".pbrMetallicRoughness.baseColorTexture");
    d.base_color_texture.srgb = true;
  }
  if (g.normalTexture.index >= 0) {
    d.normal_texture.file = image_file(m, g.normalTexture.index, path, where + ".normalTexture");
    d.normal_texture.srgb = false;
  }
  // emissiveFactor in [0, 1]³ and emissiveStrength in [0, 1e6] (check_material_factors).
  if (g.emissiveFactor.size() == 3 && (g.emissiveFactor[0] > 0 || g.emissiveFactor[1] > 0 || g.emissiveFactor[2] > 0)) {
    d.type = MaterialType::Emissive;
    d.emission = Color(float(g.emissiveFactor[0]), float(g.emissiveFactor[1]), float(g.emissiveFactor[2]));
    auto it = g.extensions.find("KHR_materials_emissive_strength");
    if (it != g.extensions.end() && it->second.Has("emissiveStrength"))
      d.strength = float(it->second.Get("emissiveStrength").GetNumberAsDouble());
  }
  d.double_sided = g.doubleSided;
  return d;
}

// The nodes flattening starts from: the default (or first) scene's nodes, or in a file
// without scenes every node that is nobody's child; `where` names the list in messages.
struct Roots {
  std::vector<int> nodes;
  std::string where;
};
Roots scene_roots(const tinygltf::Model& model, const GltfReader& rd) {
  Roots r;
  if (!model.scenes.empty()) {
    const int si = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(si) >= model.scenes.size()) rd.fail("scene", "default scene index out of range");
    r.nodes = model.scenes[si].nodes;
    r.where = "scenes[" + std::to_string(si) + "].nodes";
    return r;
  }
  std::vector<bool> is_child(model.nodes.size(), false);
  for (const auto& n : model.nodes)
    for (int c : n.children)
      if (c >= 0 && size_t(c) < is_child.size()) is_child[c] = true;
  for (size_t n = 0; n < model.nodes.size(); ++n)
    if (!is_child[n]) r.nodes.push_back(int(n));
  r.where = "nodes";
  return r;
}

// Flattening copies a node's meshes once for every path from a root to it. glTF requires the
// nodes to form disjoint trees (each node has at most one parent), but a file whose nodes
// share children anyway makes a graph whose paths multiply: 40 nodes each listing the next
// one twice are 2^40 instances, which no machine holds. So what flattening would make is
// counted first, once per node (memoised), and refused beyond these bounds: far above any
// real model (a thousand instanced trees of a thousand nodes each), and below what exhausts
// memory (a loaded vertex takes about 50 bytes, an index 4).
constexpr uint64_t kMaxNodeInstances = 1'000'000;
constexpr uint64_t kMaxInstancedVertices = 100'000'000;
constexpr uint64_t kMaxInstancedIndices = 300'000'000;  // 100 million triangles
constexpr int kMaxNodeDepth = 64;

// What flattening one node (with its subtree) makes.
struct Expansion {
  uint64_t instances = 0, vertices = 0, indices = 0;
  void add(const Expansion& e) {
    // Each term is within its bound (checked at every node) and a file lists fewer than 2^32
    // children: no overflow.
    instances += e.instances;
    vertices += e.vertices;
    indices += e.indices;
  }
};

class ExpansionCount {
 public:
  ExpansionCount(const tinygltf::Model& m, const GltfReader& rd)
      : m_(m), rd_(rd), state_(m.nodes.size(), kNew), memo_(m.nodes.size()) {}

  // Node `ni`'s expansion, its subtree checked: indices in range, no cycle, at most
  // kMaxNodeDepth levels (which also bounds this recursion) and every bound kept. `referrer`
  // names the list that holds `ni`.
  Expansion node(int ni, int depth, const std::string& referrer) {
    if (ni < 0 || size_t(ni) >= m_.nodes.size())
      rd_.fail(referrer, "node index " + std::to_string(ni) + " out of range (file has " + std::to_string(m_.nodes.size()) +
                             " nodes)");
    const std::string where = "nodes[" + std::to_string(ni) + "]";
    if (state_[ni] == kDone) return memo_[ni];
    if (state_[ni] == kOpen)
      rd_.fail(referrer, "lists " + where + ", one of its own ancestors: the node hierarchy has a cycle (glTF nodes form trees)");
    if (depth > kMaxNodeDepth) rd_.fail(where, "node hierarchy deeper than " + std::to_string(kMaxNodeDepth) + " (cycle?)");
    state_[ni] = kOpen;
    const tinygltf::Node& n = m_.nodes[ni];
    Expansion e = mesh(n.mesh);
    e.instances = 1;
    for (int c : n.children) e.add(node(c, depth + 1, where + ".children"));
    check(e, where);
    state_[ni] = kDone;
    return memo_[ni] = e;
  }

  void check(const Expansion& e, const std::string& where) const {
    auto refuse = [&](uint64_t n, uint64_t max, const char* what) {
      if (n > max)
        rd_.fail(where, "flattening the node hierarchy from here makes " + std::to_string(n) + " " + what + "; at most " +
                            std::to_string(max) + " are allowed (a node listed as a child of several parents is copied " +
                            "for every path to it; glTF nodes form trees)");
    };
    refuse(e.instances, kMaxNodeInstances, "node instances");
    refuse(e.vertices, kMaxInstancedVertices, "vertices");
    refuse(e.indices, kMaxInstancedIndices, "vertex indices");
  }

 private:
  // One instance of mesh `mi`: its triangle primitives' vertices and indices, by their
  // accessors' counts (already checked against their buffers). Anything invalid counts 0 and
  // is left to the loader, which names it.
  Expansion mesh(int mi) const {
    Expansion e;
    if (mi < 0 || size_t(mi) >= m_.meshes.size()) return e;
    auto count = [&](int a) { return a >= 0 && size_t(a) < m_.accessors.size() ? uint64_t(m_.accessors[a].count) : 0; };
    for (const tinygltf::Primitive& p : m_.meshes[mi].primitives) {
      if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) continue;
      const auto pos = p.attributes.find("POSITION");
      const uint64_t nv = pos == p.attributes.end() ? 0 : count(pos->second);
      e.vertices += nv;
      e.indices += p.indices >= 0 ? count(p.indices) : nv;
    }
    return e;
  }

  enum State : unsigned char { kNew, kOpen, kDone };
  const tinygltf::Model& m_;
  const GltfReader& rd_;
  std::vector<State> state_;
  std::vector<Expansion> memo_;
};

// Refuses a node hierarchy whose flattening would be out of bounds, before anything is copied.
void check_node_graph(const tinygltf::Model& model, const GltfReader& rd, const Roots& roots) {
  ExpansionCount count(model, rd);
  Expansion all;
  for (int n : roots.nodes) all.add(count.node(n, 0, roots.where));
  count.check(all, roots.where);
}

// A node's world transform (its own composed with its ancestors'), which must stay finite as a
// float: 40 nested nodes each scaled by 1e10 are each valid, their product is not.
void check_world(const Mat4f& world, const GltfReader& rd, const std::string& node) {
  if (!world.allFinite())
    rd.fail(node, "its world transform (its own composed with its ancestors') overflows a float; the composed "
                  "scales and translations must stay within about 3.4e38");
}

}  // namespace

LoadedModel load_gltf(const std::string& path, const std::vector<AttributeRequest>& attributes) {
  const tinygltf::Model model = open_gltf(path);
  GltfReader rd(model, path);
  LoadedModel out;
  out.attributes.resize(attributes.size());
  for (size_t i = 0; i < model.materials.size(); ++i) out.materials.push_back(convert_material(model, int(i), path));

  // The hierarchy was checked before (check_node_graph): node indices in range, no cycle, at
  // most kMaxNodeDepth levels, and what flattening makes within bounds.
  std::function<void(int, const Mat4f&)> visit_node = [&](int ni, const Mat4f& parent) {
    const tinygltf::Node& node = model.nodes[ni];
    const std::string node_where = "nodes[" + std::to_string(ni) + "]";
    const Mat4f world = parent * node_matrix(node, rd, node_where);
    check_world(world, rd, node_where);
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model.meshes.size())
        rd.fail(node_where + ".mesh", "mesh index " + std::to_string(node.mesh) + " out of range");
      const tinygltf::Mesh& mesh = model.meshes[node.mesh];
      const Mat3f nrm = world.topLeftCorner<3, 3>().inverse().transpose();
      const bool flip = world.topLeftCorner<3, 3>().determinant() < 0;
      for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
        const tinygltf::Primitive& prim = mesh.primitives[pi];
        const std::string where = "meshes[" + std::to_string(node.mesh) + "].primitives[" + std::to_string(pi) + "]";
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;  // lines/points don't render
        auto pos_it = prim.attributes.find("POSITION");
        if (pos_it == prim.attributes.end()) rd.fail(where + ".attributes", "POSITION is missing");
        MeshData md;
        const auto P = rd.floats(pos_it->second, 3, where + ".attributes.POSITION");
        const size_t nv = P.size() / 3;
        for (size_t v = 0; v < nv; ++v) {
          md.positions.push_back(transform_point(world, Vec3f(P[3 * v], P[3 * v + 1], P[3 * v + 2])));
          if (!md.positions.back().allFinite())
            rd.fail(node_where, "its world transform moves vertex " + std::to_string(v) + " of " + where +
                                    " beyond the range of a float (about 3.4e38)");
        }
        if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
          const auto N = rd.floats(it->second, 3, where + ".attributes.NORMAL");
          if (N.size() != P.size()) rd.fail(where + ".attributes.NORMAL", "count differs from POSITION");
          for (size_t v = 0; v < nv; ++v) {
            // A transform that flattens the mesh (a scale of 0) has no inverse: its normals
            // are meaningless, not an error.
            const Vec3f n = nrm * Vec3f(N[3 * v], N[3 * v + 1], N[3 * v + 2]);
            const float len = n.norm();
            md.normals.push_back(len > 0 && std::isfinite(len) ? Vec3f(n / len) : Vec3f(0, 1, 0));
          }
        }
        if (auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
          const auto T = rd.uvs(it->second, where + ".attributes.TEXCOORD_0");
          if (T.size() / 2 != nv) rd.fail(where + ".attributes.TEXCOORD_0", "count differs from POSITION");
          for (size_t v = 0; v < nv; ++v) md.uvs.emplace_back(T[2 * v], 1.0f - T[2 * v + 1]);  // glTF v runs down
        }
        if (prim.indices >= 0) {
          md.indices = rd.indices(prim.indices, where + ".indices");
        } else {
          for (uint32_t v = 0; v < nv; ++v) md.indices.push_back(v);
        }
        if (md.indices.size() % 3)
          rd.fail(where + ".indices", "index count " + std::to_string(md.indices.size()) + " is not a multiple of 3");
        for (size_t k = 0; k < md.indices.size(); ++k)
          if (md.indices[k] >= nv)
            rd.fail(where + ".indices", "index " + std::to_string(md.indices[k]) + " at position " + std::to_string(k) +
                                            " is out of range (" + std::to_string(nv) + " vertices)");
        if (flip)
          for (size_t k = 0; k + 2 < md.indices.size(); k += 3) std::swap(md.indices[k + 1], md.indices[k + 2]);
        if (prim.material >= int(model.materials.size()))
          rd.fail(where + ".material", "material index " + std::to_string(prim.material) + " out of range");
        md.material = prim.material;
        if (!md.normals.empty()) compute_tangents(md);
        for (size_t r = 0; r < attributes.size(); ++r) {
          const AttributeRequest& req = attributes[r];
          const auto it = prim.attributes.find(req.name);
          if (it == prim.attributes.end()) rd.fail(where + ".attributes", "has no vertex attribute " + req.name);
          const std::string at = where + ".attributes." + req.name;
          const std::vector<float> a = req.vec3 ? rd.floats(it->second, 3, at) : rd.first_components(it->second, at);
          if (a.size() != (req.vec3 ? 3 * nv : nv)) rd.fail(at, "count differs from POSITION");
          std::vector<float>& values = out.attributes[r];
          if (!req.vec3) {
            values.insert(values.end(), a.begin(), a.end());
            continue;
          }
          const Mat3f linear = world.topLeftCorner<3, 3>();
          for (size_t v = 0; v < nv; ++v) {
            const Vec3f d = linear * Vec3f(a[3 * v], a[3 * v + 1], a[3 * v + 2]);
            if (!d.allFinite())
              rd.fail(node_where, "its world transform turns value " + std::to_string(v) + " of " + at +
                                      " beyond the range of a float (about 3.4e38)");
            values.insert(values.end(), d.data(), d.data() + 3);
          }
        }
        out.meshes.push_back(std::move(md));
      }
    }
    for (int c : node.children) visit_node(c, world);
  };

  const Roots roots = scene_roots(model, rd);
  check_node_graph(model, rd, roots);
  for (int n : roots.nodes) visit_node(n, Mat4f::Identity());
  if (out.meshes.empty()) rd.fail("meshes", "the file contains no triangle geometry");
  return out;
}

LoadedModel load_mesh_file(const std::string& path, const std::vector<AttributeRequest>& attributes) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".obj") {
    if (!attributes.empty())
      throw UserError(path, "", "an OBJ file carries no vertex attribute " + attributes.front().name + "; use a glTF file (.glb/.gltf)");
    return load_obj(path);
  }
  return load_gltf(path, attributes);
}

}  // namespace phellem
