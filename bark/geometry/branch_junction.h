// A branch junction as one closed surface: a trunk (a capped cylinder along +Y from y = 0 to
// `height`) with one branch (a thinner capped cylinder) leaving it at an angle, the boolean
// union of the two (CGAL's corefinement), remeshed isotropically to about the requested
// triangle count (CGAL's isotropic remeshing, the end-cap rims and the junction crease kept
// as features; within about 10 % of the count from a few thousand triangles up), its side
// vertices moved out onto the round cylinders and the crease rounded into a small fillet (a
// few edges wide) as wood fills a crotch. A closed, outward-oriented 2-manifold once its UV
// seam copies are welded by position, so it can grow (bark/growth/) like a log. Units metres,
// +Y up. Deterministic: the same parameters give the same mesh (corefinement's output is
// renumbered in order of position first).
//
//   radius, height           the trunk (m)
//   branch_radius            the branch (m), less than the trunk's
//   branch_angle_deg         between the branch and the trunk's axis, [20, 90]
//   branch_length            from the trunk's axis to the branch's end cap, along its axis (m)
//   branch_height            where the branch's axis leaves the trunk's axis (fraction of `height`)
//   triangles                about how many triangles the surface has
//   jitter, seed             vertices moved in the surface by up to jitter × the edge length
//
// The branch leaves towards +X. UVs: u = the angle around each part's own axis / 2π with the
// seam on the −Z side (the back, for a camera on +Z), v = metres along the axis / `height` (so
// trunk and branch share the texture's density along their lengths); the end caps continue
// v radially inwards. A face takes both from the part whose surface it lies on; corners on a
// seam or on the junction curve are repeated with their other part's or turn's UVs (same
// position).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

struct BranchJunctionParams {
  double radius = 0.15, height = 1.0;
  double branch_radius = 0.09, branch_angle_deg = 50, branch_length = 0.6, branch_height = 0.45;
  int triangles = 8000;
  double jitter = 0.3;
  uint64_t seed = 1;
};

// What is wrong with a set of parameters: the parameter to blame (its name as above) and why,
// with the bound it must meet; empty when they make a junction.
struct BranchJunctionProblem {
  std::string parameter, what;
};
std::optional<BranchJunctionProblem> check_branch_junction(const BranchJunctionParams& p);

// The fewest triangles that put 8 edges around the branch (check_branch_junction's lower
// bound on `triangles`; its upper bound is the constant).
int branch_junction_least_triangles(const BranchJunctionParams& p);
inline constexpr int kBranchJunctionMaxTriangles = 2'000'000;

// The junction's surface. std::invalid_argument for parameters check_branch_junction refuses;
// std::runtime_error if CGAL's union or remeshing does not give a closed, outward-oriented,
// self-intersection-free 2-manifold (an internal failure).
TriMesh branch_junction_mesh(const BranchJunctionParams& p);

// The volume enclosed by the exact (smooth) junction, estimated: trunk + branch − the part of
// the branch inside the trunk (its cross-section times the length of its axis inside the
// trunk, exact for a flat cut and within a few per cent of the branch's volume for the trunk's
// curved one).
double branch_junction_volume_estimate(const BranchJunctionParams& p);

}  // namespace phellem::bark
