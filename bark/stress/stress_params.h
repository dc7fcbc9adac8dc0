// Every parameter of the stress-field cracking model (Spicker 2014 Figure 17 and Table 1).
// Stress is measured in units of the membrane modulus (so the relaxation time step is
// dimensionless), and the threshold τ relative to the initial stress magnitude times the
// mesh's mean edge length (a uniformly stretched flat mesh has separation-tensor eigenvalues
// of about 0.75 in these units at interior vertices), which keeps a parameter set meaningful
// across mesh sizes.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace phellem::bark {

enum class StressPattern {
  UniformTension,  // σ = s·I in every face
  Horizontal,      // tension along the horizontal tangent (perpendicular to +Y): vertical cracks
  Vertical,        // tension along the vertical tangent: horizontal cracks
  Mixed,           // horizontal tension plus mix_ratio × vertical tension
  Image,           // a stress image over UV space (StressImage)
  Strokes,         // only the strokes (zero elsewhere)
  Growth,          // outward growth: tension along each direction in proportion to the surface's curvature
};

// A stress image over the mesh's UV space: 1 channel scales the base pattern's magnitude;
// 3 channels give the tensor (σ_uu, σ_vv, σ_uv) in the texture's u and v directions.
struct StressImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;  // row-major, row 0 at v = 0 (glTF: the top of the image), channels interleaved
  bool empty() const { return values.empty(); }
};

// A sketched stroke (sec. 3.3): a polyline in UV space or of 3D points projected onto the
// mesh. The faces it crosses get stress orthogonal to its direction, smoothed over the
// `smoothing` previous and next faces along it; later strokes overwrite earlier ones. A
// one-face-wide band of tension barely separates its own vertices (each is pulled from one
// side only), so the stroke is painted with a brush: faces whose centre lies within `radius`
// (metres on the surface; 0: two mean edge lengths) of a crossed face take its stress.
struct StressStroke {
  bool in_uv = true;
  std::vector<Eigen::Vector3d> points;  // UV strokes use x, y
  double magnitude = 1.0;               // relative to StressParams::magnitude
  int smoothing = 3;                    // n of sec. 3.3
  double radius = 0;                    // brush radius (m); 0: 2 × the mean edge length
};

struct StressParams {
  int iterations = 50;                // TI
  int cracks_per_iteration = 5;       // CPI
  int relaxations_per_iteration = 1;  // RPI
  double alpha = 0.0;                 // residual weighting α ∈ [0, 1] (eq. 6)
  double stress_alleviation = 0.0;    // SA ∈ [0, 1] (sec. 3.2): 0 = no stress left in faces a crack creates
  double random_rotation = 0.0;       // RR: each face's initial tensor rotated by up to ±RR·π/2
  double crack_rotation = 0.0;        // crack direction rotated by up to ±crack_rotation·π/2
  double snap_angle_deg = 10.0;       // ESA: snap onto an existing edge closer than this
  double threshold = 0.6;             // τ, relative (see above)
  double time_step = 0.2;             // Δt of eq. 7 (dimensionless; see stress_relaxation.h)
  double kappa = 4.0;                 // κ: new faces' β singular values ≤ κ × the initial maximum
  StressPattern pattern = StressPattern::UniformTension;
  double magnitude = 1.0;  // s: initial stress magnitude
  double mix_ratio = 0.5;  // Mixed: vertical / horizontal tension
  StressImage image;
  std::vector<StressStroke> strokes;
  // Woodification sec. 5 hooks: a stress increment added to every face each iteration
  // (growth), and a coefficient on the face's curvature tensor added each iteration.
  Eigen::Matrix2d growth_increment = Eigen::Matrix2d::Zero();  // in the (horizontal, vertical) tangent frame
  double curvature_stress = 0.0;
  uint64_t seed = 1;
};

// A parameter outside its valid range: `key` is the scene key, `message` says what is allowed.
struct StressParamError {
  std::string key, message;
};
std::optional<StressParamError> validate(const StressParams& p);

}  // namespace phellem::bark
