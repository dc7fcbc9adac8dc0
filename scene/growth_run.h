// Runs the cambial growth of one scene mesh object with `"growth"` (bark/growth/
// cambial_growth.h): its mesh in world space (file or procedural, the transform applied), the
// obstacles it names, the steps with a progress bar. Shared by `phellem simulate`,
// `phellem growth` (one frame per step it is asked for), `phellem slice` and the renderer's
// bark stage.
#pragma once

#include <functional>
#include <memory>

#include "bark/growth/cambial_growth.h"
#include "bark/growth/texture_cells.h"
#include "scene/scene_desc.h"

namespace phellem {

// A growth as it stands, as it is written and rendered: its interface in world space with UV
// seams cut open (bark/geometry/uv_seams.h), the cracks when coupled (cut the same way), and
// the texture cell levels of the mesh rendered (sec. 4.6).
struct GrownBark {
  std::shared_ptr<const bark::TriMesh> surface;  // UVs when the input had them
  std::shared_ptr<const bark::CrackedMesh> cracked;  // with stress bark (and cracks on): cracked as it grew
  // Per vertex of `cracked` when there is one, else of `surface`: bark/growth/texture_cells.h
  // (empty with "texture_cells": false or without UVs).
  std::vector<Eigen::Vector2f> texture_levels;
};

// The texture scales the cell levels are measured against: the surface before it grows.
std::shared_ptr<const bark::TextureScaleField> start_texture_scale(const bark::CambialGrowth& g);
GrownBark grown_bark(const bark::CambialGrowth& g, const GrowthDesc& desc, const bark::TextureScaleField& start_scale);

struct GrowthRun : GrownBark {
  std::vector<bark::GrowthRing> rings;
  bark::CambialGrowthStats stats;
  int steps = 0;
};

// The growth's surface and obstacles, tetrahedralized (TetGen) and ready to step, its cracks
// coupled when the object has stress bark; a progress line while TetGen runs when asked
// (errors name the scene).
bark::CambialGrowth start_growth(const SceneDesc& desc, size_t object_index, bool progress = false);

// All steps; `on_step(growth)` after each (time-lapse frames), when given.
GrowthRun run_growth_object(const SceneDesc& desc, size_t object_index, bool progress,
                            const std::function<void(const bark::CambialGrowth&)>& on_step = {});


}  // namespace phellem
