#include "scene/growth_run.h"

#include <cmath>

#include "bark/geometry/procedural_meshes.h"
#include "bark/geometry/uv_seams.h"
#include "bark/growth/texture_cells.h"
#include "bark/growth/texture_transport.h"
#include "scene/mesh_source.h"
#include "util/errors.h"
#include "util/progress.h"

namespace phellem {

namespace {

bark::TriMesh obstacle_mesh(const ObjectDesc& o) {
  if (o.type == ObjectType::Sphere) {
    bark::TriMesh m = bark::icosphere(4, double(o.radius));
    for (auto& p : m.positions) p += o.center.cast<double>();
    return m;
  }
  return object_trimesh(o);
}

// Whether some face of the mesh spans an area of texture space: a mesh file without
// TEXCOORD_0 loads with every UV at (0, 0), which no painted map can be read through.
bool has_texture_area(const bark::TriMesh& m) {
  if (!m.has_uvs()) return false;
  for (const auto& t : m.triangles) {
    const Eigen::Vector2d a = bark::wrapped_uv_delta(m.uvs[t[0]], m.uvs[t[1]]), b = bark::wrapped_uv_delta(m.uvs[t[0]], m.uvs[t[2]]);
    if (std::abs(a.x() * b.y() - a.y() * b.x()) > 1e-12) return true;
  }
  return false;
}

}  // namespace

bark::CambialGrowth start_growth(const SceneDesc& desc, size_t oi, bool progress) {
  const ObjectDesc& obj = desc.objects.at(oi);
  if (!obj.growth) throw std::logic_error("start_growth: the object does not grow");
  const GrowthDesc& g = *obj.growth;
  std::vector<bark::GrowthObstacle> obstacles;
  for (size_t k = 0; k < g.obstacles.size(); ++k)
    obstacles.push_back({obstacle_mesh(desc.objects.at(g.obstacles[k])), g.where.path + "/obstacles/" + std::to_string(k)});
  // Meshes that cannot grow (open, overlapping) are reported at the growth block and at the
  // obstacle's entry in it.
  // The painted attributes (sec. 4.4) are read with the mesh: a speed, then a direction.
  const std::string attribute = g.speed_map ? g.speed_map->attribute : std::string();
  std::vector<AttributeRequest> requests;
  if (!attribute.empty()) requests.push_back({attribute, false});
  const std::string direction_attribute = g.direction_map ? g.direction_map->attribute : std::string();
  if (!direction_attribute.empty()) requests.push_back({direction_attribute, true});
  std::vector<std::vector<float>> painted;
  const bark::TriMesh surface = object_trimesh(obj, requests, &painted);
  std::vector<float> speed;
  if (!attribute.empty()) {
    speed = std::move(painted.front());
    // Painted on the vertices (sec. 4.4): the attribute's first component × scale.
    for (size_t v = 0; v < speed.size(); ++v) {
      if (!(speed[v] >= 0 && speed[v] <= 1e6f))
        throw UserError(desc.file, g.where.path + "/speed_map/attribute",
                        obj.file + ": vertex " + std::to_string(v) + " has " + attribute + " = " + std::to_string(speed[v]) +
                            "; a speed factor must lie in [0, 1e6]");
      speed[v] *= g.speed_map->scale;
    }
  } else if (g.speed_map) {
    if (!has_texture_area(surface))
      throw UserError(desc.file, g.where.path + "/speed_map", "a speed map needs a mesh with texture coordinates");
    for (const auto& uv : surface.uvs) speed.push_back(g.speed_map->scale * g.speed_map->at(uv.x(), uv.y()));
  }
  // Painted directions (sec. 4.4): a VEC3 attribute, in the scene's space, or a flow map read
  // in each vertex's texture frame.
  std::vector<Eigen::Vector3f> direction;
  if (!direction_attribute.empty()) {
    const std::vector<float>& d = painted.back();
    if (d.size() != 3 * surface.positions.size()) throw std::logic_error("start_growth: directions and vertices differ");
    for (size_t v = 0; v < surface.positions.size(); ++v) {
      const Eigen::Vector3f D(d[3 * v], d[3 * v + 1], d[3 * v + 2]);
      if (!(D.norm() <= 1e6f))
        throw UserError(desc.file, g.where.path + "/direction_map/attribute",
                        obj.file + ": vertex " + std::to_string(v) + " has a " + direction_attribute +
                            " longer than 1e6 (its length, up to 1, is how far the growth turns)");
      direction.push_back(D);
    }
  } else if (g.direction_map) {
    if (!has_texture_area(surface))
      throw UserError(desc.file, g.where.path + "/direction_map", "a direction map needs a mesh with texture coordinates");
    const std::vector<bark::TextureAxes> axes = bark::texture_axes(surface.positions, surface.uvs, surface.triangles);
    for (size_t v = 0; v < surface.positions.size(); ++v) {
      const Eigen::Vector2d d = double(g.direction_map->scale) * g.direction_map->at(surface.uvs[v].x(), surface.uvs[v].y());
      direction.push_back(bark::texture_direction(axes[v], d).cast<float>());
    }
  }
  const std::string name = obj.name.empty() ? "mesh" + std::to_string(oi) : obj.name;
  Progress bar("tetrahedralize " + name, 1, progress);
  bark::CambialGrowth growth(surface, obstacles, g.settings, desc.file, g.where.path, speed, direction);
  bar.advance();
  bar.finish();
  // Stress bark cracks as the surface grows (thesis sec. 5): the young surface now, then after
  // every step.
  if (obj.stress_bark && g.cracks) {
    bark::CrackCouplingSettings cs;
    const int steps = std::max(1, g.settings.steps);
    cs.iterations_per_step = g.crack_iterations > 0 ? g.crack_iterations
                                                    : (obj.stress_bark->params.iterations + steps - 1) / steps;
    cs.stretch_stress = g.stretch_stress;
    try {
      growth.couple_cracks(obj.stress_bark->params, cs);
    } catch (const bark::StressParamError& e) {
      throw UserError(desc.file, "/objects/" + std::to_string(oi) + "/bark/" + e.key, e.key + ": " + e.message);
    }
  }
  return growth;
}

std::shared_ptr<const bark::TextureScaleField> start_texture_scale(const bark::CambialGrowth& g) {
  if (g.steps_done() != 0) throw std::logic_error("start_texture_scale: the growth has already stepped");
  return std::make_shared<const bark::TextureScaleField>(bark::extract_interface(g.complex()).mesh);
}

GrownBark grown_bark(const bark::CambialGrowth& g, const GrowthDesc& desc, const bark::TextureScaleField& start_scale) {
  GrownBark b;
  auto surface = std::make_shared<bark::TriMesh>(bark::cut_uv_seams(bark::extract_interface(g.complex()).mesh));
  if (g.cracks()) {
    std::shared_ptr<const bark::CrackedMesh> cracked = g.cracks()->result();
    auto cut = std::make_shared<bark::CrackedMesh>(*cracked);
    std::vector<uint32_t> source;
    cut->mesh = bark::cut_uv_seams(cracked->mesh, &source);
    // Copies at a seam carry their vertex's crack attributes; crack edges keep the originals.
    for (size_t v = cracked->mesh.positions.size(); v < source.size(); ++v) {
      cut->crack_width.push_back(cracked->crack_width[source[v]]);
      cut->component.push_back(cracked->component[source[v]]);
      cut->displacement.push_back(cracked->displacement[source[v]]);
    }
    b.cracked = cut;
  }
  if (desc.texture_cells)
    b.texture_levels = bark::texture_cell_levels(b.cracked ? b.cracked->mesh : *surface, start_scale);
  b.surface = std::move(surface);
  return b;
}

GrowthRun run_growth_object(const SceneDesc& desc, size_t oi, bool progress,
                            const std::function<void(const bark::CambialGrowth&)>& on_step) {
  const ObjectDesc& obj = desc.objects.at(oi);
  const std::string name = obj.name.empty() ? "mesh" + std::to_string(oi) : obj.name;
  bark::CambialGrowth growth = start_growth(desc, oi, progress);
  const auto start_scale = start_texture_scale(growth);
  {
    Progress bar("grow " + name, growth.steps_total(), progress);
    while (growth.step()) {
      if (on_step) on_step(growth);
      bar.advance();
    }
    bar.finish();
  }
  GrowthRun run;
  static_cast<GrownBark&>(run) = grown_bark(growth, *obj.growth, *start_scale);
  run.rings = growth.rings();
  run.stats = growth.stats();
  run.steps = growth.steps_done();
  return run;
}

}  // namespace phellem
