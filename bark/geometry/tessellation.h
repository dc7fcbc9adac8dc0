// Adaptive, watertight dicing of displaced surfaces into triangles.
//
// Every patch edge gets ONE tessellation rate, computed from the edge alone (its displaced
// length in world space or in pixels of a fixed dicing camera), and its vertices are created
// once and shared by both patches that meet there. A patch's interior grid is as fine as its
// finest edge; grid points on a coarser edge snap to that edge's own vertices (degenerate
// triangles are dropped). Neighbours refined to different levels therefore share every edge
// vertex: no cracks, no T-junctions.
#pragma once

#include <functional>

#include "bark/geometry/mesh_data.h"

namespace phellem {

struct DicingParams {
  bool screen_space = true;
  float target = 1.0f;  // pixels per micro-edge (screen) or metres (object)
  float scale = 1.0f;   // memory knob: multiplies the target
  Vec3f camera_position{0, 0, 0};
  float pixel_angle = 1e-3f;  // radians subtended by one pixel of the dicing camera
  int max_rate = 256;         // segments per patch edge
  // Crack-aware dicing: when set, an edge for which it returns false is not subdivided (the
  // displacement cannot reach it), so only the surface near features is refined.
  std::function<bool(const Vec3f& a, const Vec3f& b)> refine_edge;

  // Segments for an edge whose displaced polyline is `pts` (first..last inclusive).
  int edge_rate(const Vec3f* pts, int count) const;
};

// A parametric surface on [0,1]² (u may be periodic), already displaced: `position` writes the
// offset along the undisplaced surface's normal (m) to `offset` when it is not null, and dice()
// keeps it per vertex in MeshData::displacement.
struct ParametricSurface {
  std::function<Vec3f(float u, float v, float* offset)> position;
  std::function<Vec2f(float u, float v)> texcoord;
  bool periodic_u = false;
  bool keep_params = false;  // store (u, v) per vertex in MeshData::params
  int patches_u = 8, patches_v = 8;
};

using DisplacementFn = std::function<float(const Vec2f& uv, const Vec3f& p)>;

// Triangles the surface would produce (for the triangle budget).
long long estimate_triangles(const ParametricSurface& s, const DicingParams& d);
MeshData dice(const ParametricSurface& s, const DicingParams& d);

// Displaced triangle mesh: each input triangle is a patch, displaced along the interpolated
// normal by `disp` (metres), which MeshData::displacement keeps per vertex. Requires normals;
// UVs are interpolated when present.
// A displacement that also takes the undisplaced unit normal; when `params` is not null it
// also writes the vertex's MeshData::params (e.g. the crack depth for shading) from the same
// evaluation. dice() asks for them with `keep_params`.
using SurfaceDisplacementFn = std::function<float(const Vec2f& uv, const Vec3f& p, const Vec3f& n, Vec4f* params)>;
long long estimate_triangles(const MeshData& base, const SurfaceDisplacementFn& disp, const DicingParams& d);
MeshData dice(const MeshData& base, const SurfaceDisplacementFn& disp, const DicingParams& d, bool keep_params = false);
long long estimate_triangles(const MeshData& base, const DisplacementFn& disp, const DicingParams& d);
MeshData dice(const MeshData& base, const DisplacementFn& disp, const DicingParams& d);

}  // namespace phellem
