// Every fissure statistic by name, with its unit and a one-line description: the rows of the
// report's table and the keys of its JSON (docs/compare.md describes each in full).
#pragma once

#include <string>
#include <vector>

#include "compare/fissure_statistics.h"

namespace phellem {

struct NamedStatistic {
  std::string name, unit, description;
  double value = 0;
  bool core = false;  // part of the score
};

std::vector<NamedStatistic> named_statistics(const FissureStats& s);

}  // namespace phellem
