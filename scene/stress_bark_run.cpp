#include "scene/stress_bark_run.h"

#include <chrono>

#include "bark/geometry/irregular_remesh.h"
#include "scene/mesh_source.h"
#include "util/errors.h"
#include "util/progress.h"

namespace phellem {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

StressRun run_stress_object(const SceneDesc& desc, size_t oi, std::optional<uint64_t> seed, bool progress) {
  const ObjectDesc& obj = desc.objects.at(oi);
  if (!obj.stress_bark) throw std::logic_error("run_stress_object: the object has no stress bark");
  const std::string where = "/objects/" + std::to_string(oi);
  const std::string name = obj.name.empty() ? "mesh" + std::to_string(oi) : obj.name;
  bark::StressParams params = obj.stress_bark->params;
  if (seed) params.seed = *seed;
  StressRun run;
  const auto tp = Clock::now();
  // Stages: the surface (a tree's tubes joined), the remeshing, the stress mesh and its set-up.
  Progress prepare("prepare " + name, 3, progress);
  bark::TriMesh input = object_trimesh(obj);
  prepare.advance();
  // The mesh's own problems are reported at the mesh file, or at the object for procedural ones.
  bark::StressMesh mesh = [&] {
    try {
      if (obj.stress_bark->preprocess.enabled) {
        bark::RemeshOptions ro;
        ro.edge_length = obj.stress_bark->preprocess.edge_length;
        ro.jitter = obj.stress_bark->preprocess.jitter;
        ro.seed = params.seed;
        input = bark::irregular_remesh(input, ro);
      }
      prepare.advance();
      return bark::StressMesh::from(input);
    } catch (const bark::MeshError& e) {
      if (e.where == "edge_length") throw UserError(desc.file, where + "/bark/preprocess/edge_length", e.what());
      if (obj.file.empty()) throw UserError(desc.file, where + "/procedural", e.where + ": " + e.what());
      throw UserError(obj.file, e.where, e.what());
    }
  }();
  run.preprocess_s = since(tp);
  run.triangles_in = mesh.mesh().number_of_faces();
  const auto ts = Clock::now();
  std::optional<bark::StressCracker> cracker;
  try {
    cracker.emplace(std::move(mesh), params);
  } catch (const bark::StressParamError& e) {
    throw UserError(desc.file, where + "/bark/" + e.key, e.key + ": " + e.message);
  }
  prepare.advance();
  prepare.finish();
  {
    Progress bar("crack " + name, params.iterations, progress);
    cracker->run([&](int, int) { bar.advance(); });
    bar.finish();
  }
  run.cracked = std::make_shared<const bark::CrackedMesh>(cracker->result());
  run.stats = cracker->stats();
  run.threshold_absolute = cracker->absolute_threshold();
  run.simulate_s = since(ts);
  return run;
}

}  // namespace phellem
