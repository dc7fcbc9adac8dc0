// The memory `phellem fit` needs, worked out from the photo's size and scale before any work
// (scene/memory_estimate.h does the same for scenes), and its check against the budget
// (--memory-limit, PHELLEM_MEMORY_LIMIT, a share of physical memory, the address-space limit).
// The photo's pixels bound everything: the search's patches at the evaluation scale, the
// choice's and the relief stage's at the final scale, and the last patch and its compare report
// at the photo's own size and scale.
#pragma once

#include <string>

#include "compare/patch_size.h"
#include "scene/memory_estimate.h"

namespace phellem {

struct FitMemoryRequest {
  std::string photo;   // the height image's path (the refusal's file)
  PatchSize full;      // the photo: the last patch and the report
  PatchSize eval;      // the search's patches
  PatchSize final;     // the choice's and the relief stage's patches
  int search_parallel = 2;  // evaluations the search runs at a time
  int final_parallel = 2;   // patches simulated at a time at the final scale (the threads)
  bool stress = false;
};

MemoryEstimate estimate_fit_memory(const FitMemoryRequest& request);
// Throws UserError at the height image (or --memory-limit) when the fit would not fit.
void check_fit_memory(const FitMemoryRequest& request, const std::string& memory_limit);

}  // namespace phellem
