// The triangle mesh of a scene mesh object, as the bark simulations take it (bark::TriMesh)
// and as the renderer takes it (MeshData): read from its file (all its meshes merged, the
// object's transform applied) or made from its procedural description.
#pragma once

#include "bark/geometry/branch_junction.h"
#include "bark/geometry/mesh_data.h"
#include "bark/geometry/tessellation.h"
#include "bark/geometry/tri_mesh.h"
#include "io/mesh_io.h"
#include "scene/scene_desc.h"

namespace phellem {

// Errors in the file are UserErrors naming it. A tree is its trunk and branches, each diced
// (tree_mesh_dicing) and joined at the branchings, with flat caps on the open ends: one closed
// surface (bark/geometry/tube_junctions.h), which a growing tree requires of every branch.
bark::TriMesh object_trimesh(const ObjectDesc& o);
// The same for a mesh file, with vertex attributes of every triangle primitive (glTF; mesh_io.h)
// read in the same pass: (*values)[k] holds attribute k over the vertices of the result (a VEC3
// one also turned by the object's transform, as offsets are).
bark::TriMesh object_trimesh(const ObjectDesc& o, const std::vector<AttributeRequest>& attributes,
                             std::vector<std::vector<float>>* values);
// A mesh file already loaded as object o's: its triangles as one TriMesh, the object's
// transform applied (what object_trimesh gives for the file, without reading it again).
bark::TriMesh model_trimesh(const LoadedModel& model, const ObjectDesc& o);
// The object-space dicing of a tree's parts for object_trimesh: the stress bark's preprocess
// edge_length when set, else with growth the growth's edge_length band's maximum / 1.5, else a
// hundredth of the trunk's circumference.
DicingParams tree_mesh_dicing(const ObjectDesc& o);
bark::TriMesh procedural_trimesh(const ProceduralMeshDesc& p);
// A copy with at most `at_most` triangles (for estimates from a coarse mesh), but never fewer
// than the shape accepts (a branch junction's least).
ProceduralMeshDesc coarse_procedural(const ProceduralMeshDesc& p, int at_most);
// A `branch_junction`'s parameters, its defaults relative to the trunk resolved.
bark::BranchJunctionParams branch_junction_params(const ProceduralMeshDesc& p);

// Positions, UVs and triangles (no normals).
MeshData to_mesh_data(const bark::TriMesh& t);

}  // namespace phellem
