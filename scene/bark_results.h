// The bark stage of a scene (SceneDesc -> BarkResults): every bark simulation a scene asks
// for, run once, before any renderer sees the scene — strip bark of tree objects (one dressed
// FractureField per tree part) and stress cracking of meshes and trees (the cracked mesh).
// Immutable once built; a renderer turns the results into BarkSurfaces and a time-lapse swaps
// in the bark of each frame.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "bark/dressing/crack_bark_surface.h"
#include "bark/dressing/field_bark_surface.h"
#include "bark/stress/cracked_mesh.h"
#include "scene/scene_desc.h"

namespace phellem {

struct ObjectBark {
  std::vector<std::shared_ptr<const bark::FieldBarkSurface>> strip_parts;  // strip bark: one per tree part
  std::shared_ptr<const bark::CrackedMesh> cracked;                        // stress bark
  std::shared_ptr<const bark::TriMesh> grown;  // cambial growth: the surface at the last step (world space)
  // Cambial growth: per vertex of the mesh rendered (`cracked` when there is one, else `grown`)
  // its texture cell levels (bark/growth/texture_cells.h); empty: none.
  std::vector<Eigen::Vector2f> texture_levels;
};

struct BarkResults {
  std::map<size_t, ObjectBark> objects;  // by 0-based object index; objects without bark have none
  double seconds = 0;                    // time spent simulating and dressing

  const ObjectBark* find(size_t object) const {
    const auto it = objects.find(object);
    return it == objects.end() ? nullptr : &it->second;
  }
};

// Whether object `o` has bark for the bark stage to simulate (or a mesh to grow).
bool has_simulated_bark(const ObjectDesc& o);
// The bark of one object (strip bark, stress bark, growth and the stress bark of the grown
// surface), with progress when asked.
ObjectBark simulate_object_bark(const SceneDesc& desc, size_t object, bool progress);
// The bark of every object that has some, in scene order.
BarkResults simulate_bark(const SceneDesc& desc, bool progress);

// A stress-bark object's cracks as a BarkSurface (its look and seed from the scene).
std::shared_ptr<const bark::CrackBarkSurface> crack_surface(const ObjectDesc& o, const bark::CrackedMesh& cracked);

}  // namespace phellem
