#include "cli/growth.h"

#include <cmath>
#include <memory>

#include "cli/frame_sequence.h"
#include "cli/outputs.h"
#include "cli/render_job.h"
#include "renderer/render_scene.h"
#include "scene/strip_bark_tree.h"
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
  std::vector<std::pair<size_t, std::unique_ptr<TreeStripSimulation>>> sims;
  for (size_t oi = 0; oi < l.desc.objects.size(); ++oi) {
    const ObjectDesc& obj = l.desc.objects[oi];
    if (obj.type == ObjectType::Tree && obj.tree.strip_bark)
      sims.emplace_back(oi, std::make_unique<TreeStripSimulation>(obj, oi, o.seed));
  }
  if (sims.empty()) throw UserError(o.scene, "/objects", "no tree object has a \"bark\": {\"model\": \"strips\"} to grow");
  // Bark that does not grow with the frames (stress bark) is simulated once.
  BarkResults still;
  for (size_t oi = 0; oi < l.desc.objects.size(); ++oi) {
    const ObjectDesc& obj = l.desc.objects[oi];
    if (has_simulated_bark(obj) && !(obj.type == ObjectType::Tree && obj.tree.strip_bark && !obj.stress_bark))
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
    const auto scene = build_render_scene(frame_desc, bark, frame_desc.camera, l.width, l.height, !o.quiet);
    render_frame(o, l, *scene, Camera(frame_desc.camera, l.width, l.height), f, frames, out);
  }
  if (!o.mp4.empty()) encode_mp4(o, out);
  out.commit();
  return 0;
}

}  // namespace phellem
