#include "cli/simulate_stress.h"

#include <chrono>

#include "cli/outputs.h"
#include "io/cracked_mesh_io.h"
#include "scene/stress_bark_run.h"

namespace phellem {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

StressRunTotals simulate_stress_objects(const cli::Options& o, const SceneDesc& desc, const std::filesystem::path& dir,
                                        OutputSet& out) {
  StressRunTotals totals;
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& obj = desc.objects[oi];
    if (!obj.stress_bark || obj.growth) continue;  // grown objects: simulate_growth.cpp
    const std::string name = obj.name.empty() ? "mesh" + std::to_string(oi) : obj.name;
    const StressRun run = run_stress_object(desc, oi, o.seed, !o.quiet);
    const bark::CrackedMesh& result = *run.cracked;
    totals.t_preprocess += run.preprocess_s;
    totals.t_simulate += run.simulate_s;
    const auto tw = Clock::now();
    const std::string glb = (dir / (name + ".glb")).string();
    out.write("-o", glb, [&](const std::string& tmp) { write_cracked_glb(tmp, name, result); });
    const bark::StressStats& st = run.stats;
    const nlohmann::json summary = {{"model", "stress"},
                                    {"object", name},
                                    {"preset", obj.stress_bark->preset},
                                    {"triangles_in", run.triangles_in},
                                    {"triangles_out", result.mesh.triangles.size()},
                                    {"iterations", st.iterations},
                                    {"cracks", st.cracks},
                                    {"crack_edges", st.crack_edges},
                                    {"crack_length_m", result.crack_length()},
                                    {"snapped", st.snapped},
                                    {"edge_splits", st.splits},
                                    {"threshold_absolute", run.threshold_absolute},
                                    {"time_s", {{"preprocess", run.preprocess_s}, {"simulate", run.simulate_s}}}};
    const std::string json = (dir / (name + ".json")).string();
    write_json_output(out, "-o", json, summary);
    totals.t_write += since(tw);
    ++totals.objects;
    totals.triangles_in += (long long)run.triangles_in;
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
