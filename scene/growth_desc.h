// The `"growth": {...}` object of a scene mesh: cambial growth (Kratt et al., Woodification;
// bark/growth/cambial_growth.h) of the mesh before its bark is cracked and rendered.
//
//   "growth": {
//     "steps": 50,                     // growth steps, [1, 100000]
//     "years": 20, "age_start": 0,     // the ages simulated (years)
//     "age_scale": 30,                 // years per unit of the Weibull age t, Eq. (2)
//     "weibull_c": 2,                  // the species parameter c, (0, 20]
//     "thickness": 0.05,               // m: the total thickening S(∞) = 1 maps to
//     "eccentricity": 0.2, "eccentricity_direction": [0, 1, 0],   // Eq. (3)
//     "strokes": [{"point": [x, y, z], "radius": 0.05, "value": 1, "direction": [x, y, z]}],  // sec. 4.4
//     "speed_map": {"file": "paint.png", "scale": 1},   // sec. 4.4: speed × scale × map(uv)
//                  or {"attribute": "COLOR_0"}      // ... × a glTF mesh's vertex attribute (first component)
//     "direction_map": {"attribute": "_GROWTH_DIRECTION"},  // sec. 4.4: a VEC3 vertex attribute turns the growth
//                  or {"file": "flow.png", "scale": 1}  // ... or a flow map in texture space (GrowthDirectionMap)
//     "obstacles": ["wire"],           // names of other mesh or sphere objects
//     "ring_interval": 10,             // steps between growth rings (0: none)
//     "cracks": true,                  // with stress bark: crack the surface as it grows (false: no cracks)
//     "crack_iterations": 0,           // stress iterations after each step (0: the bark's iterations spread over the steps)
//     "stretch_stress": 4,             // stress per unit of strain as the surface stretches (× the bark's magnitude)
//     "texture_cells": true,           // sec. 4.6: textures repeat as the surface stretches, cells keep their size
//     "edge_length": [0.004, 0.01],    // m: the interface's edge band (default: from the mesh)
//     "tetrahedra": {"quality": 1.5, "max_volume": 0, "padding": 0.5, "lattice": 0.2,  // lattice: TetSettings
//                    "remesh_blocked": 0.02,   // CambialGrowthSettings: when the volume is made again
//                    "upkeep_reach": 0.6},     // ... how far ahead the volume's upkeep carries (0: every step)
//     "reverse": false                 // sec. 4.3: shrink the mesh back to its age_start
//   }
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bark/growth/cambial_growth.h"
#include "util/errors.h"

namespace phellem {

class JsonObject;

// A painted speed map (sec. 4.4): its first channel as stored (numbers, not colours), row 0
// at v = 0 (glTF), repeated outside [0, 1]; the speed is multiplied by scale × the bilinear value
// at each vertex's texture coordinates.
// Or painted on the vertices: `attribute` names a vertex attribute of the object's glTF file
// (a painted COLOR_0's red channel, a custom "_GROWTH_SPEED"), its first component the factor.
struct GrowthSpeedMap {
  int width = 0, height = 0;
  std::vector<float> values;
  std::string attribute;  // non-empty: a vertex attribute instead of an image
  float scale = 1;
  float at(double u, double v) const;
};

// Painted growth directions (sec. 4.4). On the vertices: `attribute` names a VEC3 attribute of
// the object's glTF file, in object space. Or a flow map in texture space, sampled like a speed
// map at each vertex's texture coordinates: red is the direction's component along increasing
// u, green along increasing v (the surface directions ∂x/∂u and ∂x/∂v, normalised). Integer
// images (PNG) hold 0.5 + 0.5·d, as painting tools write flow maps (mid-grey: no turn); float
// images (EXR) hold d. Either way × scale, whose length (up to 1) is how far the growth turns
// from the normal.
struct GrowthDirectionMap {
  std::string attribute;  // non-empty: a vertex attribute instead of an image
  int width = 0, height = 0;
  std::vector<Eigen::Vector2f> values;  // per texel, (along u, along v), decoded
  float scale = 1;
  Eigen::Vector2d at(double u, double v) const;
};

struct GrowthDesc {
  bark::CambialGrowthSettings settings;
  std::vector<std::string> obstacle_names;
  std::vector<size_t> obstacles;  // object indices, resolved once every object is parsed
  bool cracks = true;
  int crack_iterations = 0;  // 0: ceil(the stress bark's iterations / steps)
  float stretch_stress = 4;
  bool texture_cells = true;  // sec. 4.6 (bark/growth/texture_cells.h); false: textures stretch with the surface
  std::shared_ptr<const GrowthSpeedMap> speed_map;
  std::shared_ptr<const GrowthDirectionMap> direction_map;
  Location where;  // of the growth object itself
};

// `base_dir` resolves the speed and direction maps' file names.
GrowthDesc parse_growth(JsonObject o, const std::string& base_dir);

// The size a growth reaches at its end, from the input mesh's vertex count and area and the
// settings; used to refuse a growth before TetGen runs.
struct GrowthSize {
  double interface_vertices = 0;  // at the last step
  double bytes = 0;               // the tetrahedral complex, adjacency and rings held then
  // TetGen's child process while it tetrahedralizes the volume at that size (a
  // re-tetrahedralization near the end; the set-up's is smaller): its private memory.
  double tetgen_bytes = 0;
  // The parent's own copies while it takes TetGen's volume in (the volume as received, as
  // unpacked, and the relabelled complex with its adjacency), beside the complex it replaces.
  double remesh_bytes = 0;
};
GrowthSize estimate_growth_size(const GrowthDesc& g, size_t input_vertices, double input_area, double mean_edge);

}  // namespace phellem
