// Ridge relief and rough fissure walls of a dressed FractureField: what makes the plates of
// strip bark read as bark instead of flat plateaus cut by smooth V/U trenches.
//  - shoulder: a ridge rounds down towards the fissure lips, its height a function of the
//    distance d to the nearest fissure, h = −S·(1 − d/w)² for d < w (a parabolic shoulder:
//    steepest at the lip, level with the plate at d = w), merged into the fissure wall
//    (depth = max(wall, shoulder): continuous at the lip);
//  - detail: tileable fbm over the ridges and the fissures (it repeats exactly around θ);
//  - rough walls: the fissure's depth profile (DepthProfile) × (1 + ε·n), n a zero-mean,
//    unit-RMS tileable fbm, so the walls deviate from the profile by a relative RMS ε.
// The ridge relief (shoulder + detail together) is scaled so that the field's depth ratio
//   (median ridge height − median fissure height) / (P90 − P10 of the ridge heights)
// equals the requested one (`depth_ratio`, real bark ≈ 1–2; issue 22): its amplitude is
// relative to the fissure depth the strip model produced.
#pragma once

#include <cstdint>

#include "bark/strips/fracture_field.h"

namespace phellem::bark {

struct ReliefLook {
  bool enabled = false;           // off: the field's depth is left exactly as rasterized
  bool ridges = true;             // false: no ridge relief (flat plates), only the rough walls
  double depth_ratio = 1.5;       // target (median ridge − median fissure height) / ridge P90−P10
  double shoulder_width = 0.012;  // m over which a ridge rounds down to the lip
  double detail = 0.4;            // share of the ridge relief that is fbm detail (rest: shoulder)
  double detail_size = 0.008;     // m, the detail's first octave
  double wall_noise = 0.15;       // relative RMS of the fissure depth noise (rough walls)
  double wall_size = 0.004;       // m, the wall noise's first octave
  uint32_t seed = 1;
};

// Zero-mean tileable fbm (4 octaves of value noise, gain 0.5) at (x, y) metres with first
// octave `size`; it repeats exactly with period_x / period_y (0: no period).
float tileable_fbm(double x, double y, double size, double period_x, double period_y, uint32_t seed);

// (median ridge − median fissure height) / (P90 − P10 of ridge heights), heights = −depth;
// fissure pixels: opening ≥ 0.5, ridge pixels: no fissure within one pixel (8-neighbours, the
// compare's ridge = NOT(dilated mask)). 0 without ridges or fissures or with flat ridges.
double depth_ratio(const FractureField& field);

// Distance (m) of each pixel to the nearest fissure pixel (opening ≥ 0.5), periodic around θ
// (Felzenszwalb & Huttenlocher 2012, the exact squared Euclidean distance transform in 1D
// passes, with the field's own pixel sizes C/W × L/H). Infinity without fissures.
std::vector<float> fissure_distance(const FractureField& field);

// Rough walls alone: every pixel with depth > 0 × (1 + ε·n), n standardized over them.
void roughen_walls(FractureField& field, const ReliefLook& look);

struct ReliefResult {
  double scale = 0;  // m: amplitude of the unit ridge relief
  double ratio = 0;  // the depth ratio reached
};

// Adds the relief to field.depth (call before dress_colors). Without `ridges`, only the rough
// walls, and the result is {0, 0} (no ratio is aimed at or measured). Fields without fissures or
// ridges get only the walls' noise and the detail at 1/depth_ratio of the profile's max depth.
// A ratio below what the relief can reach (mostly-shoulder relief on sparse fissures, or a
// relief amplitude above twice the profile's max depth) gives the lowest reachable one:
// `ratio` reports what was reached.
ReliefResult apply_relief(FractureField& field, const ReliefLook& look, const DepthProfile& profile);

}  // namespace phellem::bark
