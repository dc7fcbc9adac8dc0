#include "cli/simulate_growth.h"

#include <chrono>
#include <cstdio>

#include "bark/growth/growth_rings.h"
#include "cli/outputs.h"
#include "io/cracked_mesh_io.h"
#include "io/gltf_writer.h"
#include "scene/bark_results.h"
#include "scene/growth_run.h"
#include "scene/mesh_source.h"

namespace phellem {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The texture cell levels (sec. 4.6) as glTF custom attributes, for a shader that tiles the
// textures the same way (none when there are none).
std::vector<std::pair<std::string, std::vector<float>>> level_attributes(const std::vector<Eigen::Vector2f>& levels) {
  if (levels.empty()) return {};
  std::vector<float> u, v;
  for (const auto& l : levels) u.push_back(l.x()), v.push_back(l.y());
  return {{"_TEXTURE_LEVEL_U", u}, {"_TEXTURE_LEVEL_V", v}};
}

GlbMesh surface_mesh(const bark::TriMesh& t, const std::vector<Eigen::Vector2f>& levels) {
  GlbMesh m;
  m.vertices = to_mesh_data(t);
  compute_vertex_normals(m.vertices, true);
  m.scalars = level_attributes(levels);
  GlbPart p;
  p.name = "bark";
  p.indices = m.vertices.indices;
  p.base_color = Color(0.35f, 0.27f, 0.2f);
  m.parts.push_back(std::move(p));
  return m;
}

}  // namespace

GlbMesh rings_mesh(const std::vector<bark::GrowthRing>& rings) {
  GlbMesh m;
  for (size_t k = 0; k < rings.size(); ++k) {
    const bark::GrowthRing& r = rings[k];
    const uint32_t base = uint32_t(m.vertices.positions.size());
    for (const auto& p : r.points) m.vertices.positions.push_back(p.cast<float>());
    GlbPart part;
    char name[32];
    std::snprintf(name, sizeof name, "ring_%05d", r.step);
    part.name = name;
    for (const auto& f : r.faces)
      for (uint32_t v : f) part.indices.push_back(base + v);
    const float s = rings.size() > 1 ? float(k) / float(rings.size() - 1) : 1.0f;  // later rings lighter
    part.base_color = Color(0.25f + 0.5f * s, 0.18f + 0.4f * s, 0.1f + 0.3f * s);
    m.parts.push_back(std::move(part));
  }
  compute_vertex_normals(m.vertices);
  return m;
}

GrowthRunTotals simulate_growth_objects(const cli::Options& o, const SceneDesc& desc, const std::filesystem::path& dir,
                                        OutputSet& out) {
  GrowthRunTotals totals;
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& obj = desc.objects[oi];
    if (!obj.growth) continue;
    const std::string name = obj.name.empty() ? "mesh" + std::to_string(oi) : obj.name;
    const GrowthRun run = run_growth_object(desc, oi, !o.quiet);
    const std::shared_ptr<const bark::CrackedMesh> cracked = run.cracked;  // cracked as it grew
    const double t_crack = run.stats.cracks_s;
    const auto tw = Clock::now();
    const std::string glb = (dir / (name + ".glb")).string();
    if (cracked)
      out.write("-o", glb, [&](const std::string& tmp) {
        write_cracked_glb(tmp, name, *cracked, level_attributes(run.texture_levels));
      });
    else
      out.write("-o", glb, [&](const std::string& tmp) {
        write_glb(tmp, name, surface_mesh(*run.surface, run.texture_levels));
      });
    const std::string rings = (dir / (name + "_rings.glb")).string();
    if (!run.rings.empty())
      out.write("-o", rings, [&](const std::string& tmp) { write_glb(tmp, name + "_rings", rings_mesh(run.rings)); });
    const bark::CambialGrowthStats& st = run.stats;
    nlohmann::json summary = {{"model", "growth"},
                              {"object", name},
                              {"steps", run.steps},
                              {"vertices_start", st.vertices_start},
                              {"vertices_end", st.vertices_end},
                              {"tetrahedra_start", st.tets_start},
                              {"tetrahedra_end", st.tets_end},
                              {"moves", {{"full", st.moved}, {"shortened", st.shortened}, {"clamped", st.clamped}}},
                              {"splits", st.splits},
                              {"collapses", st.collapses},
                              {"flips", st.flips},
                              {"interface_flips", st.interface_flips},
                              {"upkeep_steps", st.upkeep_steps},
                              {"frozen", {{"obstacle", st.frozen_obstacle}, {"contact", st.frozen_contact}}},
                              {"rings", run.rings.size()},
                              {"remeshes", {{"made", st.remeshes}, {"refused", st.remesh_refused}}},
                              {"time_s",
                               {{"setup", st.setup_s},
                                {"growth", st.steps_s},
                                {"motion", st.motion_s},
                                {"contact", st.contact_s},
                                {"repair", st.repair_s},
                                {"remesh", st.remesh_s},
                                {"crack", t_crack},
                                {"motion_parts",
                                 {{"carry", st.carry_s}, {"moves", st.moves_s}, {"unblock", st.unblock_s}, {"smoothing", st.smooth_s}}},
                                {"contact_parts", {{"curvature", st.curvature_s}}},
                                {"repair_parts",
                                 {{"interface_flips", st.flips_s},
                                  {"splits_collapses", st.band_s},
                                  {"vertex_removal", st.removal_s},
                                  {"improve", st.improve_s}}}}}};
    if (cracked) summary["crack_length_m"] = cracked->crack_length();
    write_json_output(out, "-o", (dir / (name + ".json")).string(), summary);
    totals.t_write += since(tw);
    ++totals.objects;
    totals.steps += run.steps;
    totals.vertices_start += (long long)st.vertices_start;
    totals.vertices_end += (long long)st.vertices_end;
    totals.t_setup += st.setup_s;
    totals.t_growth += st.steps_s;
    totals.remeshes += st.remeshes;
    totals.t_remesh += st.remesh_s;
    totals.t_motion += st.motion_s;
    totals.t_contact += st.contact_s;
    totals.t_repair += st.repair_s;
    totals.t_crack += t_crack;
    totals.outputs.push_back(glb);
    if (!run.rings.empty()) totals.outputs.push_back(rings);
  }
  return totals;
}

}  // namespace phellem
