// The meshes of a scene's analytic objects, for every renderer that draws them as triangles
// (the path tracer's emissive spheres and its planes, the preview's patches).
#pragma once

#include "bark/geometry/mesh_data.h"
#include "bark/geometry/tessellation.h"
#include "scene/scene_desc.h"

namespace phellem {

// A `plane` object: two triangles over its size, with UVs (size / uv_scale) and tangents.
MeshData plane_mesh(const ObjectDesc& o);
// A `patch` object's frame: its centre, unit normal, and the unit directions of u (right) and
// v (up) in its plane.
struct PatchFrame {
  Vec3f centre, normal, right, up;
};
PatchFrame patch_frame(const ObjectDesc& o);
// A `patch` object as a parametric surface on [0, 1]² with texcoords (u, v), displaced along
// its normal by `disp` evaluated at the texcoords, for the dicer (bark/geometry/tessellation.h);
// patches of about 2 cm, each edge refined by the dicer.
ParametricSurface patch_surface(const ObjectDesc& o, const DisplacementFn& disp);
// The undisplaced patch as a grid of nu × nv quads with normals, texcoords and tangents.
MeshData patch_mesh(const ObjectDesc& o, int nu, int nv);
// A UV sphere of nu × nv quads with radial normals.
MeshData sphere_mesh(const Vec3f& centre, float radius, int nu = 96, int nv = 48);

}  // namespace phellem
