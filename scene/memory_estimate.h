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

struct MemoryBudget {
  double bytes = 0;
  std::string source;  // how it was set, for messages: "75% of the 23.5 GiB of physical memory"
};

// Physical memory (MemTotal; a smaller cgroup limit wins), in bytes.
double physical_memory();
// "6G", "6GiB", "512M", "1.5T", "4096" (bytes), "50%" (of physical memory); K, M, G, T are
// powers of 1024. Throws std::invalid_argument.
double parse_memory_size(const std::string& text);
// `option`: the value of --memory-limit (empty: not given), else PHELLEM_MEMORY_LIMIT, else
// kDefaultMemoryShare of physical memory. A bad value is a UserError at its option / variable.
MemoryBudget memory_budget(const std::string& option);
inline constexpr double kDefaultMemoryShare = 0.75;

// Throws UserError at the knob of the largest item held at the peak, when the peak exceeds the
// budget.
void check_memory(const MemoryEstimate& estimate, const MemoryBudget& budget);
// The estimate as a table (phellem ... --memory-estimate).
std::string describe(const MemoryEstimate& estimate, const MemoryBudget& budget);
// "9.1 GiB", "640 MiB".
std::string format_bytes(double bytes);

}  // namespace phellem
