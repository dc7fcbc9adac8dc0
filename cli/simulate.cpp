#include "cli/simulate.h"

#include <OpenImageIO/imageio.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "cli/memory_check.h"
#include "cli/outputs.h"
#include "cli/simulate_growth.h"
#include "cli/simulate_stress.h"
#include "io/height_image.h"
#include "io/image_file.h"
#include "scene/scene_parser.h"
#include "scene/strip_bark_tree.h"
#include "util/errors.h"
#include "util/output_set.h"
#include "util/progress.h"

namespace phellem {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Multi-channel scene-linear EXR of a FractureField; row 0 of the image is the top of the
// cylinder (s = length), so the image looks like the bark seen from outside, axis up. Written
// to `tmp`, the staged temporary of `path`.
void write_field(const bark::FractureField& f, const std::string& path, const std::string& tmp) {
  const std::vector<std::string> names = {"color.R", "color.G",     "color.B", "opening", kFieldDepthChannel, "uv0.u",
                                          "uv0.v",   "fracture_id", "age",     "level",   "interior"};
  const int nc = int(names.size());
  std::vector<float> px(size_t(f.width) * f.height * nc);
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const size_t p = f.index(x, y);
      float* o = &px[(size_t(f.height - 1 - y) * f.width + x) * nc];
      const float v[] = {f.color[3 * p],   f.color[3 * p + 1], f.color[3 * p + 2], f.opening[p], f.depth[p],   f.uv0[2 * p],
                         f.uv0[2 * p + 1], f.fracture_id[p],   f.age[p],           f.level[p],   f.interior[p]};
      std::copy(v, v + nc, o);
    }
  OIIO::ImageSpec spec(f.width, f.height, nc, OIIO::TypeDesc::FLOAT);
  spec.channelnames = names;
  spec.attribute("compression", "zip");
  // io/height_image reads these back (`phellem compare`).
  spec.attribute(kFieldLengthAttribute, float(f.length));
  spec.attribute(kFieldCircumferenceAttribute, float(f.circumference));
  write_image_file(path, tmp, spec, OIIO::TypeDesc::FLOAT, px.data());
}

}  // namespace

int run_simulate(const cli::Options& o) {
  const auto t0 = Clock::now();
  OutputSet out;
  expect_outputs(o, out);
  const SceneDesc desc = load_scene_file(o.scene);
  expect_scene_inputs(desc, out);
  check_scene_memory(o, desc, 0, 0);
  const std::filesystem::path dir(o.exr);
  double t_sim = 0, t_dress = 0, t_mesh = 0;
  long long strips = 0, fractures = 0, created = 0, propagated = 0, merged = 0;
  int steps = 0, outputs = 0;
  nlohmann::json files = nlohmann::json::array();
  long long crossings = 0, mesh_triangles = 0;
  nlohmann::json meshes = nlohmann::json::array();
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& obj = desc.objects[oi];
    if (obj.type != ObjectType::Tree || !obj.tree.strip_bark) continue;
    const auto ts = Clock::now();
    TreeStripSimulation sim(obj, oi, o.seed);
    sim.run(!o.quiet);
    t_sim += since(ts);
    const std::string base = obj.name.empty() ? "tree" + std::to_string(oi) : obj.name;
    for (size_t k = 0; k < sim.parts(); ++k) {
      // Stages, not a smooth bar: the field, its EXR, the mesh (the writes are one call each).
      Progress bar("dress " + base + "_" + sim.part_name(k), o.no_mesh ? 2 : 3, !o.quiet);
      const auto td = Clock::now();
      const bark::FractureField field = sim.field(k, o.width.value_or(0), o.height.value_or(0));
      bar.advance();
      const std::string file = (dir / (base + "_" + sim.part_name(k) + ".exr")).string();
      out.write("-o", file, [&](const std::string& tmp) { write_field(field, file, tmp); });
      bar.advance();
      t_dress += since(td);
      const bark::StripModel& model = sim.bark().model(k);
      strips += long(model.strips().size());
      std::set<int32_t> roots;
      for (const auto& st : model.strips())
        for (const auto& fe : st.fractures) roots.insert(model.skeleton().find(fe.id));
      fractures += long(roots.size());
      created += model.stats().created;  // scripted breaks and arrivals included
      propagated += model.stats().propagated;
      merged += model.stats().merged;
      steps = std::max(steps, model.steps_total());
      ++outputs;
      files.push_back(file);
      if (!o.no_mesh) {
        const auto tm = Clock::now();
        const GlbMesh mesh = sim.mesh(k);
        const std::string glb = (dir / (base + "_" + sim.part_name(k) + ".glb")).string();
        out.write("-o", glb, [&](const std::string& tmp) { write_glb(tmp, base + "_" + sim.part_name(k), mesh); });
        mesh_triangles += (long long)mesh.triangle_count();
        meshes.push_back(glb);
        t_mesh += since(tm);
        bar.advance();
      }
      bar.finish();
    }
    crossings += long(sim.bark().crossings().size());
  }
  const StressRunTotals stress = simulate_stress_objects(o, desc, dir, out);
  const GrowthRunTotals growth = simulate_growth_objects(o, desc, dir, out);
  if (outputs == 0 && stress.objects == 0 && growth.objects == 0)
    throw UserError(o.scene, "/objects",
                    "no object has a \"bark\" to simulate (trees: {\"model\": \"strips\"}; meshes: {\"model\": \"stress\"}) "
                    "or a \"growth\"");
  if (!o.stats.empty()) {
    nlohmann::json j;
    if (stress.objects > 0) {
      j = {{"model", "stress"},
           {"objects", stress.objects},
           {"triangles_in", stress.triangles_in},
           {"triangles_out", stress.triangles_out},
           {"iterations", stress.iterations},
           {"cracks", stress.cracks},
           {"crack_edges", stress.crack_edges},
           {"crack_length_m", stress.crack_length},
           {"outputs", stress.outputs},
           {"time_s",
            {{"total", since(t0)},
             {"preprocess", stress.t_preprocess},
             {"simulate", stress.t_simulate},
             {"write", stress.t_write}}}};
    }
    if (outputs > 0) {
      if (stress.objects > 0)
        j["model"] = "strips+stress";
      else
        j["model"] = "strips";
      j.update(nlohmann::json{
          {"strips", strips},
          {"steps", steps},
          {"fractures", fractures},
          {"fractures_created", created},
          {"propagations", propagated},
          {"merges", merged},
          {"junction_crossings", crossings},
          {"outputs", files},
          {"meshes", meshes},
          {"mesh_triangles", mesh_triangles},
      });
      j["time_s"]["total"] = since(t0);
      j["time_s"]["simulate"] = t_sim + stress.t_simulate;
      j["time_s"]["dress"] = t_dress;
      j["time_s"]["mesh"] = t_mesh;
      if (stress.objects > 0) j["stress_outputs"] = stress.outputs;
    }
    if (growth.objects > 0) {
      if (!j.contains("model")) j["model"] = "growth";
      j["growth"] = {{"objects", growth.objects},
                     {"steps", growth.steps},
                     {"vertices_start", growth.vertices_start},
                     {"vertices_end", growth.vertices_end},
                     {"remeshes", growth.remeshes},
                     {"outputs", growth.outputs}};
      j["time_s"]["total"] = since(t0);
      j["time_s"]["growth"] = growth.t_growth;
      j["time_s"]["growth_setup"] = growth.t_setup;
      j["time_s"]["growth_remesh"] = growth.t_remesh;
      j["time_s"]["growth_motion"] = growth.t_motion;
      j["time_s"]["growth_contact"] = growth.t_contact;
      j["time_s"]["growth_repair"] = growth.t_repair;
      j["time_s"]["growth_crack"] = growth.t_crack;
    }
    write_json_output(out, "--stats", o.stats, j);
  }
  out.commit();
  return 0;
}

}  // namespace phellem
