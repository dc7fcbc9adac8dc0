#include "scene/procedural_mesh_desc.h"

#include <cstdio>
#include <string>

#include "scene/mesh_source.h"

namespace phellem {

ProceduralMeshDesc parse_procedural(JsonObject o) {
  ProceduralMeshDesc p;
  p.shape = o.string("shape");
  if (p.shape != "trunk" && p.shape != "log" && p.shape != "torus_knot" && p.shape != "vase" && p.shape != "sheet" &&
      p.shape != "sphere" && p.shape != "branch_junction")
    o.fail("shape",
           "unknown procedural shape \"" + p.shape + "\"; allowed: trunk, log, torus_knot, vase, sheet, sphere, branch_junction");
  if (auto v = o.get("triangles")) {
    p.triangles = v->integer();
    if (p.triangles < 20 || p.triangles > 20000000) v->fail("triangles must be an integer in [20, 20000000]");
  }
  if (auto v = o.get("radius")) p.radius = v->positive();
  if (auto v = o.get("height")) p.height = v->positive();
  if (auto v = o.get("tube")) p.tube = v->positive();
  if (auto v = o.get("jitter")) {
    p.jitter = v->non_negative();
    if (p.jitter > 0.45f) v->fail("jitter must lie in [0, 0.45] (fraction of the vertex spacing)");
  }
  if (auto v = o.get("seed")) p.seed = v->seed();
  const bool junction = p.shape == "branch_junction";
  for (const char* key : {"branch_radius", "branch_length", "branch_angle_deg", "branch_height"})
    if (!junction && o.has(key)) o.fail(key, std::string(key) + " belongs to the shape branch_junction only");
  if (auto v = o.get("branch_radius")) p.branch_radius = v->positive();
  if (auto v = o.get("branch_length")) p.branch_length = v->positive();
  if (auto v = o.get("branch_angle_deg")) p.branch_angle_deg = v->number();
  if (auto v = o.get("branch_height")) p.branch_height = v->number();
  o.finish();
  // A junction's parameters bound each other (the branch must leave through the trunk's
  // side): the problem is reported at the parameter to change, or at the block when it was
  // left at its default.
  if (junction)
    if (const auto problem = bark::check_branch_junction(branch_junction_params(p)))
      o.fail(o.has(problem->parameter) ? problem->parameter : "", problem->what);
  return p;
}

std::string growth_problem(const ProceduralMeshDesc& p) {
  if (p.shape != "torus_knot") return "";
  // The (2, 3) knot's centre line comes within 0.5544 × radius of itself where its strands
  // cross (found numerically; the curve scales with radius): a tube thicker than half that
  // passes through its other strand, and the default tube (0.06 of 0.15 m) does.
  constexpr double kClosestApproach = 0.5544;
  const double gap = kClosestApproach * double(p.radius);
  if (double(p.tube) < 0.5 * gap) return "";
  char what[320];
  std::snprintf(what, sizeof what,
                "a growing torus knot must not intersect itself: its strands pass %.3g m apart (0.554 x radius), so its "
                "tube (%.3g m) must be thinner than %.3g m; growth needs a closed surface without self-intersections",
                gap, double(p.tube), 0.5 * gap);
  return what;
}

}  // namespace phellem
