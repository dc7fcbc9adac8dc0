// How long each cambial growth of a scene will take, worked out before it starts (as the memory
// is, memory_estimate.h): a growth of 100000 steps may run for hours, which the user should
// hear of up front, and which a command refuses over its time limit (cli/memory_check.h).
//
// The costs are measured on the project's machine (growth_time.cpp) and aim at a factor of two:
// enough to tell minutes from hours.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace phellem {

struct GrowthTime {
  std::string object;    // its name, or mesh<N> / tree<N>
  std::string file;      // the scene
  std::string where;     // the growth's steps: /objects/N/growth/steps
  int steps = 0;
  double vertices = 0;   // interface vertices, the mean over the steps
  double seconds = 0;    // TetGen's set-up and the steps (with the crack coupling)
};

// One per growing object, in object order. Reads mesh files (for their size) as the memory
// estimate does.
std::vector<GrowthTime> estimate_growth_times(const SceneDesc& desc);

// "45 s", "12 min", "3 h 20 min", "2 d 5 h": a duration as people say it.
std::string human_duration(double seconds);

}  // namespace phellem
