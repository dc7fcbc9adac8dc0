// Initial stress fields (Spicker 2014 sec. 3.1.5 patterns and sec. 3.3 user-based
// initialization): uniform tension, horizontal, vertical, mixed, random rotation (RR), a
// stress image in UV space and sketched strokes.
#pragma once

#include <Eigen/Core>

#include "bark/stress/stress_mesh.h"
#include "bark/stress/stress_params.h"

namespace phellem::bark {

// The face's horizontal (perpendicular to +Y, in the face plane) and vertical tangents.
std::pair<Eigen::Vector3d, Eigen::Vector3d> horizontal_vertical(const Eigen::Vector3d& normal);

// Sets σ of every face from p (pattern, magnitude, RR, image, then the strokes in order).
void initialize_stress(StressMesh& m, const StressParams& p);

// The faces a stroke crosses, in order, without repeats of consecutive faces.
std::vector<FaceId> stroke_faces(const StressMesh& m, const StressStroke& s);

// Curvature tensor of face f in its local frame: sym(Eᵀ Σ_j n_j β_j), n_j the vertex normals
// (the shape operator of the interpolated normal field; Woodification sec. 5 curvature stress).
Eigen::Matrix2d face_curvature(const StressMesh& m, FaceId f);

}  // namespace phellem::bark
