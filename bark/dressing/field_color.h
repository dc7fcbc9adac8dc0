// Dressed colour of a FractureField (Lefebvre & Neyret 2002, sec. 3.3 "Texturing"): epidermis
// colour outside fractures, fracture-interior colour inside, darkened with normalized depth
// (the papers' depth darkening). Flat colours for now; texture samples come with BarkSurface.
#pragma once

#include <Eigen/Core>

#include "bark/strips/fracture_field.h"

namespace phellem::bark {

struct FieldColors {
  Eigen::Vector3f epidermis{0.32f, 0.27f, 0.22f};
  Eigen::Vector3f fracture{0.42f, 0.27f, 0.16f};
  Eigen::Vector3f hardened{0.36f, 0.26f, 0.19f};  // refractured old fracture surface
  float depth_darkening = 0.7f;                   // albedo × (1 − k · depth / max_depth)
};

void dress_colors(FractureField& field, const FieldColors& colors, double max_depth);

}  // namespace phellem::bark
