// Memory estimates: what every stage of a command will hold, worked out from the scene before
// any stage runs (strip simulations, fracture fields and bark meshes, stress cracking, the
// diced geometry, the film and its output copies), and the budget it must fit in: a share of
// physical memory, or the user's --memory-limit / PHELLEM_MEMORY_LIMIT. A scene over budget is
// refused at once, at the JSON path or option of the knob that bounds its largest part,
// instead of failing in bad_alloc (or being killed) after minutes of work.
//
// The per-unit costs are measured peak RSS (see memory_estimate.cpp); estimates aim at ±50 %.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace phellem {

// One thing a stage holds, and the knob that bounds it.
struct MemoryItem {
  std::string what;  // e.g. "the strip simulation of \"tree\" (4 limbs: 1200 strips, 9.4e+04 elements)"
  double bytes = 0;
  std::string file;    // the scene file; empty: the command line
  std::string where;   // JSON path or option of the knob; empty: no knob (the program itself)
  std::string advice;  // e.g. "raise strip_width (now 0.005 m) or element_length (now 0.01 m)"
};

// What is held together at one moment of a command (a stage, with what earlier ones left).
struct MemoryMoment {
  std::string stage;
  std::vector<MemoryItem> items;
  double bytes() const;
};

enum class MemoryCommand { Render, Growth, Simulate };  // turntable: Render (one scene, many frames)

struct MemoryRequest {
  MemoryCommand command = MemoryCommand::Render;
  int height = 0;                         // render, growth: the film's height (screen-space dicing)
  MemoryItem film;                        // render, growth: the film and its outputs (renderer/film_memory.h)
  int field_width = 0, field_height = 0;  // simulate --res: every fracture field's size (0: the scene's)
  bool meshes = true;                     // simulate: the bark meshes are written (no --no-mesh)
  MemoryItem section;                     // slice: the section image, drawn after the growth (0 bytes: none)
};

struct MemoryEstimate {
  std::vector<MemoryMoment> moments;
  const MemoryMoment& peak() const;
};

// Throws UserError when a strip bark exceeds the strip model's own limits (10^6 strips,
// 2·10^7 elements per limb) or a stress mesh the remesher's (2·10^7 triangles): the same
// refusals the models make, made before any of them is built. Mesh files with stress bark or
// displacement are read to count their triangles.
MemoryEstimate estimate_memory(const SceneDesc& desc, const MemoryRequest& request);

// The surface a growth starts from, as its memory and time estimates see it before it is
// built (a closed surface has about two triangles per vertex).
struct GrowthInputSize {
  double vertices = 0;
  double area = 0;       // m²
  double mean_edge = 0;  // m: of that many equilateral triangles over that area
};
GrowthInputSize growth_input_size(const ObjectDesc& o);

}  // namespace phellem
