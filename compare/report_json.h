// The compare report's figures for scripts: score, orientation_emd_deg, verdict, the band,
// every fixed parameter and, per input, every statistic by name.
#pragma once

#include <nlohmann/json.hpp>

#include "compare/compare_inputs.h"

namespace phellem {

nlohmann::json report_json(const CompareReport& report);

}  // namespace phellem
