// The cracks of a CrackedMesh as real geometry (Spicker 2014 sec. 4.2, done as displacement
// in the path tracer instead of GPU tessellation): each crack edge carves a V-profile
// ψ = D·(w − d)/w into the surface within its half-width w of it (d: distance to the edge),
// w from the Algorithm 1 width of its ends, D growing with w, both modulated by noise. The
// displacement is limited by a ray cast against the mesh so thin parts are never punched
// through (the thesis's future work).
#pragma once

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <memory>
#include <unordered_map>
#include <vector>

#include "bark/dressing/bark_roughness.h"
#include "bark/stress/cracked_mesh.h"
#include "util/math.h"

namespace phellem {

// Crack geometry for rendering (sec. 4.2 as real geometry): a V-profile whose half-width grows
// with the Algorithm 1 width and whose depth grows with the half-width, both modulated by noise.
struct CrackLook {
  float width_per_edge = 0.0008f;  // half-width (m) per crack edge of Algorithm 1 width
  float min_width = 0.0008f;       // half-width at the crack's ends (m)
  float max_width = 0.006f;        // half-width cap (m)
  float depth_per_width = 1.2f;    // depth / half-width
  float max_depth = 0.012f;        // depth cap (m)
  float noise = 0.3f;              // relative modulation of width and depth
  float darkening = 0.7f;          // albedo × (1 − darkening × normalized depth)
  // The visible gap (sec. 3.1.6, Figure 19): the half-width also grows by gap × the crack
  // vertex's summed virtual displacement from the relaxation (still capped at max_width).
  float gap = 0.0f;
  // Relief between and in the cracks (issue 22; all 0: off), depths relative to max_depth:
  // the surface rounds down towards each crack over `shoulder_width` metres beyond its
  // half-width, by shoulder × max_depth at the lip (h = −S·(1 − d/w)², bark_relief.h); fbm
  // detail of amplitude detail × max_depth and feature size detail_size everywhere; the V's
  // depth × (1 + wall_noise · fbm) at wall_size (rough walls).
  float shoulder = 0, shoulder_width = 0;
  float detail = 0, detail_size = 0.008f;
  float wall_noise = 0, wall_size = 0.004f;
  bark::BarkRoughness roughness;  // ridges vs crack interiors (off: the material's)
  // Colours replacing the material's base colour (a photo's ridges and fissures,
  // scene/bark_photo.h), darkened with depth. Off unless `colored`.
  bool colored = false;
  Eigen::Vector3f ridge_color{0.5f, 0.5f, 0.5f}, fissure_color{0.3f, 0.3f, 0.3f};
  // Per-crack and per-plate colour variation (bark/dressing/bark_tints.h; empty: none): each
  // crack chain (between junctions and ends) picks a fissure tint, the ridges a ridge tint
  // from a field of feature size tint_size (m). Tints multiply the colours above, or the
  // material's base colour, and the roughness noise follows them.
  std::vector<Eigen::Vector3f> ridge_tints, fissure_tints;
  float tint_size = 0.04f;
};

class CrackProfile {
 public:
  CrackProfile(const bark::CrackedMesh& mesh, const CrackLook& look, uint32_t seed);

  struct Sample {
    float depth = 0;     // metres below the surface (≥ 0)
    float relative = 0;  // depth / the look's max_depth, in [0, 1] (the crack AOV, darkening)
    float mask = 0;      // 1 inside a crack's width
    float chain = 0;     // the nearest crack chain's coordinate in [0, 1) (its tint; also outside it)
  };
  // At a point of the undisplaced surface with unit normal n (outwards).
  Sample at(const Vec3f& p, const Vec3f& n) const;
  // Whether any crack reaches the segment a–b (crack-aware dicing: elsewhere edges stay whole).
  bool reaches(const Vec3f& a, const Vec3f& b) const;
  float reach() const { return reach_; }
  size_t segments() const { return seg_.size(); }
  uint32_t seed() const { return seed_; }
  const CrackLook& look() const { return look_; }

  struct Segment {
    Vec3f a, b;
    float wa, wb;  // half-widths at the ends (m), before noise
    float chain;   // coordinate of the chain (edges between junctions and ends) it belongs to
  };
  // The crack edges as at() sees them (the preview uploads them to the GPU).
  const std::vector<Segment>& segment_list() const { return seg_; }

 private:
  // Every edge's chain coordinate: a hash of the chain's first edge.
  static std::vector<float> chain_coordinates(const bark::CrackedMesh& mesh, uint32_t seed);
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Triangles = std::vector<K::Triangle_3>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>>>;

  int64_t cell_key(int x, int y, int z) const;
  template <class F>
  void for_near(const Vec3f& lo, const Vec3f& hi, F&& f) const;

  CrackLook look_;
  uint32_t seed_;
  float reach_ = 0, cell_ = 1;
  std::vector<Segment> seg_;
  std::unordered_map<int64_t, std::vector<uint32_t>> grid_;
  // Segments whose box spans more than kMaxCells grid cells (a mesh at a scale far from the
  // cracks' width): visited by every query instead of filling the grid.
  std::vector<uint32_t> long_;
  // Grid cells spanned by a box, or infinity when its cell indices would leave int range.
  double cells_spanned(const Vec3f& lo, const Vec3f& hi) const;
  static constexpr double kMaxCells = 4096;
  Triangles triangles_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace phellem
