#include "scene/memory_estimate.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "bark/geometry/irregular_remesh.h"
#include "bark/strips/strip_domain.h"
#include "bark/strips/strip_model.h"
#include "scene/dicing_params.h"
#include "scene/displacement.h"
#include "scene/displacement_map.h"
#include "scene/object_meshes.h"
#include "scene/mesh_source.h"
#include "scene/tree_surface.h"
#include "util/errors.h"

namespace phellem {

namespace {

// ---- Measured costs -------------------------------------------------------------------------
// Peak RSS from `/usr/bin/time -v` (Release build, 2 threads, Debian 12), each at two sizes at
// least; the scenes are straight trees and procedural meshes (scratch files, not kept).

// The program itself: `phellem render` of one sphere at 64x64 pixels, 1 spp: 141 MB.
constexpr double kBaseBytes = 141e6;

// Strip model (one StripModel per limb, all of a tree's held together). Cost = kBytesPerStrip
// per strip + per element at the final size E_f (= strips × final strip length /
// element_length) kBytesPerInitialElement / G^T + kBytesPerFinalElement, G^T =
// growth_rate^steps the total growth: the strips are built at the initial size (E_f / G^T
// elements) and the fractures then add elements in proportion to the final size. Number of
// steps alone changes nothing (2000 steps at G^T = 1.82: 371 MB, 500 steps: 370 MB).
//   phellem simulate T.json -o out --no-mesh --res 16x16 --threads 2    (furrowed preset)
//   trunk 10 m × r 0.15, strip_width 0.005, element_length 0.01, steps 8: 2000 strips, E_f 1.9e5: 236 MB
//     the same, 40 m:                              8000 strips, E_f 7.5e5:  540 MB
//     the same, 10 m × r 0.6:                      2000 strips, E_f 7.5e5:  492 MB
//     250 m × r 0.02:                             50000 strips, E_f 6.3e5:  575 MB
//     1000 m × r 0.02:                           200000 strips, E_f 2.5e6: 1928 MB
//   steps 500 (G^T 1.82): 10 m × r 0.15: 196 MB; × r 0.6: 370 MB; 40 m × r 0.15: 389 MB
//   steps 160 (G^T 1.21): 10 m × r 0.15: 219 MB; × r 0.6: 451 MB (model: 462 MB)
//   steps 300, growth_rate 1.01 (G^T 19.8), 10 m × r 0.6: 250 MB (model: 266 MB)
// Furrowed is the most expensive preset at G^T ≈ 1.8 (fissured 329 MB, brittle 323, banded
// 378, plated 249 on the 10 m × r 0.6 trunk); plated, which refractures, reaches 313 MB at
// G^T 19.8 (model: 266 MB).
constexpr double kBytesPerStrip = 3400;
constexpr double kBytesPerInitialElement = 336;
constexpr double kBytesPerFinalElement = 131;

// Fracture fields (bark::FractureField, 11 floats a texel). `render`: the field while it is
// dressed plus the BarkSurface kept for rendering (5 floats a texel), 64 bytes a texel in all:
//   phellem render FR.json --res 32x32 --spp 1 (1 m trunk, field_resolution 16², 2048², 4096²)
//   150 MB, 400 MB, 1188 MB. Of it, kSurfaceBytesPerTexel stays until the end of the render.
// `simulate`: the field and its EXR's interleaved copy, 89 bytes a texel:
//   phellem simulate F.json -o out --no-mesh --res 16x16 / 2048x2048 / 4096x4096: 148, 515, 1609 MB.
constexpr double kFieldBytesPerTexel = 44;
constexpr double kSurfaceBytesPerTexel = 20;
constexpr double kSimulateFieldBytesPerTexel = 89;
// `simulate` without --no-mesh: the bark mesh of each limb (its own field, texels half a
// strip wide, the constrained Delaunay mesh and the glTF buffers), per texel of that field:
//   trunk 10.24 m × r 1.63, strip_width 0.01, element_length 0.02, steps 100 (2048² mesh
//   texels, 2.15e6 triangles): 353 MB with --no-mesh, 888 MB without: 131 bytes a texel.
constexpr double kMeshBytesPerTexel = 131;

// Stress cracking, per triangle of the mesh it cracks (after the preprocessing remesh):
//   phellem simulate S.json -o out (procedural trunk, woodification)
//   2.0e5 triangles: 381 MB, 8.0e5: 1069 MB (1175 bytes a triangle; iterations 0: the same)
//   without preprocessing, 1.0e5: 215 MB, 4.0e5: 470 MB (870 bytes a triangle; `render` of the
//   same scene peaks at the same RSS: the cracking, not the dicing, is its peak).
// Each crack adds about 1.3 triangles (2510 for 1920 crack edges): counted as 2 per crack,
// at most as many as the mesh has.
constexpr double kStressBytesPerTriangle = 1175;
constexpr double kStressBytesPerTriangleRaw = 870;

// Rendered geometry, per triangle (diced vertices, indices, the padded copy and the BVH):
//   phellem render T.json (tree 2 m, grooves, tessellation object mode, edge_length 0.002 /
//   0.001): 1.15e6 triangles 289 MB, 4.51e6 triangles 711 MB: 129 bytes a triangle. Bark
//   adds its shading attributes (4 floats a vertex, about 8 bytes a triangle), within the margin.
constexpr double kGeometryBytesPerTriangle = 129;
constexpr double kCrackAwareShare = 0.6;

constexpr double kTwoPi = 6.283185307179586;

std::string num(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string count(double x) {
  char buf[64];
  if (x < 1e5)
    std::snprintf(buf, sizeof buf, "%.0f", x);
  else
    std::snprintf(buf, sizeof buf, "%.2g", x);
  return buf;
}

std::string object_name(const ObjectDesc& o, size_t oi, const char* kind) {
  return "\"" + (o.name.empty() ? kind + std::to_string(oi) : o.name) + "\"";
}

std::string path(size_t oi, const std::string& tail) { return "/objects/" + std::to_string(oi) + tail; }

// Mean circumference over the length, as longitudinal_domain measures it (16 sections × 32 chords).
double mean_circumference(const bark::GeneralizedCylinder& c) {
  constexpr int kSections = 16, kChords = 32;
  double mean = 0;
  for (int i = 0; i < kSections; ++i) {
    const double u = (i + 0.5) / kSections;
    double sum = 0;
    for (int k = 0; k < kChords; ++k)
      sum += (c.position(u, kTwoPi * (k + 1) / kChords) - c.position(u, kTwoPi * k / kChords)).norm();
    mean += sum / kSections;
  }
  return mean;
}

// ---- Strip bark -----------------------------------------------------------------------------

struct StripTreeCost {
  size_t parts = 0;
  double strips = 0, elements = 0;
  double strips_bytes = 0, elements_bytes = 0, branch_bytes = 0;
  std::vector<double> field_texels;  // per limb: the scene's field_resolution or the automatic size
  std::vector<double> mesh_texels;   // per limb: `simulate`'s bark mesh field
  std::vector<std::pair<int, int>> field_size;
  double sim() const { return strips_bytes + elements_bytes; }
};

int clamp_round(double x, int lo, int hi) { return int(std::clamp(std::round(x), double(lo), double(hi))); }

StripTreeCost strip_tree_cost(const ObjectDesc& o, size_t oi) {
  const StripBarkDesc& bark = *o.tree.strip_bark;
  const bark::StripParams& p = bark.params;
  const std::vector<TreePart> parts = build_tree(o.tree, [](const Vec2f&, const Vec3f&) { return 0.0f; });
  const bool horizontal = p.orientation == bark::FractureOrientation::Horizontal;
  const double total_growth = std::pow(p.growth_rate, double(p.steps));
  StripTreeCost c;
  c.parts = parts.size();
  for (size_t k = 0; k < parts.size(); ++k) {
    const bark::GeneralizedCylinder& cyl = *parts[k].cylinder;
    const double L = cyl.length(), C = mean_circumference(cyl);
    // The strip model's own limits (strip_domain.cpp, strip_model.cpp), checked before its
    // domain is measured (which alone takes seconds to minutes when they are exceeded).
    const double across = horizontal ? C : L, along = horizontal ? L : C;
    const double ratio = across / p.strip_width;
    if (!(ratio <= bark::kMaxStrips)) {
      std::ostringstream m;
      m << "strip_width: must be at least " << across / bark::kMaxStrips << " m here: the bark is " << across
        << " m across its strips, and " << p.strip_width << " m strips would make " << ratio << " of them, more than the "
        << bark::kMaxStrips << " a simulation allows";
      throw UserError(o.where.file, path(oi, "/bark/strip_width"), m.str());
    }
    const double n = std::max(horizontal ? 3.0 : 1.0, std::round(ratio));
    const double elements = n * along / p.element_length;
    if (!(elements <= bark::kMaxElements)) {
      std::ostringstream m;
      m << "element_length: must be at least " << p.element_length * elements / bark::kMaxElements << " m here: " << n
        << " strips of this bark would hold " << elements << " elements of " << p.element_length
        << " m at their final size, more than the " << bark::kMaxElements << " a simulation allows";
      throw UserError(o.where.file, path(oi, "/bark/element_length"), m.str());
    }
    const double strips_bytes = n * kBytesPerStrip;
    const double elements_bytes = elements * (kBytesPerInitialElement / total_growth + kBytesPerFinalElement);
    c.strips += n;
    c.elements += elements;
    c.strips_bytes += strips_bytes;
    c.elements_bytes += elements_bytes;
    if (k > 0) c.branch_bytes += strips_bytes + elements_bytes;
    // Fields as TreeStripSimulation::field / mesh size them: texels a quarter (a half for the
    // mesh) of the actual strip width, around (the circumference) by along the axis.
    const double width = across / n;
    int W = bark.field_width, H = bark.field_height;
    if (W <= 0 || H <= 0) {
      W = clamp_round(C / (width / 4), 64, 8192);
      H = clamp_round(L / (width / 4), 16, 8192);
    }
    c.field_size.emplace_back(W, H);
    c.field_texels.push_back(double(W) * H);
    c.mesh_texels.push_back(double(clamp_round(C / (width / 2), 32, 4096)) * clamp_round(L / (width / 2), 8, 4096));
  }
  return c;
}

MemoryItem strip_sim_item(const ObjectDesc& o, size_t oi, const StripTreeCost& c) {
  const bark::StripParams& p = o.tree.strip_bark->params;
  MemoryItem m;
  m.bytes = c.sim();
  m.what = "the strip simulation of " + object_name(o, oi, "tree") + " (" + std::to_string(c.parts) +
           (c.parts == 1 ? " limb: " : " limbs: ") + count(c.strips) + " strips, " + count(c.elements) + " elements)";
  m.file = o.where.file;
  m.advice = "raise strip_width (now " + num(p.strip_width) + " m) or element_length (now " + num(p.element_length) + " m)";
  if (c.parts > 1) m.advice += ", or give the tree fewer or smaller branches";
  if (c.parts > 1 && c.branch_bytes > 0.5 * m.bytes)
    m.where = path(oi, "/branches");
  else
    m.where = path(oi, c.strips_bytes > c.elements_bytes ? "/bark/strip_width" : "/bark/element_length");
  return m;
}

MemoryItem field_item(const ObjectDesc& o, size_t oi, const std::string& what, double bytes, std::pair<int, int> size) {
  MemoryItem m;
  m.what = what + " of " + object_name(o, oi, "tree");
  m.bytes = bytes;
  m.file = o.where.file;
  m.where = path(oi, "/bark/field_resolution");
  const StripBarkDesc& b = *o.tree.strip_bark;
  const std::string wh = std::to_string(size.first) + "x" + std::to_string(size.second);
  m.advice = b.field_width > 0 ? "lower field_resolution (now " + wh + ")"
                               : "set a field_resolution below the automatic " + wh + " (texels a quarter of a strip wide)";
  return m;
}

// ---- Stress bark ----------------------------------------------------------------------------

double trimesh_area(const bark::TriMesh& t) {
  double a = 0;
  for (const auto& f : t.triangles)
    a += 0.5 * (t.positions[f[1]] - t.positions[f[0]]).cross(t.positions[f[2]] - t.positions[f[0]]).norm();
  return a;
}

struct LoadedCounts {
  double triangles = 0, area = 0;
};

// Triangles of a mesh file with the object's transform (read once per object that needs it).
LoadedCounts file_counts(const ObjectDesc& o) {
  const bark::TriMesh t = object_trimesh(o);
  return {double(t.triangles.size()), trimesh_area(t)};
}

// Object-space dicing of a tree for the stress model (mesh_source.cpp, object_trimesh).
struct StressCost {
  double triangles = 0;  // the mesh the cracker works on (after preprocessing, with its cracks)
  MemoryItem item;
};

StressCost stress_cost(const ObjectDesc& o, size_t oi) {
  const StressBarkDesc& s = *o.stress_bark;
  double n_in = 0, area = 0;
  MemoryItem m;
  m.file = o.where.file;
  if (o.type == ObjectType::Tree) {
    const DicingParams d = tree_mesh_dicing(o);
    for (const TreePart& part : build_tree(o.tree, make_displacement(o.tree.displacement))) {
      n_in += double(estimate_triangles(part.surface, d));
      area += mean_circumference(*part.cylinder) * part.cylinder->length();
    }
    m.where = path(oi, "/bark/preprocess/edge_length");
    m.advice = "set a longer preprocess edge_length (now " + num(d.target) + " m" +
               (s.preprocess.edge_length > 0 ? std::string(")") : std::string(", a hundredth of the trunk's circumference)"));
  } else if (o.procedural) {
    // The shapes make about the number of triangles asked for; the area from a coarse copy.
    n_in = double(std::max(20, o.procedural->triangles));
    ObjectDesc coarse = o;
    coarse.procedural = coarse_procedural(*o.procedural, 2000);
    area = trimesh_area(object_trimesh(coarse));
    m.where = path(oi, "/procedural/triangles");
    m.advice = "lower triangles (now " + std::to_string(o.procedural->triangles) + ")";
  } else {
    const LoadedCounts lc = file_counts(o);
    n_in = lc.triangles;
    area = lc.area;
    m.where = path(oi, "/file");
    m.advice = "use a coarser mesh, or remesh it coarser with bark/preprocess/edge_length";
  }
  double n = n_in;
  if (s.preprocess.enabled && s.preprocess.edge_length > 0) {
    n = area / (0.4330127 * double(s.preprocess.edge_length) * double(s.preprocess.edge_length));
    if (n > double(bark::kMaxRemeshTriangles))
      throw UserError(o.where.file, path(oi, "/bark/preprocess/edge_length"),
                      "an edge length of " + std::to_string(s.preprocess.edge_length) + " m would make about " +
                          std::to_string(static_cast<long long>(n)) + " triangles; at most " +
                          std::to_string(bark::kMaxRemeshTriangles) + " are allowed (use a longer edge_length)");
    m.where = path(oi, "/bark/preprocess/edge_length");
    m.advice = "raise preprocess edge_length (now " + num(s.preprocess.edge_length) + " m)";
  }
  const double cracks = 2.0 * double(s.params.iterations) * double(s.params.cracks_per_iteration);
  StressCost c;
  c.triangles = n + std::min(cracks, n);
  m.bytes = std::max(n_in, c.triangles) * (s.preprocess.enabled ? kStressBytesPerTriangle : kStressBytesPerTriangleRaw);
  m.what = "the stress cracking of " + object_name(o, oi, o.type == ObjectType::Tree ? "tree" : "mesh") + " (about " +
           count(c.triangles) + " triangles)";
  c.item = m;
  return c;
}

// ---- Geometry -------------------------------------------------------------------------------

// A displaced mesh's diced triangles: the estimate on a copy of at most 20000 triangles (the
// dicing follows the target edge, not the input's), and at least one per input triangle.
double displaced_mesh_triangles(const ObjectDesc& o, double triangles, const DicingParams& d) {
  ObjectDesc copy = o;
  if (copy.procedural) copy.procedural = coarse_procedural(*copy.procedural, 20000);
  MeshData m = to_mesh_data(object_trimesh(copy));
  compute_vertex_normals(m);
  return std::max(triangles, double(estimate_triangles(m, make_displacement(o.displacement), d)));
}

MemoryItem geometry_item(const SceneDesc& desc, int height, const std::map<size_t, double>& stress_triangles) {
  const TessellationDesc& tess = desc.render.tessellation;
  const DicingParams d = dicing_params(desc.render.tessellation, desc.camera, height);
  double diced = 0, stored = 0;
  std::map<std::string, double> files;  // instanced mesh files: stored once
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& o = desc.objects[oi];
    if (o.stress_bark && stress_triangles.count(oi)) {  // not a grown object with "cracks": false
      // The cracked mesh diced where its cracks reach (crack_aware, the default), or everywhere
      // (crack_aware false, or a mesh's own displacement: the surface's uniform dicing), and at
      // least one triangle per triangle of the cracked mesh. Where the cracks reach depends on
      // the cracks: kCrackAwareShare of the uniform dicing, the middle of scenes/stress_*.json
      // (render --stats diced_triangles / this estimate: birch 0.34, knot 0.34, palm 0.61,
      // pine 0.71, tree 1.29).
      double uniform = 0;
      if (o.type == ObjectType::Tree) {
        for (const TreePart& part : build_tree(o.tree, make_displacement(o.tree.displacement)))
          uniform += double(estimate_triangles(part.surface, d));
      } else {
        uniform = displaced_mesh_triangles(o, 0, d);
      }
      const bool own = o.type == ObjectType::Mesh && o.displacement.type != DisplacementDesc::Type::None;
      diced += std::max(tess.crack_aware && !own ? kCrackAwareShare * uniform : uniform, stress_triangles.at(oi));
    } else if (o.type == ObjectType::Tree) {
      for (const TreePart& part : build_tree(o.tree, make_displacement(o.tree.displacement)))
        diced += double(estimate_triangles(part.surface, d));
    } else if (o.type == ObjectType::Patch) {
      diced += double(estimate_triangles(patch_surface(o, make_displacement(o.displacement)), d));
    } else if (o.type == ObjectType::Mesh) {
      const bool displaced = o.displacement.type != DisplacementDesc::Type::None;
      double n = 0;
      if (o.procedural) {
        n = double(o.procedural->triangles);
      } else {
        if (!displaced && files.count(o.file)) continue;
        n = file_counts(o).triangles;
        if (!displaced) files[o.file] = n;
      }
      if (displaced)
        diced += displaced_mesh_triangles(o, n, d);
      else
        stored += n;
    }
  }
  MemoryItem m;
  const double triangles = std::min(diced, double(tess.max_triangles)) + stored;
  m.bytes = triangles * kGeometryBytesPerTriangle;
  m.what = "the geometry (about " + count(triangles) + " triangles, diced and stored)";
  m.file = desc.file;
  m.where = "/render/tessellation/max_triangles";
  m.advice = "lower max_triangles (now " + std::to_string(tess.max_triangles) + ") or raise edge_length_scale";
  return m;
}

MemoryItem base_item() { return {"the program itself", kBaseBytes, "", "", ""}; }

// Cambial growth: the tetrahedral complex at the last step, from the input's size and area;
// with stress bark and cracks on, the crack coupling too (bark/growth/growth_cracks.h): the
// cracking model over the whole interface, rebuilt every step, at its size at the last step.
struct GrowthCost {
  MemoryItem growth;
  MemoryItem tetgen;  // TetGen's child process, re-tetrahedralizing at the grown size
  std::optional<MemoryItem> remesh;  // the parent taking a re-tetrahedralized volume in
  std::optional<MemoryItem> cracks;
  double crack_triangles = 0;  // the cracked mesh rendered at the end (0 without coupling)
};

}  // namespace

GrowthInputSize growth_input_size(const ObjectDesc& o) {
  GrowthInputSize in;
  if (o.type == ObjectType::Tree) {
    const DicingParams d = tree_mesh_dicing(o);
    for (const TreePart& part : build_tree(o.tree, make_displacement(o.tree.displacement))) {
      in.vertices += double(estimate_triangles(part.surface, d)) / 2;
      in.area += mean_circumference(*part.cylinder) * part.cylinder->length();
    }
  } else if (o.procedural) {
    ObjectDesc coarse = o;
    coarse.procedural = coarse_procedural(*o.procedural, 2000);
    const bark::TriMesh t = object_trimesh(coarse);
    in.area = trimesh_area(t);
    in.vertices = double(std::max(20, o.procedural->triangles)) / 2;
  } else {
    const LoadedCounts lc = file_counts(o);
    in.vertices = lc.triangles / 2;
    in.area = lc.area;
  }
  // The mean edge of that many equilateral triangles.
  in.mean_edge = std::sqrt(in.area / std::max(1.0, 2 * in.vertices) / 0.4330127);
  return in;
}

namespace {

GrowthCost growth_cost(const ObjectDesc& o, size_t oi) {
  const GrowthInputSize in = growth_input_size(o);
  const GrowthSize size = estimate_growth_size(*o.growth, size_t(in.vertices), in.area, in.mean_edge);
  const std::string name = object_name(o, oi, o.type == ObjectType::Tree ? "tree" : "mesh");
  GrowthCost c;
  c.growth.file = o.where.file;
  c.growth.bytes = size.bytes;
  c.growth.what = "the cambial growth of " + name + " (its tetrahedra at the last step)";
  c.growth.where = path(oi, "/growth/edge_length");
  c.growth.advice = "raise the growth's edge_length band, or lower its thickness or steps / ring_interval";
  c.tetgen = c.growth;
  c.tetgen.bytes = size.tetgen_bytes;
  c.tetgen.what = "TetGen's process tetrahedralizing the grown " + name;
  c.tetgen.advice = "raise the growth's edge_length band, or lower its thickness";
  if (size.remesh_bytes > 0) {
    MemoryItem r = c.growth;
    r.bytes = size.remesh_bytes;
    r.what = "the new volume of " + name + " taken in from TetGen beside the old one";
    r.where = path(oi, "/growth/tetrahedra/remesh_blocked");
    r.advice = "raise the growth's edge_length band, or set \"tetrahedra\": {\"remesh_blocked\": 0}";
    c.remesh = r;
  }
  if (o.stress_bark && o.growth->cracks) {
    // A closed surface has two triangles per vertex; the coupling cracks it unpreprocessed.
    const double triangles = 2 * size.interface_vertices;
    const double cracks = 2.0 * double(o.stress_bark->params.iterations) * double(o.stress_bark->params.cracks_per_iteration);
    c.crack_triangles = triangles + std::min(cracks, triangles);
    MemoryItem m = c.growth;
    m.bytes = c.crack_triangles * kStressBytesPerTriangleRaw;
    m.what = "the crack coupling of " + name + " (about " + count(c.crack_triangles) + " triangles at the last step)";
    m.advice = "raise the growth's edge_length band, or set \"cracks\": false";
    c.cracks = m;
  }
  return c;
}

}  // namespace

double MemoryMoment::bytes() const {
  double b = 0;
  for (const auto& i : items) b += i.bytes;
  return b;
}

const MemoryMoment& MemoryEstimate::peak() const {
  if (moments.empty()) throw std::logic_error("MemoryEstimate::peak: no moments");
  size_t best = 0;
  for (size_t i = 1; i < moments.size(); ++i)
    if (moments[i].bytes() > moments[best].bytes()) best = i;
  return moments[best];
}

MemoryEstimate estimate_memory(const SceneDesc& desc, const MemoryRequest& req) {
  MemoryEstimate e;
  std::map<size_t, double> stress_triangles;
  if (req.command == MemoryCommand::Simulate) {
    for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
      const ObjectDesc& o = desc.objects[oi];
      if (o.type != ObjectType::Tree || !o.tree.strip_bark) continue;
      const StripTreeCost c = strip_tree_cost(o, oi);
      MemoryMoment m{"simulating " + object_name(o, oi, "tree"), {base_item(), strip_sim_item(o, oi, c)}};
      // The limbs are dressed one after the other: the largest field and mesh.
      double field = 0, mesh = 0;
      std::pair<int, int> size;
      for (size_t k = 0; k < c.parts; ++k) {
        const double texels = req.field_width > 0 ? double(req.field_width) * req.field_height : c.field_texels[k];
        if (texels * kSimulateFieldBytesPerTexel > field) field = texels * kSimulateFieldBytesPerTexel, size = c.field_size[k];
        mesh = std::max(mesh, c.mesh_texels[k] * kMeshBytesPerTexel);
      }
      MemoryItem f = field_item(o, oi, "the fracture field of a limb", field, size);
      if (req.field_width > 0) {
        f.file.clear();
        f.where = "--res";
        f.advice = "lower --res (now " + std::to_string(req.field_width) + "x" + std::to_string(req.field_height) + ")";
      }
      m.items.push_back(f);
      if (req.meshes)
        m.items.push_back(
            {"the bark mesh of a limb of " + object_name(o, oi, "tree") + " (texels half a strip wide, at most 4096x4096)", mesh,
             "", "--no-mesh", "pass --no-mesh, or raise strip_width"});
      e.moments.push_back(std::move(m));
    }
    for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
      const ObjectDesc& o = desc.objects[oi];
      if (o.growth) {
        const GrowthCost g = growth_cost(o, oi);
        MemoryMoment m{"growing " + object_name(o, oi, o.type == ObjectType::Tree ? "tree" : "mesh"),
                       {base_item(), g.growth, g.tetgen}};
        if (g.remesh) m.items.push_back(*g.remesh);
        if (g.cracks) m.items.push_back(*g.cracks);
        e.moments.push_back(std::move(m));
        continue;  // a grown object's bark is cracked as it grows (or not at all)
      }
      if (!o.stress_bark) continue;
      e.moments.push_back({"cracking " + object_name(o, oi, o.type == ObjectType::Tree ? "tree" : "mesh"),
                           {base_item(), stress_cost(o, oi).item}});
    }
    if (e.moments.empty()) e.moments.push_back({"simulating", {base_item()}});
    // slice: the growth is over (its tetrahedra freed) when the section is drawn.
    if (req.section.bytes > 0) e.moments.push_back({"drawing the section", {base_item(), req.section}});
    return e;
  }

  // render, turntable, growth: the bark stages in object order, then the geometry and the film.
  std::vector<MemoryItem> surfaces, sims, stresses;  // kept to the end (surfaces; growth: sims)
  double field_scratch = 0;
  for (size_t oi = 0; oi < desc.objects.size(); ++oi) {
    const ObjectDesc& o = desc.objects[oi];
    if (o.type == ObjectType::Tree && o.tree.strip_bark) {
      const StripTreeCost c = strip_tree_cost(o, oi);
      double texels = 0, largest = 0;
      size_t k_largest = 0;
      for (size_t k = 0; k < c.parts; ++k) {
        texels += c.field_texels[k];
        if (c.field_texels[k] > largest) largest = c.field_texels[k], k_largest = k;
      }
      const MemoryItem sim = strip_sim_item(o, oi, c);
      const MemoryItem kept = field_item(o, oi, "the dressed bark", texels * kSurfaceBytesPerTexel, c.field_size[k_largest]);
      MemoryItem dressing = field_item(o, oi, "the fracture fields",
                                       texels * kSurfaceBytesPerTexel + largest * kFieldBytesPerTexel, c.field_size[k_largest]);
      if (req.command == MemoryCommand::Render) {
        MemoryMoment m{"simulating " + object_name(o, oi, "tree"), {base_item()}};
        m.items.insert(m.items.end(), surfaces.begin(), surfaces.end());
        m.items.push_back(sim);
        m.items.push_back(dressing);
        e.moments.push_back(std::move(m));
      } else {
        sims.push_back(sim);
        field_scratch = std::max(field_scratch, largest * kFieldBytesPerTexel);
      }
      surfaces.push_back(kept);
    }
    if (o.growth) {
      const GrowthCost g = growth_cost(o, oi);
      MemoryMoment m{"growing " + object_name(o, oi, o.type == ObjectType::Tree ? "tree" : "mesh"), {base_item()}};
      m.items.insert(m.items.end(), surfaces.begin(), surfaces.end());
      m.items.push_back(g.growth);
      m.items.push_back(g.tetgen);
      if (g.remesh) m.items.push_back(*g.remesh);
      if (g.cracks) {
        m.items.push_back(*g.cracks);
        stress_triangles[oi] = g.crack_triangles;
      }
      e.moments.push_back(std::move(m));
      continue;  // cracked as it grew (or not at all)
    }
    if (o.stress_bark) {
      const StressCost c = stress_cost(o, oi);
      stress_triangles[oi] = c.triangles;
      if (req.command == MemoryCommand::Render) {
        MemoryMoment m{"cracking " + object_name(o, oi, o.type == ObjectType::Tree ? "tree" : "mesh"), {base_item()}};
        m.items.insert(m.items.end(), surfaces.begin(), surfaces.end());
        m.items.push_back(c.item);
        e.moments.push_back(std::move(m));
      } else {
        stresses.push_back(c.item);
      }
    }
  }
  MemoryMoment last{req.command == MemoryCommand::Render ? "rendering" : "rendering a growth frame", {base_item()}};
  // Growth holds every tree's simulation through all frames, dresses and (for stress bark)
  // cracks again for each frame.
  last.items.insert(last.items.end(), sims.begin(), sims.end());
  if (!stresses.empty())
    last.items.push_back(*std::max_element(stresses.begin(), stresses.end(), [](auto& a, auto& b) { return a.bytes < b.bytes; }));
  last.items.insert(last.items.end(), surfaces.begin(), surfaces.end());
  if (field_scratch > 0) {
    MemoryItem scratch = surfaces.front();
    scratch.what = "the fracture field being dressed";
    scratch.bytes = field_scratch;
    last.items.push_back(scratch);
  }
  last.items.push_back(geometry_item(desc, req.height, stress_triangles));
  // Image displacement maps, held as floats from the scene's reading to the end of the dicing.
  for (const ObjectDesc& o : desc.objects) {
    const DisplacementMap* map = o.displacement.map.get();
    if (o.displacement.type != DisplacementDesc::Type::Image || !map) continue;
    last.items.push_back({"the displacement map " + o.displacement.file + " (" + std::to_string(map->width) + "×" +
                              std::to_string(map->height) + " px)",
                          double(map->value.size()) * sizeof(float), desc.file, o.where.path + "/displacement/file",
                          "use a smaller map"});
  }
  last.items.push_back(req.film);
  e.moments.push_back(std::move(last));
  return e;
}

}  // namespace phellem
