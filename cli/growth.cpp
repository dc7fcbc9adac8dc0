#include "cli/growth.h"

#include <cmath>
#include <map>
#include <memory>

#include "cli/frame_sequence.h"
#include "cli/outputs.h"
#include "cli/render_job.h"
#include "renderer/render_scene.h"
#include "scene/growth_run.h"
#include "scene/strip_bark_tree.h"
#include "util/progress.h"
#include "util/errors.h"

namespace phellem {

namespace {

void scale_radii(std::vector<BranchDesc>& branches, float k) {
  for (BranchDesc& b : branches) {
    for (float& r : b.radius) r *= k;
    scale_radii(b.branches, k);
  }
}

}  // namespace

int run_growth(const cli::Options& o) {
  check_view(o);
  check_frame_outputs(o);
  OutputSet out;
  expect_outputs(o, out);
  Loaded l = load(o);
  expect_scene_inputs(l.desc, out);
  std::vector<std::pair<size_t, std::unique_ptr<TreeStripSimulation>>> sims;
  for (size_t oi = 0; oi < l.desc.objects.size(); ++oi) {
    const ObjectDesc& obj = l.desc.objects[oi];
    if (obj.type == ObjectType::Tree && obj.tree.strip_bark)
      sims.emplace_back(oi, std::make_unique<TreeStripSimulation>(obj, oi, o.seed));
  }
  // Cambial growth of meshes (Kratt et al.): each frame shows the surface at its step.
  std::vector<std::pair<size_t, bark::CambialGrowth>> growths;
  std::map<size_t, std::shared_ptr<const bark::TextureScaleField>> start_scales;  // the texture cells' reference (sec. 4.6)
  for (size_t oi = 0; oi < l.desc.objects.size(); ++oi)
    if (l.desc.objects[oi].growth) {
      growths.emplace_back(oi, start_growth(l.desc, oi, !o.quiet));
      start_scales[oi] = start_texture_scale(growths.back().second);
    }
  if (sims.empty() && growths.empty())
    throw UserError(o.scene, "/objects",
                    "nothing grows: no tree object has a \"bark\": {\"model\": \"strips\"} and no mesh a \"growth\"");
  // Bark that does not grow with the frames (stress bark) is simulated once.
  BarkResults still;
  for (size_t oi = 0; oi < l.desc.objects.size(); ++oi) {
    const ObjectDesc& obj = l.desc.objects[oi];
    if (has_simulated_bark(obj) && !obj.growth && !(obj.type == ObjectType::Tree && obj.tree.strip_bark && !obj.stress_bark))
      still.objects.emplace(oi, simulate_object_bark(l.desc, oi, !o.quiet));
  }
  const int frames = *o.frames;
  for (int f = 0; f < frames; ++f) {
    SceneDesc frame_desc = l.desc;
    BarkResults bark = still;
    for (auto& [oi, sim] : sims) {
      const int step = int(std::lround(double(sim->steps_total()) * double(f + 1) / double(frames)));
      sim->run_to(step, !o.quiet);
      // The simulation lives on the final shape (shrinking strategy); the frame shows the tree
      // at the girth of this step.
      const float k = float(sim->girth_scale(step));
      TreeDesc& tree = frame_desc.objects[oi].tree;
      for (float& r : tree.radius) r *= k;
      scale_radii(tree.branches, k);
      bark.objects[oi].strip_parts = sim->surfaces();
    }
    for (auto& [oi, g] : growths) {
      const int step = int(std::lround(double(g.steps_total()) * double(f + 1) / double(frames)));
      const std::string name = l.desc.objects[oi].name.empty() ? "mesh" + std::to_string(oi) : l.desc.objects[oi].name;
      Progress bar("grow " + name, step - g.steps_done(), !o.quiet && step > g.steps_done());
      while (g.steps_done() < step && g.step()) bar.advance();
      bar.finish();
      // Stress bark: the cracks as they stand at this step (they open as the surface grows).
      GrownBark now = grown_bark(g, *l.desc.objects[oi].growth, *start_scales.at(oi));
      ObjectBark& b = bark.objects[oi];
      b.grown = std::move(now.surface);
      b.cracked = std::move(now.cracked);
      b.texture_levels = std::move(now.texture_levels);
    }
    const auto scene = build_render_scene(frame_desc, bark, frame_desc.camera, l.width, l.height, !o.quiet);
    render_frame(o, l, *scene, Camera(frame_desc.camera, l.width, l.height), f, frames, out);
  }
  if (!o.mp4.empty()) encode_mp4(o, out);
  out.commit();
  return 0;
}

}  // namespace phellem
