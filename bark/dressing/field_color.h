// Dressed colour of a FractureField (Lefebvre & Neyret 2002, sec. 3.3 "Texturing"): the
// epidermis sample is mapped through the material coordinate UV0 stored at each break, so its
// pattern stays on the plate it was born on and is torn apart by the fractures; the fracture
// sample fills the opening, lighter where new material appears (per the fracture's opening
// mode, the field's `interior` channel) and older towards the lips; everything darkens with
// normalized depth (the papers' depth darkening).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "bark/dressing/bark_roughness.h"
#include "bark/strips/fracture_field.h"

namespace phellem::bark {

// A tileable colour sample in metres: an image (scene-linear RGB, repeating every
// size_x × size_y metres) or, without one, a procedural bark texture (fibres along the axis
// over value noise) around `base`.
struct ColorSample {
  Eigen::Vector3f base{0.5f, 0.5f, 0.5f};
  float variation = 0.25f;  // procedural: relative brightness variation
  double grain = 0.004;     // procedural: fibre spacing across the axis (m)
  uint32_t seed = 1;
  int width = 0, height = 0;  // image, when not empty
  std::vector<float> rgb;     // #height×#width×3, row 0 at the top
  double size_x = 0.1, size_y = 0.1;
  // x around, y along the axis (m). A non-zero period makes the sample repeat exactly with
  // it (its features are resized to fit a whole number of times): cyclic strips get no seam.
  Eigen::Vector3f at(double x, double y, double period_x = 0, double period_y = 0) const;

  static ColorSample procedural(const Eigen::Vector3f& base, float variation, double grain, uint32_t seed) {
    ColorSample s;
    s.base = base;
    s.variation = variation;
    s.grain = grain;
    s.seed = seed;
    return s;
  }
};

struct FieldColors {
  ColorSample epidermis = ColorSample::procedural({0.30f, 0.26f, 0.22f}, 0.30f, 0.006, 11);
  ColorSample fracture = ColorSample::procedural({0.40f, 0.25f, 0.15f}, 0.20f, 0.0025, 23);
  ColorSample hardened = ColorSample::procedural({0.34f, 0.25f, 0.19f}, 0.25f, 0.004, 37);  // refractured old fracture surface
  float interior_darkening = 0.35f;  // oldest fracture material × (1 − this) relative to the newest
  float depth_darkening = 0.7f;      // albedo × (1 − k · depth / max_depth)
  // Per-plate and per-fracture colour variation (a photo's distribution, scene/bark_photo):
  // each fracture multiplies its sample by fissure_tints[hash(id)]; the epidermis by a tint
  // picked per tint_size cell of its material coordinate (so a tint stays on its plate and
  // is torn apart with it). Empty: no tints.
  std::vector<Eigen::Vector3f> ridge_tints, fissure_tints;
  double tint_size = 0.04;  // m
  BarkRoughness roughness;  // off by default: the material's roughness
};

// Fills field.color; `initial_circumference` (m) scales the material coordinate UV0. With
// `tile_s` the samples also repeat along the axis with the field's length.
void dress_colors(FractureField& field, const FieldColors& colors, double max_depth, double initial_circumference,
                  bool tile_s = false);

}  // namespace phellem::bark
