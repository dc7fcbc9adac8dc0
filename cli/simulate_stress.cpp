#include "cli/simulate_stress.h"

#include <chrono>
#include <fstream>

#include "bark/geometry/irregular_remesh.h"
#include "bark/stress/stress_cracker.h"
#include "renderer/atomic_file.h"
#include "renderer/cracked_mesh_io.h"
#include "renderer/errors.h"
#include "renderer/mesh_source.h"
#include "renderer/progress.h"

namespace phellem {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

StressRunTotals simulate_stress_objects(const cli::Options& o, const SceneDesc& desc, const std::filesystem::path& dir) {
  StressRunTotals totals;
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& obj = desc.objects[oi];
    if (!obj.stress_bark) continue;
    const std::string where = "/objects/" + std::to_string(oi);
    const std::string name = obj.name.empty() ? "mesh" + std::to_string(oi) : obj.name;
    bark::StressParams params = obj.stress_bark->params;
    if (o.seed) params.seed = *o.seed;
    const auto tp = Clock::now();
    bark::TriMesh input = object_trimesh(obj);
    // The mesh's own problems are reported at the mesh file, or at the object for procedural ones.
    const std::string mesh_file = obj.file.empty() ? desc.file : obj.file;
    auto mesh_error = [&](const bark::MeshError& e) {
      return UserError(mesh_file, obj.file.empty() ? where + "/procedural" : e.where, std::string(e.what()));
    };
    bark::StressMesh mesh = [&] {
      try {
        if (obj.stress_bark->preprocess.enabled) {
          bark::RemeshOptions ro;
          ro.edge_length = obj.stress_bark->preprocess.edge_length;
          ro.jitter = obj.stress_bark->preprocess.jitter;
          ro.seed = params.seed;
          input = bark::irregular_remesh(input, ro);
        }
        return bark::StressMesh::from(input);
      } catch (const bark::MeshError& e) {
        throw mesh_error(e);
      }
    }();
    totals.t_preprocess += since(tp);
    const auto ts = Clock::now();
    const size_t triangles_in = mesh.mesh().number_of_faces();  // after preprocessing
    std::optional<bark::StressCracker> cracker;
    try {
      cracker.emplace(std::move(mesh), params);
    } catch (const bark::StressParamError& e) {
      throw UserError(desc.file, where + "/bark/" + e.key, e.key + ": " + e.message);
    }
    {
      Progress bar("crack " + name, params.iterations, !o.quiet);
      cracker->run([&](int, int) { bar.advance(); });
      bar.finish();
    }
    const bark::CrackedMesh result = cracker->result();
    const double t_sim = since(ts);
    totals.t_simulate += t_sim;
    const auto tw = Clock::now();
    const std::string glb = (dir / (name + ".glb")).string();
    write_cracked_glb(glb, name, result);
    const bark::StressStats& st = cracker->stats();
    const nlohmann::json summary = {{"model", "stress"},
                                    {"object", name},
                                    {"preset", obj.stress_bark->preset},
                                    {"triangles_in", triangles_in},
                                    {"triangles_out", result.mesh.triangles.size()},
                                    {"iterations", st.iterations},
                                    {"cracks", st.cracks},
                                    {"crack_edges", st.crack_edges},
                                    {"crack_length_m", result.crack_length()},
                                    {"snapped", st.snapped},
                                    {"edge_splits", st.splits},
                                    {"threshold_absolute", cracker->absolute_threshold()},
                                    {"time_s", {{"simulate", t_sim}}}};
    const std::string json = (dir / (name + ".json")).string();
    write_atomically(json, [&](const std::string& tmp) {
      std::ofstream f(tmp);
      f << summary.dump(2) << "\n";
      if (!f) throw UserError(json, "", "cannot write the summary");
    });
    totals.t_write += since(tw);
    ++totals.objects;
    totals.triangles_in += (long long)triangles_in;
    totals.triangles_out += (long long)result.mesh.triangles.size();
    totals.cracks += st.cracks;
    totals.crack_edges += st.crack_edges;
    totals.iterations = std::max(totals.iterations, st.iterations);
    totals.crack_length += result.crack_length();
    totals.outputs.push_back(glb);
  }
  return totals;
}

}  // namespace phellem
