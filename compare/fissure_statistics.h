// The fissure statistics of a height field (docs/compare.md documents each one and every
// fixed parameter). Every figure is invariant to a positive affine change of the heights.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compare/compare_params.h"  // CompareParams, kCompareParams
#include "compare/height_field.h"

namespace phellem {

inline constexpr int kOrientationBins = 18;  // 10° bins centred on 0°, 10°, …, 170°

struct ColourStats {
  double L_mean = 0, L_std = 0, a_mean = 0, a_std = 0, b_mean = 0, b_std = 0;  // OKLab
  double contrast = 0;  // median L on ridges − median L in fissures
};

struct FissureStats {
  double fissure_fraction = 0;
  double vertical_fraction = 0;
  double orientation_mean_deg = 0;  // circular mean, 90° = along the trunk
  std::array<double, kOrientationBins> orientation_hist{};  // length-weighted, sums to 1
  double spacing_h_mean = 0, spacing_h_std = 0;  // cm, along rows
  double spacing_v_mean = 0, spacing_v_std = 0;  // cm, along columns
  double width_mean = 0, width_std = 0;          // cm
  double length_median = 0;                      // cm, median vertical extent of fissures
  double depth_ratio = 0;                        // fissure depth / ridge relief
  double skeleton_length_cm = 0;                 // Σ length weights of the skeleton
  int components = 0;                            // fissure components kept
  std::optional<ColourStats> colour;
  // The samples behind the figures, for the report's histograms.
  std::vector<double> spacings_h_cm, widths_cm;
};

// The measured field with its fissure mask, kept for the report's overlays.
struct FissureAnalysis {
  HeightField field;           // as measured (at the common scale)
  std::vector<uint8_t> mask;   // 1 = fissure, same pixels as field
  FissureStats stats;
};

// Measures `field` (already at the common scale). Throws UserError (file = `name`) when the
// field is too small, too coarse or has constant relief. `albedo`, when given, has the same size.
FissureAnalysis analyse_fissures(const HeightField& field, const AlbedoField* albedo, const std::string& name);

}  // namespace phellem
