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

MaterialDesc convert_material(const tinygltf::Model& m, int index, const std::string& path) {
  const tinygltf::Material& g = m.materials[index];
  const std::string where = "materials[" + std::to_string(index) + "]";
  MaterialDesc d;
  d.name = g.name.empty() ? where : g.name;
  d.where = {path, where};
  const auto& pbr = g.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() >= 3)
    d.base_color =
        Color(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]), float(pbr.baseColorFactor[2])).max(0.0f).min(1.0f);
  d.roughness = float(std::clamp(pbr.roughnessFactor, 0.0, 1.0));
  d.type = pbr.metallicFactor >= 0.5 ? MaterialType::Conductor : MaterialType::Bark;
  // KHR_materials_specular: F0 = 0.04 × specularFactor × specularColorFactor for the default
  // IOR 1.5; our bark/dielectric-base layer has F0 = 0.08 × specular.
  if (auto it = g.extensions.find("KHR_materials_specular"); it != g.extensions.end()) {
    double factor = 1.0, color = 1.0;
    if (it->second.Has("specularFactor")) factor = it->second.Get("specularFactor").GetNumberAsDouble();
    if (it->second.Has("specularColorFactor")) {
      const auto& c = it->second.Get("specularColorFactor");
      color = 0;
      for (size_t k = 0; k < std::min<size_t>(3, c.ArrayLen()); ++k) color = std::max(color, c.Get(int(k)).GetNumberAsDouble());
    }
    if (!std::isfinite(factor) || !std::isfinite(color) || factor < 0 || color < 0)
      throw UserError(path, where + ".extensions.KHR_materials_specular", "specular factors must be finite and non-negative");
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

}  // namespace

LoadedModel load_gltf(const std::string& path, const std::vector<AttributeRequest>& attributes) {
  const tinygltf::Model model = open_gltf(path);
  GltfReader rd(model, path);
  LoadedModel out;
  out.attributes.resize(attributes.size());
  for (size_t i = 0; i < model.materials.size(); ++i) out.materials.push_back(convert_material(model, int(i), path));

  std::function<void(int, const Mat4f&, int)> visit_node = [&](int ni, const Mat4f& parent, int depth) {
    if (ni < 0 || size_t(ni) >= model.nodes.size()) rd.fail("nodes", "node index " + std::to_string(ni) + " out of range");
    if (depth > 64) rd.fail("nodes[" + std::to_string(ni) + "]", "node hierarchy deeper than 64 (cycle?)");
    const tinygltf::Node& node = model.nodes[ni];
    const Mat4f world = parent * node_matrix(node, rd, "nodes[" + std::to_string(ni) + "]");
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model.meshes.size())
        rd.fail("nodes[" + std::to_string(ni) + "].mesh", "mesh index " + std::to_string(node.mesh) + " out of range");
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
        for (size_t v = 0; v < nv; ++v)
          md.positions.push_back(transform_point(world, Vec3f(P[3 * v], P[3 * v + 1], P[3 * v + 2])));
        if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
          const auto N = rd.floats(it->second, 3, where + ".attributes.NORMAL");
          if (N.size() != P.size()) rd.fail(where + ".attributes.NORMAL", "count differs from POSITION");
          for (size_t v = 0; v < nv; ++v) {
            Vec3f n = nrm * Vec3f(N[3 * v], N[3 * v + 1], N[3 * v + 2]);
            md.normals.push_back(n.norm() > 0 ? Vec3f(n.normalized()) : Vec3f(0, 1, 0));
          }
        }
        if (auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
          const auto T = rd.floats(it->second, 2, where + ".attributes.TEXCOORD_0");
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
            values.insert(values.end(), d.data(), d.data() + 3);
          }
        }
        out.meshes.push_back(std::move(md));
      }
    }
    for (int c : node.children) visit_node(c, world, depth + 1);
  };

  if (!model.scenes.empty()) {
    const int si = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(si) >= model.scenes.size()) rd.fail("scene", "default scene index out of range");
    for (int n : model.scenes[si].nodes) visit_node(n, Mat4f::Identity(), 0);
  } else {
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const auto& n : model.nodes)
      for (int c : n.children)
        if (c >= 0 && size_t(c) < is_child.size()) is_child[c] = true;
    for (size_t n = 0; n < model.nodes.size(); ++n)
      if (!is_child[n]) visit_node(int(n), Mat4f::Identity(), 0);
  }
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
