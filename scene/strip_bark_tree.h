// The strip-model bark of one scene `tree`: its cylinders (trunk and branches, from
// build_tree) simulated together (bark::TreeStripBark), dressed into FractureFields and handed
// to the renderer as FieldBarkSurfaces. Used by `phellem simulate` (fields to EXR), by the render
// scene (displacement and shading) and by `phellem growth` (frames along the simulation).
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bark/dressing/field_bark_surface.h"
#include "bark/dressing/field_color.h"
#include "bark/strips/tree_bark.h"
#include "io/gltf_writer.h"
#include "scene/scene_desc.h"
#include "scene/strip_bark_desc.h"
#include "scene/tree_surface.h"

namespace phellem {

class TreeStripSimulation {
 public:
  // Builds the models. A parameter the built surface cannot take is a UserError at
  // /objects/<index>/bark/<key>. `seed` overrides the scene's.
  TreeStripSimulation(const ObjectDesc& tree, size_t object_index, std::optional<uint64_t> seed = {});

  // Grows until `step` (clamped to the total), showing progress when asked. The models advance
  // by blocks of bark::kBlockSteps, so the bark then shows the end of the block `step` falls
  // in (steps_done() >= step).
  void run_to(int step, bool progress);
  void run(bool progress) { run_to(steps_total(), progress); }
  int steps_done() const { return sim_->model(0).steps_done(); }
  int steps_total() const { return sim_->model(0).steps_total(); }
  // Girth at `step` relative to the final shape (≤ 1): frame k of a growth time-lapse draws the
  // tree at the scale of its own step, so the trunk thickens smoothly however many frames there
  // are, with the bark of the block its step falls in (fracture widths within 8 steps, 1 % of
  // girth at the presets' growth rate, of the frame's own). Horizontal fractures come from
  // axial growth: the limbs keep their girth (and, in growth frames, their final length: the
  // stretch shows in the bark only).
  double girth_scale(int step) const {
    const bark::StripModel& m = sim_->model(0);
    return m.domain().along_axis ? 1.0 : m.scale_at_step(std::clamp(step, 0, steps_total()));
  }

  size_t parts() const { return parts_.size(); }
  // "trunk", "branch1", ...
  std::string part_name(size_t k) const { return k == 0 ? "trunk" : "branch" + std::to_string(k); }
  const bark::TreeStripBark& bark() const { return *sim_; }
  const StripBarkDesc& desc() const { return *desc_; }

  // The dressed field of part k in the current state; 0 × 0 picks the scene's resolution or,
  // without one, texels a quarter of a strip wide.
  bark::FractureField field(size_t k, int width = 0, int height = 0) const;
  // The bark mesh of part k with the fracture geometry inserted (bark::mesh_fracture_field on
  // the field at `width` × `height`, 0: texels half a strip wide), mapped onto the cylinder and
  // sunk by the depth; "epidermis" and "fracture" parts sharing the vertices.
  GlbMesh mesh(size_t k, int width = 0, int height = 0) const;
  // Every part's BarkSurface in the current state, at the automatic resolution.
  std::vector<std::shared_ptr<const bark::FieldBarkSurface>> surfaces() const;

 private:
  std::shared_ptr<const StripBarkDesc> desc_;
  std::vector<TreePart> parts_;
  std::unique_ptr<bark::TreeStripBark> sim_;
  std::string label_;
};

}  // namespace phellem
