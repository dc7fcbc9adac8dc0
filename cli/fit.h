// `phellem fit HEIGHT_IMAGE --scale PX_PER_CM --model strips|stress -o DIR`: searches the
// model's parameters so that a simulated patch at the photo's scale matches the photo's
// fissure statistics (docs/plans/issue-22-compare-fit.md §4), and writes into DIR
// fitted.json (a trunk scene with the fitted bark), patch.exr (the fit at the photo's size
// and scale), report.html and report.json (the compare report of the fit vs the photo).
#pragma once

#include "cli/options.h"

namespace phellem {
int run_fit(const cli::Options& o);
}
