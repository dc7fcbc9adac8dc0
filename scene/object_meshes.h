// The meshes of a scene's analytic objects, for every renderer that draws them as triangles
// (the path tracer's emissive spheres and its planes, the preview's patches).
#pragma once

#include "bark/geometry/mesh_data.h"
#include "scene/scene_desc.h"

namespace phellem {

// A `plane` object: two triangles over its size, with UVs (size / uv_scale) and tangents.
MeshData plane_mesh(const ObjectDesc& o);
// A UV sphere of nu × nv quads with radial normals.
MeshData sphere_mesh(const Vec3f& centre, float radius, int nu = 96, int nv = 48);

}  // namespace phellem
