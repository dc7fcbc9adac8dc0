// Where the strips live (Lefebvre & Neyret 2002, sec. 5.2–5.3): a generalized cylinder (cyclic
// strips whose length and width vary along and around the axis) or a flat sample. Each strip
// keeps its substrate metric in the final (s, θ) parameter space: the arc length of M angular
// bins at the final shape and each bin's growth exponent (1 + dilatation). The substrate at
// step t is the final one shrunk by G^{-(T - t)(1 + d)} per bin: the shrinking strategy.
#pragma once

#include <vector>

#include "bark/geometry/generalized_cylinder.h"
#include "bark/strips/strip_params.h"

namespace phellem::bark {

struct StripMetric {
  double s = 0;                    // centre of the strip along the axis (m)
  std::vector<double> bin_length;  // #M final arc length of each angular bin (m)
  std::vector<double> exponent;    // #M growth exponent 1 + d(s, θ); empty: homogeneous
  std::vector<double> width;       // #M local strip width / nominal width (sec. 5.3)
};

struct StripDomain {
  double length = 0;       // extent along the axis (m)
  double strip_width = 0;  // nominal w (m)
  bool cyclic = true;      // strips close around (trees, tileable samples)
  bool wrap_s = false;     // propagation wraps from the last strip to the first (tileable)
  // Strips run along a cylinder's axis (horizontal fractures): strip j lies at angle
  // θ = 2π (j + ½) / n, position along a strip is s, and `length` is the mean circumference.
  bool along_axis = false;
  double axis_length = 0;  // along_axis: the cylinder's length (m)
  std::vector<StripMetric> strips;
  int bins() const { return strips.empty() ? 0 : int(strips[0].bin_length.size()); }
};

// The domain builders throw StripParamError (key strip_width) rather than make more strips
// than this: 10^6 strips of 5 mm span a 5 km trunk.
inline constexpr double kMaxStrips = 1e6;

// Strips over a generalized cylinder: strip_width from the params, M angular bins.
StripDomain cylinder_domain(const GeneralizedCylinder& cylinder, const StripParams& p, int bins = 64);
// Strips along the axis of a generalized cylinder (FractureOrientation::Horizontal): about
// one per strip_width of mean circumference, M bins along s each; a strip's width follows the
// local circumference, so fracture density stays constant where the limb thins.
StripDomain longitudinal_domain(const GeneralizedCylinder& cylinder, const StripParams& p, int bins = 64);
// The strips a cylinder's bark runs on for the params' orientation: cylinder_domain
// (vertical fractures) or longitudinal_domain (horizontal).
StripDomain oriented_domain(const GeneralizedCylinder& cylinder, const StripParams& p);
// A flat sample `width` × `height` metres (θ maps to x = θ/2π · width).
StripDomain flat_domain(double width, double height, const StripParams& p, int bins = 64);

}  // namespace phellem::bark
