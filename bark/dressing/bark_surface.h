// BarkSurface: what a renderer takes from a bark model for one surface (DESIGN.md data flow),
// whichever model made it. Two questions:
//  - displace(): how far the surface moves along its normal at a point (metres; negative goes
//    into the bark), and the four attributes the point keeps for shading (stored per vertex
//    by the dicer and interpolated across triangles);
//  - shade(): the fracture coverage, the normalized depth and the albedo from those attributes
//    and the shaded point's position (the object's own space, where displace() saw it).
// Four floats, so a GPU renderer keeps them as one vec4 per vertex.
// Strip bark (FieldBarkSurface: a dressed FractureField over the part's (u, v)) and cracked
// meshes (CrackBarkSurface: the V-profiles of the cracks, Spicker 2014 sec. 4.2) implement
// it, so the path tracer and any later renderer displace and shade bark by the same functions.
#pragma once

#include <Eigen/Core>
#include <cstddef>

namespace phellem::bark {

// A point of the undisplaced surface.
struct SurfacePoint {
  Eigen::Vector2d param{0, 0};  // the surface's own (u, v) in [0, 1]² (u wraps around a trunk)
  Eigen::Vector3f position{0, 0, 0};
  Eigen::Vector3f normal{0, 0, 1};  // unit, outwards
};

struct BarkDisplacement {
  float offset = 0;                  // metres along the normal (< 0: into the bark)
  Eigen::Vector4f attributes{0, 0, 0, 0};  // kept per vertex, handed back to shade()
};

struct BarkShade {
  float mask = 0;                   // fracture coverage in [0, 1]
  float depth = 0;                  // normalized depth in [0, 1] (the crack AOV)
  bool replaces_albedo = false;     // the bark's own albedo replaces the material's
  Eigen::Vector3f albedo{0, 0, 0};  // when replaces_albedo (depth darkening included)
  float albedo_scale = 1.0f;        // otherwise: the material's base colour × this
  Eigen::Vector3f tint{1, 1, 1};    // ... × this (per-plate and per-crack colour variation)
  float roughness = -1;             // GGX roughness of the bark here (< 0: the material's own)
};

class BarkSurface {
 public:
  virtual ~BarkSurface() = default;
  virtual BarkDisplacement displace(const SurfacePoint& p) const = 0;
  virtual BarkShade shade(const Eigen::Vector4f& attributes, const Eigen::Vector3f& position) const = 0;
  // Whether the bark can displace anything along the segment a–b of the undisplaced surface
  // (a dicer refines only there).
  virtual bool reaches(const Eigen::Vector3f& a, const Eigen::Vector3f& b) const = 0;
  virtual size_t memory_bytes() const = 0;
};

}  // namespace phellem::bark
