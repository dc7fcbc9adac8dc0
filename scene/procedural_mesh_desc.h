// The `"procedural": {...}` block of a mesh object: which built-in shape and its parameters
// (docs/scene-format.md), validated like the rest of the scene; the mesh itself is built in
// mesh_source.h.
#pragma once

#include <string>

#include "scene/json_reader.h"
#include "scene/scene_desc.h"

namespace phellem {

ProceduralMeshDesc parse_procedural(JsonObject o);

// Why the shape cannot be the surface of a growth, which needs a closed surface that does not
// intersect itself, or "" (open shapes are refused as such by the growth itself).
std::string growth_problem(const ProceduralMeshDesc& p);

}  // namespace phellem
