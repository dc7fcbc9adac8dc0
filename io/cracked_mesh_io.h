// CrackedMesh in and out as glTF 2.0 binary (.glb): the triangles with POSITION, NORMAL,
// TEXCOORD_0 and the custom vertex attributes _CRACK_WIDTH (Algorithm 1, in crack edges),
// _CRACK_COMPONENT (−1 off cracks) and _DISPLACEMENT_X/Y/Z (virtual displacement, m), plus the
// crack edges as a LINES primitive. Blender opens it (custom attributes become attributes);
// read_cracked_glb reads it back.
#pragma once

#include <string>

#include "bark/stress/cracked_mesh.h"

namespace phellem {

// `extra`: more per-vertex custom attributes (names starting with "_", one value per vertex).
void write_cracked_glb(const std::string& path, const std::string& name, const bark::CrackedMesh& mesh,
                       const std::vector<std::pair<std::string, std::vector<float>>>& extra = {});

// Throws UserError naming the file and the glTF element when it is not such a file.
bark::CrackedMesh read_cracked_glb(const std::string& path);

}  // namespace phellem
