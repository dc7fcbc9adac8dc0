// The parameters `phellem fit` searches, normalized to [0, 1] (log-mapped where marked), and
// how each value is applied to a model's parameters. Adding a knob is one row in
// strip_fit_table() or stress_fit_table() (compare/fit_parameters.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "compare/stress_patch.h"
#include "compare/strip_patch.h"

namespace phellem {

enum class FitModel { strips, stress };

// What one evaluation simulates: the parameters of the model being fitted.
struct FitCandidate {
  FitModel model = FitModel::strips;
  StripPatchParams strips;
  StressPatchParams stress;
};

struct FitParameter {
  std::string key;  // JSON path under the scene's `bark` object, e.g. "depth/depth_per_width"
  double lo = 0, hi = 1;
  bool log = false;
  // Sets the value (already rounded to float, as the scene parser reads numbers). Rows are
  // applied in table order, so a row may read what earlier rows set.
  std::function<void(double value, FitCandidate&)> apply;
  // The value a candidate has (to place the presets in the normalized space).
  std::function<double(const FitCandidate&)> read;

  double value(double x) const;       // x ∈ [0, 1] → [lo, hi]
  double normalized(double v) const;  // the inverse, clamped to [0, 1]
};

struct FitSpace {
  FitModel model = FitModel::strips;
  std::string preset;  // the preset the fixed parameters come from (written to fitted.json)
  FitCandidate base;   // fixed parameters
  std::vector<FitParameter> table;
  // Known good starting points (normalized): the model's presets that fit the photo's kind of bark.
  std::vector<std::vector<double>> starts;

  size_t dimension() const { return table.size(); }
  // The base with every row applied at x (x.size() == dimension()).
  FitCandidate candidate(const std::vector<double>& x) const;
  // The values of every row at x, for reports.
  std::vector<double> values(const std::vector<double>& x) const;
};

// The space restricted to the rows named (the others keep the base's values); the starts
// are the base's values. Throws std::logic_error for an unknown key.
FitSpace restrict_space(const FitSpace& s, const std::vector<std::string>& keys);

// The linear row `key` searched over [centre − half_width, centre + half_width] instead of its
// own range, every start at the centre: for a parameter the photo all but measures (the
// fissures' lean, spiral_deg). Throws std::logic_error for an unknown or log-mapped key.
void narrow_row(FitSpace& s, const std::string& key, double centre, double half_width);

// A row that sets one member of the strip candidate's relief (bark::ReliefLook).
FitParameter relief_row(std::string key, double lo, double hi, bool log, double bark::ReliefLook::*member);

FitSpace strip_fit_space();
FitSpace stress_fit_space();
FitSpace fit_space(FitModel model);

// Simulates the candidate at the photo's size and scale with one simulation seed.
HeightField simulate_candidate(const FitCandidate& c, const PatchSize& size, uint64_t seed);

}  // namespace phellem
