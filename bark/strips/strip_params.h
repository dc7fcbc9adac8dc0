// Every user-controllable parameter of the strip model (Lefebvre & Neyret 2002, Figure 3,
// and sec. 5 for mapped bark). Stiffnesses are relative to the epidermis material stiffness
// R: only their ratios shape the equilibrium.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "bark/strips/strip.h"

namespace phellem::bark {

// A scalar image over the bark's (s, θ) parameter space: u = θ / 2π (columns, periodic),
// v = s / length (rows). Values in [0, 1].
// Bilinear sample of a W × H row-major grid at (x, y) in texel units (texel centres at
// (i + ½, j + ½)): x wraps, y clamps.
float sample_wrapped(const std::vector<float>& values, int W, int H, double x, double y);

struct ParamImage {
  int width = 0, height = 0;
  std::vector<float> values;  // #height×#width, row-major
  bool empty() const { return values.empty(); }
  float sample(double u, double v) const;  // bilinear, u wraps, v clamps
};

// A bulge of the dilatation field (sec. 5: "heterogeneous growth", e.g. root flare): extra
// growth `amount` (relative to the base growth) centred at (s, θ), Gaussian of the given
// widths along the axis (m) and around the circumference (rad).
struct DilatationBulge {
  double s = 0, theta = 0, sigma_s = 0.2, sigma_theta = 0.5, amount = 1.0;
};

// A fracture triggered by the user (the paper's interactive picking, sec. 4 / Figure 10).
struct ScriptedFracture {
  double s = 0;      // metres along the axis (flat samples: metres from the bottom)
  double theta = 0;  // radians (flat samples: θ = 2π·x / length)
  int step = 0;
};

// Which way the fractures run on a cylinder. Vertical (the paper's model): strips around
// the trunk, circumferential growth tears them along the axis. Horizontal (the discussion's
// variant, sec. 7): strips along the axis, axial growth tears them around the trunk, as in
// cherry or birch bark.
enum class FractureOrientation : uint8_t { Vertical, Horizontal };

struct StripParams {
  FractureOrientation orientation = FractureOrientation::Vertical;
  // Discretization.
  double strip_width = 0.01;     // w (m): strip spacing across the strips
  double element_length = 0.01;  // initial epidermis element length (m)
  int steps = 200;               // growth steps
  // Growth (sec. 3.2.3, 5.2): relative circumference growth per step, G > 1. The tree shape
  // given in the scene is the final one (the shrinking strategy of sec. 5.2).
  double growth_rate = 1.005;
  // Material (sec. 3.2.2, 3.2.5, 5.1).
  double stiffness = 1.0;  // R
  // K_f(l0): fracture element stiffness against its rest length l0 (m), piecewise linear;
  // one point = constant (the paper's default).
  std::vector<Eigen::Vector2d> fracture_stiffness{{0.0, 0.05}};
  double attachment = 0.02;  // K_a: attachment to the substrate per reference element
  // Fracture creation (sec. 3.2.3): threshold S on L / l0, jittered by ±noise on S − 1.
  std::optional<double> threshold;  // default: growth_rate (the paper's practice)
  double threshold_noise = 0.5;     // in [0, 1)
  double location_jitter = 0.6;     // in [0, 1]: spread of the break point inside an element
  ParamImage weakness;              // optional weakness map (1 = weakest)
  double weakness_strength = 0.8;   // how far the map lowers S − 1, in [0, 1)
  // Propagation (sec. 3.2.4): Inglis length-to-width threshold, influence a' of nearby
  // fractures (weight f(a'·dist/width), a threshold test), angular jitter.
  double inglis_threshold = 60;
  double influence = 0.25;
  double propagation_jitter_deg = 12;
  // A tip breaks the neighbouring strip only where that strip is still in tension: strain at
  // least this fraction of the element's own threshold strain. Inglis' iso-strain curves run
  // parallel to a fracture, so tips do not cut into bark another fracture has relaxed.
  double propagation_tension = 0.5;
  // Spiral grain (our extension, issue 22): a tip with no neighbouring fracture to follow
  // propagates along a helix at this angle to the axis on the grown trunk instead of along the
  // axis (the base direction that the jitter above perturbs), so the fissures wind round the
  // trunk as on spiral-grained trees (pines: commonly a few degrees). Positive: θ increases
  // upwards. In [-45, 45]; 0 is the paper.
  double spiral_deg = 0;
  // Irregular fissures (our extension, issue 22; every knob at 0 leaves the paper's model
  // unchanged bit for bit). Real bark's fissures have varying lengths, fork, meet and
  // interlace (anastomose) and are irregularly spaced; the paper's tips run on while the
  // bark across them is strained, so they cross the whole sample at a nearly constant pitch.
  // Tough spots (length variation): this fraction of the bark, in spots `toughness_size` (m)
  // long along the strip and one strip across, cannot be cut by a propagating tip (sec. 3.2.4
  // says a tip advances into strained bark; here tough bark also arrests it). The spot still
  // breaks when its own threshold is exceeded (sec. 3.2.3), starting a new, offset fracture.
  double toughness_fraction = 0;  // in [0, 1)
  double toughness_size = 0.02;   // > 0 (m)
  // Anastomosis: with this probability per advance, a tip that can advance deviates by up to
  // `anastomosis_reach` (m) sideways to meet another fracture in the next strip and merges
  // with it (the merge of 2001 sec. 4, sought out instead of met by chance).
  double anastomosis = 0;            // in [0, 1]
  double anastomosis_reach = 0.015;  // > 0 (m)
  // Forking: with this probability, a tip that cuts the next strip also cuts it a second time
  // `fork_offset` (m, ×[0.5, 1], either side) away; the branch belongs to the same fracture.
  double fork_probability = 0;  // in [0, 1]
  double fork_offset = 0.015;   // > 0 (m)
  // Spacing irregularity: a smooth value noise of cells `weakness_noise_size` (m) across the
  // strips' direction (4× longer along the fractures) scales S − 1 by 1 ± weakness_noise, a
  // procedural weakness map (sec. 3.2.3's jitter made low-frequency).
  double weakness_noise = 0;          // in [0, 1)
  double weakness_noise_size = 0.05;  // > 0 (m)
  // Opening (sec. 3.3, Figure 13): where new material appears; `opening_mix` gives the
  // probability of each mode [axis, one side, both] per fracture.
  Eigen::Vector3d opening_mix{1, 0, 0};
  // Refracture (2002 Figure 9, 2001 sec. 4.1): fracture surface wider than this (m) hardens
  // into bark of relative stiffness `refracture_stiffness`; 0 disables.
  double refracture_width = 0;
  double refracture_stiffness = 0.3;
  // Heterogeneous growth (sec. 5): dilatation bulges added to the base growth.
  std::vector<DilatationBulge> dilatation;
  std::vector<ScriptedFracture> scripted;
  // Flat samples only: cyclic boundaries around (always on for trees) and along the axis.
  bool tile_theta = true;
  bool tile_s = false;
  uint64_t seed = 1;

  double S() const { return threshold ? *threshold : growth_rate; }
  double fracture_stiffness_at(double rest) const;
  double max_fracture_stiffness() const;
};

// The valid open range of S (sec. 3.2.3): S > 1 + e/l0 · K_f / (K_s + K_f) so that a broken
// element does not break again, with e/l0 the one-step strain G − 1 of unbroken bark, K_s
// the softest epidermis element and K_f the stiffest fracture element, widened so that the
// jittered thresholds 1 + (S − 1)(1 − noise) stay above it; and S ≤ G so that unbroken bark
// is guaranteed to break (the paper uses S = G and varies the noise).
struct ThresholdRange {
  double low = 1, high = 1;
};
ThresholdRange valid_threshold_range(const StripParams& p, double softest_epidermis);

// A parameter outside its allowed range: the JSON key (relative to the `bark` object) and
// what is allowed. Thrown by the model; the scene parser adds file and path.
struct StripParamError {
  std::string key, message;
};
// The error for an S outside `r`, naming the range and what it was computed from.
StripParamError threshold_error(const StripParams& p, const ThresholdRange& r, double softest_epidermis);

// The largest total growth growth_rate^steps: the bark starts this many times smaller than
// the tree given in the scene (the shrinking strategy of sec. 5.2).
constexpr double kMaxStripGrowth = 1e6;
// The most steps `growth_rate` (> 1) allows within kMaxStripGrowth (at most 10^6, the steps limit).
int max_steps_for_growth(double growth_rate);

// First problem found, if any (ranges of every parameter; S against valid_threshold_range
// with the reference element's stiffness R).
std::optional<StripParamError> validate(const StripParams& p);

}  // namespace phellem::bark
