#include "compare/statistic_names.h"

namespace phellem {

std::vector<NamedStatistic> named_statistics(const FissureStats& s) {
  std::vector<NamedStatistic> v = {
      {"fissure_fraction", "", "share of the area in fissures", s.fissure_fraction, true},
      {"vertical_fraction", "", "share of fissure length within 30° of the trunk axis", s.vertical_fraction, true},
      {"orientation_mean_deg", "°", "circular mean fissure direction (90° = along the trunk)", s.orientation_mean_deg, false},
      {"spacing_h_mean", "cm", "distance between fissures along rows (across the trunk)", s.spacing_h_mean, true},
      {"spacing_h_std", "cm", "spread of that distance", s.spacing_h_std, true},
      {"spacing_v_mean", "cm", "distance between fissures along columns", s.spacing_v_mean, false},
      {"spacing_v_std", "cm", "spread of that distance", s.spacing_v_std, false},
      {"width_mean", "cm", "fissure area over skeleton length", s.width_mean, true},
      {"width_std", "cm", "spread of the local fissure width", s.width_std, false},
      {"length_median", "cm", "median vertical extent of a fissure", s.length_median, true},
      {"depth_ratio", "", "fissure depth over ridge relief", s.depth_ratio, true},
  };
  if (s.colour) {
    const ColourStats& c = *s.colour;
    v.push_back({"colour_L_mean", "", "OKLab lightness, mean", c.L_mean, false});
    v.push_back({"colour_L_std", "", "OKLab lightness, spread", c.L_std, false});
    v.push_back({"colour_a_mean", "", "OKLab a (green–red), mean", c.a_mean, false});
    v.push_back({"colour_a_std", "", "OKLab a, spread", c.a_std, false});
    v.push_back({"colour_b_mean", "", "OKLab b (blue–yellow), mean", c.b_mean, false});
    v.push_back({"colour_b_std", "", "OKLab b, spread", c.b_std, false});
    v.push_back({"colour_contrast", "", "median lightness of ridges minus fissures", c.contrast, false});
  }
  return v;
}

}  // namespace phellem
