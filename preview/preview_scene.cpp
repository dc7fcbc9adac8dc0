#include "preview/preview_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bark/dressing/crack_bark_surface.h"
#include "bark/geometry/mesh_data.h"
#include "bark/geometry/tessellation.h"
#include "io/mesh_io.h"
#include "scene/displacement.h"
#include "scene/environment_image.h"
#include "scene/sky_model.h"
#include "scene/mesh_source.h"
#include "scene/object_meshes.h"
#include "scene/tree_surface.h"
#include "util/errors.h"

namespace phellem::preview {

GpuCracks gpu_cracks(const CrackProfile& profile, size_t max_cells) {
  GpuCracks g;
  g.seed = profile.seed();
  g.look = profile.look();
  const auto& segs = profile.segment_list();
  const float reach = profile.reach();
  Vec3f lo = Vec3f::Constant(std::numeric_limits<float>::max()), hi = -lo;
  for (const auto& s : segs) {
    g.segments.insert(g.segments.end(), {s.a.x(), s.a.y(), s.a.z(), s.wa, s.b.x(), s.b.y(), s.b.z(), s.wb, s.chain, 0, 0, 0});
    lo = lo.cwiseMin(s.a).cwiseMin(s.b);
    hi = hi.cwiseMax(s.a).cwiseMax(s.b);
  }
  if (segs.empty()) {
    g.cell_start = {0, 0};
    g.segments.assign(12, 0.0f);  // a buffer may not be empty
    g.items = {0};
    return g;
  }
  lo.array() -= reach;
  hi.array() += reach;
  const Vec3f extent = (hi - lo).cwiseMax(1e-6f);
  // Cells of the reach, grown until the grid fits the budget.
  g.cell = std::max(reach, 1e-4f);
  for (;;) {
    g.dims = (extent / g.cell).array().ceil().cast<int>().cwiseMax(1);
    if (double(g.dims.x()) * g.dims.y() * g.dims.z() <= double(max_cells)) break;
    g.cell *= 1.5f;
  }
  g.origin = lo;
  const size_t cells = size_t(g.dims.x()) * g.dims.y() * g.dims.z();
  std::vector<std::vector<uint32_t>> lists(cells);
  auto index = [&](const Vec3f& p) {
    return ((p - g.origin) / g.cell).array().floor().cast<int>().max(0).min(g.dims.array() - 1).matrix().eval();
  };
  for (uint32_t i = 0; i < segs.size(); ++i) {
    const Vec3f a = segs[i].a.cwiseMin(segs[i].b).array() - reach, b = segs[i].a.cwiseMax(segs[i].b).array() + reach;
    const Eigen::Vector3i ia = index(a), ib = index(b);
    for (int z = ia.z(); z <= ib.z(); ++z)
      for (int y = ia.y(); y <= ib.y(); ++y)
        for (int x = ia.x(); x <= ib.x(); ++x) lists[(size_t(z) * g.dims.y() + y) * g.dims.x() + x].push_back(i);
  }
  g.cell_start.reserve(cells + 1);
  for (const auto& l : lists) {
    g.cell_start.push_back(uint32_t(g.items.size()));
    g.items.insert(g.items.end(), l.begin(), l.end());
  }
  g.cell_start.push_back(uint32_t(g.items.size()));
  if (g.items.empty()) g.items = {0};
  return g;
}

GpuCracks gpu_cracks(const bark::CrackBarkSurface& surface, size_t max_cells) {
  GpuCracks g = gpu_cracks(surface.profile(), max_cells);
  auto take = [](const bark::TintPalette& p) {
    std::vector<Vec3f> t = p.tints();
    if (t.size() > 64) {  // evenly picked, in order (the palette stays sorted)
      std::vector<Vec3f> k;
      for (size_t i = 0; i < 64; ++i) k.push_back(t[i * t.size() / 64]);
      t = k;
    }
    return t;
  };
  g.ridge_tints = take(surface.ridge_palette());
  g.fissure_tints = take(surface.fissure_palette());
  g.tint_seed = surface.plates().seed();
  return g;
}

float GpuImageDisplacement::reach() const {
  float most = 0;
  if (map)
    for (float v : map->value) most = std::max(most, std::abs(v - midlevel));
  return std::abs(scale) * most;
}

GpuImageDisplacement gpu_image_displacement(const DisplacementDesc& d) {
  if (d.type != DisplacementDesc::Type::Image || !d.map) throw std::logic_error("gpu_image_displacement: not an image displacement");
  GpuImageDisplacement g;
  g.map = d.map;
  g.scale = d.scale;
  g.midlevel = d.midlevel;
  g.uv_repeat = d.uv_repeat;
  g.clamp = d.clamp;
  return g;
}

size_t PreviewScene::triangles() const {
  size_t n = 0;
  for (const auto& o : objects) n += o.triangles();
  return n;
}

namespace {

constexpr float kPatchSize = 0.02f;  // m
constexpr long long kMaxPresubdividedTriangles = 4000000;  // patches of one stress object

PreviewObject from_mesh(const MeshData& m) {
  PreviewObject o;
  o.positions = m.positions;
  o.normals = m.normals;
  if (o.normals.size() != o.positions.size()) {
    MeshData w = m;
    compute_vertex_normals(w);
    o.normals = w.normals;
  }
  o.params.assign(o.positions.size(), Vec2f::Zero());
  o.crack_near.assign(o.positions.size(), 0.0f);
  o.texcoords = m.uvs.size() == m.positions.size() ? m.uvs : std::vector<Vec2f>(m.positions.size(), Vec2f::Zero());
  o.indices = m.indices;
  return o;
}

}  // namespace

PreviewObject stress_preview_object(const bark::CrackedMesh& cracked, std::shared_ptr<const bark::CrackBarkSurface> surface) {
  MeshData base = to_mesh_data(cracked.mesh);
  compute_vertex_normals(base, true);
  const CrackLook& look = surface->profile().look();
  DicingParams d;
  d.screen_space = false;
  d.target = kPresubdivideHalfWidths * std::max(look.min_width, 1e-4f);
  d.max_rate = 64;
  d.refine_edge = [surface](const Vec3f& a, const Vec3f& b) { return surface->reaches(a, b); };
  // Bounded: a mesh cracked all over at a fine width would otherwise make billions of patches;
  // past the budget the pre-subdivision coarsens (the tessellator still refines up to 64).
  const DisplacementFn none = [](const Vec2f&, const Vec3f&) { return 0.0f; };
  while (estimate_triangles(base, none, d) > kMaxPresubdividedTriangles && d.target < 1e3f) d.target *= 2;
  const MeshData fine = dice(base, [](const Vec2f&, const Vec3f&, const Vec3f&, Vec4f*) { return 0.0f; }, d);
  PreviewObject p = from_mesh(fine);
  p.normals = fine.normals;
  for (size_t f = 0; f + 2 < p.indices.size(); f += 3)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = p.indices[f + size_t(e)], b = p.indices[f + size_t(e + 1) % 3];
      if (surface->reaches(p.positions[a], p.positions[b])) p.crack_near[a] = p.crack_near[b] = 1.0f;
    }
  p.bark = BarkKind::Cracks;
  p.cracks = std::make_shared<const GpuCracks>(gpu_cracks(*surface));
  p.surface = surface;
  return p;
}

namespace {

// A tree part as a grid over (u, v): the cylinder's surface with the tree's own displacement
// at the grid's vertices; strip bark is left to the GPU through (u, v).
PreviewObject tree_part(const TreePart& part, const DisplacementFn& disp, std::shared_ptr<const bark::FieldBarkSurface> field) {
  // Patches about kPatchSize across (16 to 64 around): the tessellator refines them, and each
  // patch costs llvmpipe's single-threaded geometry stages a few microseconds.
  const float L = float(part.cylinder->length());
  const float circumference = kTwoPi * float(std::max(1e-4, part.cylinder->radius(0.0, 0.0)));
  const int nu = std::clamp(int(std::ceil(circumference / kPatchSize)), 16, 64);
  const int nv = std::clamp(int(std::ceil(L / (circumference / float(nu)))), 1, 4096);
  PreviewObject o;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const float u = float(i) / nu, v = float(j) / nv;
      o.params.emplace_back(u, v);
      o.texcoords.push_back(part.surface.texcoord(u, v));  // the albedo's and an image displacement's
      if (i == nu) {  // the seam: bitwise the first column's point, so both sides tessellate alike
        o.positions.push_back(o.positions[size_t(j) * size_t(nu + 1)]);
        o.normals.push_back(o.normals[size_t(j) * size_t(nu + 1)]);
        continue;
      }
      const double theta = 2.0 * M_PI * double(u);
      const Vec3f p = part.cylinder->position(v, theta).cast<float>();
      const Vec3f n = part.cylinder->normal(v, theta).cast<float>();
      const float d = disp ? disp(Vec2f(u, v * L), p) : 0.0f;
      o.positions.push_back(p + n * d);
      o.normals.push_back(n);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = uint32_t(j * (nu + 1) + i), b = a + 1, c = a + uint32_t(nu) + 1, e = c + 1;
      o.indices.insert(o.indices.end(), {a, b, e, a, e, c});
    }
  o.crack_near.assign(o.positions.size(), field ? 1.0f : 0.0f);  // a fracture field reaches everywhere
  o.curved = true;
  if (field) {
    auto g = std::make_shared<GpuField>();
    g->width = field->width();
    g->height = field->height();
    g->max_depth = float(field->max_depth());
    field->export_texels(&g->depth_mask, &g->albedo);
    o.field = g;
    o.bark = BarkKind::Field;
    o.surface = field;
  }
  return o;
}

// An image displacement on an object drawn from triangles with texcoords: looked up on the GPU,
// and every edge tessellated finely (it reaches everywhere, as a fracture field does).
void add_image_displacement(PreviewObject& p, const DisplacementDesc& d) {
  p.image = std::make_shared<const GpuImageDisplacement>(gpu_image_displacement(d));
  std::fill(p.crack_near.begin(), p.crack_near.end(), 1.0f);
}

// As the path tracer (renderer/scene_contents.cpp): an image displacement needs texcoords.
void require_texcoords(const ObjectDesc& o, bool has_texcoords) {
  if (o.displacement.type == DisplacementDesc::Type::Image && !has_texcoords)
    throw UserError(o.where.file, o.where.path + "/displacement",
                    "an image displacement is looked up at the mesh's texture coordinates, and " +
                        (o.file.empty() ? std::string("this mesh") : printable(o.file)) + " has none (export it with UVs)");
}

Vec3f material_color(const SceneDesc& desc, const std::string& name) {
  if (name.empty()) return Vec3f(0.8f, 0.8f, 0.8f);
  const MaterialDesc& m = desc.materials.at(size_t(desc.find_material(name)));
  Color c = m.base_color;
  if (!m.base_color_texture.procedural.empty())  // the procedural bark texture's mean
    c = c * 0.5f * (m.base_color_texture.color_a + m.base_color_texture.color_b);
  return Vec3f(c.x(), c.y(), c.z());
}

}  // namespace

// Irradiance on surfaces facing straight up and straight down under a latitude-longitude map
// (row v at polar angle v·π from +y, as the path tracer maps it): Σ L·|cos θ|·dω per half.
std::pair<Vec3f, Vec3f> hemisphere_irradiance(const PreviewEnvironment& e) {
  Eigen::Vector3d up = Eigen::Vector3d::Zero(), down = Eigen::Vector3d::Zero();
  const double d_phi = 2 * M_PI / e.width, d_theta = M_PI / e.height;
  for (int y = 0; y < e.height; ++y) {
    const double theta = (y + 0.5) * d_theta, w = std::cos(theta) * std::sin(theta) * d_theta * d_phi;
    Eigen::Vector3d row = Eigen::Vector3d::Zero();
    for (int x = 0; x < e.width; ++x) {
      const float* c = &e.rgb[(size_t(y) * size_t(e.width) + size_t(x)) * 3];
      row += Eigen::Vector3d(c[0], c[1], c[2]);
    }
    (w > 0 ? up : down) += std::abs(w) * row;
  }
  return {(up * e.intensity).cast<float>(), (down * e.intensity).cast<float>()};
}

PreviewScene build_preview_scene(const SceneDesc& desc, const BarkResults& bark) {
  PreviewScene s;
  // A sun of irradiance E adds E/π × cos to a Lambertian's radiance per unit albedo; an
  // environment its irradiance on an upward and a downward facing surface, over π.
  bool sun = false;
  for (const auto& l : desc.lights) {
    if (l.type == LightType::Sun && !sun) {
      sun = true;
      s.sun_direction = l.direction.normalized();
      s.sun_color = Vec3f(l.color.x(), l.color.y(), l.color.z()) * (l.irradiance / kPi);
    } else if (l.type == LightType::EnvironmentUniform) {
      s.sky_color = s.ground_color = Vec3f(l.color.x(), l.color.y(), l.color.z()) * l.intensity;
    } else if ((l.type == LightType::EnvironmentMap || l.type == LightType::Sky) && !s.environment) {
      auto env = std::make_shared<PreviewEnvironment>();
      if (l.type == LightType::Sky) {  // the path tracer's baked sky (scene/sky_model.h)
        env->width = 128;
        env->height = 64;
        env->rgb = preetham_sky_image(l.direction, l.turbidity, l.sky_intensity.value_or(1.0f), l.ground_albedo, env->width);
      } else {
        env->rgb = load_environment_image(l, &env->width, &env->height);
        env->intensity = l.intensity;
        env->rotation_deg = l.rotation_deg;
      }
      const auto [up, down] = hemisphere_irradiance(*env);
      s.sky_color = up / kPi;
      s.ground_color = down / kPi;
      s.environment = env;
    }
  }
  auto bark_of = [&](size_t oi) -> const ObjectBark& {
    const ObjectBark* b = bark.find(oi);
    if (!b) throw std::logic_error("object " + std::to_string(oi) + " has no simulated bark");
    return *b;
  };
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& o = desc.objects[oi];
    const Vec3f color = material_color(desc, o.material);
    std::vector<PreviewObject> made;
    const bool image = o.displacement.type == DisplacementDesc::Type::Image;
    switch (o.type) {
      case ObjectType::Sphere:
        made.push_back(from_mesh(sphere_mesh(o.center, o.radius, 48, 24)));  // fewer patches: the tessellator refines
        break;
      case ObjectType::Plane:
        made.push_back(from_mesh(plane_mesh(o)));
        break;
      case ObjectType::Patch:
        // Cells about kPatchSize across, as a tree part's: the tessellator refines each, and
        // llvmpipe drops primitives of patches tessellated past a level of about 20 (a 1 m
        // patch of 16 × 16 cells at 2 px a micro-edge lost whole bands of cells).
        made.push_back(from_mesh(patch_mesh(o, std::clamp(int(std::ceil(o.size.x() / kPatchSize)), 1, 512),
                                            std::clamp(int(std::ceil(o.size.y() / kPatchSize)), 1, 512))));
        if (image) add_image_displacement(made.back(), o.displacement);
        break;
      case ObjectType::Tree:
      case ObjectType::Mesh: {
        // A mesh's image displacement adds to its cracks (a tree's is in its cracked or grown
        // mesh already, as the path tracer's).
        const bool mesh_image = o.type == ObjectType::Mesh && image;
        if (o.stress_bark && bark_of(oi).cracked) {
          made.push_back(stress_preview_object(*bark_of(oi).cracked, crack_surface(o, *bark_of(oi).cracked)));
          if (mesh_image) {
            const bark::TriMesh& cracked = bark_of(oi).cracked->mesh;
            require_texcoords(o, !cracked.uvs.empty() && cracked.uvs.size() == cracked.positions.size());
            add_image_displacement(made.back(), o.displacement);
          }
          break;
        }
        if (o.growth) {  // the surface at the last step of its cambial growth (world space)
          MeshData w = to_mesh_data(*bark_of(oi).grown);
          compute_vertex_normals(w, true);  // its UV seams are cut (growth_run.h): shade across them as one surface
          if (mesh_image) require_texcoords(o, w.uvs.size() == w.positions.size());
          made.push_back(from_mesh(w));
          if (mesh_image) add_image_displacement(made.back(), o.displacement);
          break;
        }
        if (o.type == ObjectType::Tree) {
          const DisplacementFn disp = make_displacement(o.tree.displacement);
          // The grid's vertices carry the procedural displacement; the image's is the GPU's.
          const auto parts = build_tree(o.tree, disp);
          const bool tree_image = o.tree.texture_displacement.type == DisplacementDesc::Type::Image;
          const auto* strips = o.tree.strip_bark ? &bark_of(oi).strip_parts : nullptr;
          for (size_t k = 0; k < parts.size(); ++k) {
            made.push_back(tree_part(parts[k], disp, strips && k < strips->size() ? (*strips)[k] : nullptr));
            if (tree_image) add_image_displacement(made.back(), o.tree.texture_displacement);
          }
          break;
        }
        if (o.procedural) {
          MeshData w = to_mesh_data(object_trimesh(o));
          compute_vertex_normals(w);
          if (mesh_image) require_texcoords(o, w.uvs.size() == w.positions.size());
          made.push_back(from_mesh(w));
          if (mesh_image) add_image_displacement(made.back(), o.displacement);
          break;
        }
        const LoadedModel model = load_mesh_file(o.file);
        for (const auto& m : model.meshes) {
          if (!mesh_image) {
            PreviewObject p = from_mesh(m);
            p.model = o.transform.matrix;
            made.push_back(std::move(p));
            continue;
          }
          // Displaced in world space along world normals, in metres, as the path tracer
          // flattens a displaced mesh (a scaled model matrix would scale the offset).
          MeshData w = m;
          const Mat3f nrm = o.transform.matrix.topLeftCorner<3, 3>().inverse().transpose();
          for (auto& p : w.positions) p = transform_point(o.transform.matrix, p);
          for (auto& n : w.normals) n = (nrm * n).normalized();
          if (w.normals.empty()) compute_vertex_normals(w);
          require_texcoords(o, w.uvs.size() == w.positions.size());
          made.push_back(from_mesh(w));
          add_image_displacement(made.back(), o.displacement);
        }
        break;
      }
    }
    for (auto& p : made) {
      p.name = o.name;
      p.object_id = int(oi) + 1;
      p.base_color = color;
      s.objects.push_back(std::move(p));
    }
  }
  return s;
}

}  // namespace phellem::preview
