// report.json and report.html of `phellem fit`: the compare report of the fitted patch vs the
// photo (compare/report_json.h, report_html.h), report.json with a `fit` object added (model,
// parameters, evaluations, spread over the seeds, time).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "compare/compare_inputs.h"
#include "util/output_set.h"

namespace phellem {

// Stages DIR/report.json and DIR/report.html in `out` (option -o).
void write_fit_reports(OutputSet& out, const std::string& dir, const CompareReport& report, const nlohmann::json& fit);

}  // namespace phellem
