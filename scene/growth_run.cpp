#include "scene/growth_run.h"

#include "bark/geometry/procedural_meshes.h"
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
  const bark::TriMesh surface = object_trimesh(obj);
  std::vector<float> speed;
  if (g.speed_map) {
    if (!surface.has_uvs())
      throw UserError(desc.file, g.where.path + "/speed_map", "a speed map needs a mesh with texture coordinates");
    for (const auto& uv : surface.uvs) speed.push_back(g.speed_map->scale * g.speed_map->at(uv.x(), uv.y()));
  }
  const std::string name = obj.name.empty() ? "mesh" + std::to_string(oi) : obj.name;
  Progress bar("tetrahedralize " + name, 1, progress);
  bark::CambialGrowth growth(surface, obstacles, g.settings, desc.file, g.where.path, speed);
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

std::shared_ptr<const bark::TriMesh> grown_surface(const bark::CambialGrowth& g) {
  return std::make_shared<const bark::TriMesh>(bark::extract_interface(g.complex()).mesh);
}

GrowthRun run_growth_object(const SceneDesc& desc, size_t oi, bool progress,
                            const std::function<void(const bark::CambialGrowth&)>& on_step) {
  const ObjectDesc& obj = desc.objects.at(oi);
  const std::string name = obj.name.empty() ? "mesh" + std::to_string(oi) : obj.name;
  bark::CambialGrowth growth = start_growth(desc, oi, progress);
  {
    Progress bar("grow " + name, growth.steps_total(), progress);
    while (growth.step()) {
      if (on_step) on_step(growth);
      bar.advance();
    }
    bar.finish();
  }
  GrowthRun run;
  run.surface = grown_surface(growth);
  if (growth.cracks()) run.cracked = growth.cracks()->result();
  run.rings = growth.rings();
  run.stats = growth.stats();
  run.steps = growth.steps_done();
  return run;
}

}  // namespace phellem
