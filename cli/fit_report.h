// report.json and report.html of `phellem fit`: the compare report of the fitted patch vs the
// photo, plus what the fit did (parameters, evaluations, spread over the seeds, time).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "compare/compare_score.h"
#include "compare/fissure_statistics.h"
#include "util/output_set.h"

namespace phellem {

struct FitReportInputs {
  const FissureAnalysis* photo = nullptr;  // at the common scale
  const FissureAnalysis* patch = nullptr;
  Comparison comparison;
  std::string photo_name, patch_name;
  nlohmann::json fit;  // the fit's own summary (model, parameters, evaluations, …)
};

// Stages DIR/report.json and DIR/report.html in `out` (option -o).
void write_fit_reports(OutputSet& out, const std::string& dir, const FitReportInputs& in);

}  // namespace phellem
