// Procedural triangle meshes for tests, benchmarks and example scenes: a jittered flat
// sheet, an icosphere, an open cylinder (a trunk) and a torus knot, all with UVs.
#pragma once

#include <cstdint>
#include <functional>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

// nx × ny quads over [0, width] × [0, height] in the XY plane (normal +Z, +Y up), interior
// vertices jittered by up to `jitter` × the spacing, diagonals alternating; UV = (x/width, y/height).
TriMesh jittered_sheet(int nx, int ny, double width, double height, double jitter, uint64_t seed);

// Closed icosphere of `subdivisions` levels (20·4^s triangles), outward-facing; UVs from longitude/latitude.
TriMesh icosphere(int subdivisions, double radius);

// Open cylinder along +Y from 0 to `height`, `around` × `along` quads, vertices jittered by up
// to `jitter` × the spacing (in the surface); welded around (no seam in the geometry), UVs
// with a seam at θ = 0.
TriMesh cylinder_mesh(double radius, double height, int around, int along, double jitter, uint64_t seed);

// A closed log: cylinder_mesh closed at y = 0 and y = height by flat caps of concentric rings
// (fewer vertices towards the centre, so the caps' triangles stay well shaped), outward-facing.
// The side's seam copies stay unreferenced (weld by position for a closed index mesh).
TriMesh log_mesh(double radius, double height, int around, int along, double jitter, uint64_t seed);

// The same around a radius profile r(t), t = y / height ∈ [0, 1] (a vase, a flared trunk).
TriMesh revolved_mesh(const std::function<double(double)>& radius, double height, int around, int along, double jitter,
                      uint64_t seed);

// A vase: a surface of revolution with a belly and a narrower neck.
TriMesh vase_mesh(double radius, double height, int around, int along, double jitter, uint64_t seed);

// A (p, q) torus knot tube: `segments` rings of `sides` vertices; closed.
TriMesh torus_knot(int p, int q, double radius, double tube, int segments, int sides);

}  // namespace phellem::bark
