// Every lit statistic by name, with its unit and a one-line description: the rows (and bars) of
// a report and the keys of its JSON, as named_statistics does for the fissure statistics.
#pragma once

#include <vector>

#include "compare/lit_statistics.h"
#include "compare/statistic_names.h"  // NamedStatistic

namespace phellem {

// In a fixed order; `core` = a term of the lit score (its name is that of the LitDifference,
// except the orientation histogram, scored through its EMD and listed as orientation_bin_*).
std::vector<NamedStatistic> named_lit_statistics(const LitStatistics& s);

}  // namespace phellem
