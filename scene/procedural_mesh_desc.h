// The `"procedural": {...}` block of a mesh object: which built-in shape and its parameters
// (docs/scene-format.md), validated like the rest of the scene; the mesh itself is built in
// mesh_source.h.
#pragma once

#include "scene/json_reader.h"
#include "scene/scene_desc.h"

namespace phellem {

ProceduralMeshDesc parse_procedural(JsonObject o);

}  // namespace phellem
