#include "bark/geometry/tessellation.h"

#include <tbb/parallel_for.h>

#include <array>
#include <map>

namespace phellem {

namespace {

constexpr int kEdgeSamples = 6;  // polyline samples per edge for the length estimate

// round(a * e / n) in integers: both patches sharing an edge snap identically.
inline int snap(int a, int e, int n) { return (2 * a * e + n) / (2 * n); }

struct VertexParam {
  float u, v;
  int copy_from;  // >= 0: position/normal copied bit-exactly from that vertex (periodic seam)
};

}  // namespace

int DicingParams::edge_rate(const Vec3f* pts, int count) const {
  float units = 0.0f;
  for (int i = 0; i + 1 < count; ++i) {
    const float len = (pts[i + 1] - pts[i]).norm();
    if (screen_space) {
      const Vec3f mid = 0.5f * (pts[i] + pts[i + 1]);
      const float footprint = std::max(1e-6f, (mid - camera_position).norm() * pixel_angle);
      units += len / footprint;
    } else {
      units += len;
    }
  }
  const float r = std::ceil(units / (target * scale));
  return std::clamp(static_cast<int>(std::min(r, 1e6f)), 1, max_rate);
}

// ---------------------------------------------------------------- parametric surfaces

namespace {

struct GridRates {
  int pu, pv, columns;       // columns = pu + 1 corner columns (seam column duplicated)
  std::vector<int> h, vert;  // h[(j)*pu + i], vert[j*columns + i]
  int H(int i, int j) const { return h[j * pu + i]; }
  int V(int i, int j) const { return vert[j * columns + i]; }
};

GridRates compute_rates(const ParametricSurface& s, const DicingParams& d) {
  GridRates g;
  g.pu = s.patches_u;
  g.pv = s.patches_v;
  g.columns = g.pu + 1;
  g.h.assign(size_t(g.pu) * (g.pv + 1), 1);
  g.vert.assign(size_t(g.columns) * g.pv, 1);
  tbb::parallel_for(0, g.pv + 1, [&](int j) {
    std::array<Vec3f, kEdgeSamples + 1> pts;
    for (int i = 0; i < g.pu; ++i) {
      for (int k = 0; k <= kEdgeSamples; ++k) pts[k] = s.position((i + float(k) / kEdgeSamples) / g.pu, float(j) / g.pv, nullptr);
      g.h[j * g.pu + i] = d.edge_rate(pts.data(), kEdgeSamples + 1);
    }
    if (j == g.pv) return;
    for (int i = 0; i < g.columns; ++i) {
      if (s.periodic_u && i == g.pu) {
        g.vert[j * g.columns + i] = g.vert[j * g.columns];
        continue;
      }
      for (int k = 0; k <= kEdgeSamples; ++k) pts[k] = s.position(float(i) / g.pu, (j + float(k) / kEdgeSamples) / g.pv, nullptr);
      g.vert[j * g.columns + i] = d.edge_rate(pts.data(), kEdgeSamples + 1);
    }
  });
  return g;
}

}  // namespace

long long estimate_triangles(const ParametricSurface& s, const DicingParams& d) {
  const GridRates g = compute_rates(s, d);
  long long n = 0;
  for (int j = 0; j < g.pv; ++j)
    for (int i = 0; i < g.pu; ++i) {
      const long long nu = std::max(g.H(i, j), g.H(i, j + 1));
      const long long nv = std::max(g.V(i, j), g.V(i + 1, j));
      n += 2 * nu * nv;
    }
  return n;
}

MeshData dice(const ParametricSurface& s, const DicingParams& d) {
  const GridRates g = compute_rates(s, d);
  std::vector<VertexParam> params;
  auto add = [&](float u, float v, int copy_from = -1) {
    params.push_back({u, v, copy_from});
    return static_cast<uint32_t>(params.size() - 1);
  };

  // Corners.
  std::vector<uint32_t> corner(size_t(g.columns) * (g.pv + 1));
  for (int j = 0; j <= g.pv; ++j)
    for (int i = 0; i < g.columns; ++i) {
      const int from = (s.periodic_u && i == g.pu) ? int(corner[j * g.columns]) : -1;
      corner[j * g.columns + i] = add(float(i) / g.pu, float(j) / g.pv, from);
    }
  // Edge interiors: first vertex index of each edge's (rate - 1) inner vertices.
  std::vector<uint32_t> h_first(g.h.size()), v_first(g.vert.size());
  for (int j = 0; j <= g.pv; ++j)
    for (int i = 0; i < g.pu; ++i) {
      const int e = g.H(i, j);
      h_first[j * g.pu + i] = static_cast<uint32_t>(params.size());
      for (int k = 1; k < e; ++k) add((i + float(k) / e) / g.pu, float(j) / g.pv);
    }
  for (int j = 0; j < g.pv; ++j)
    for (int i = 0; i < g.columns; ++i) {
      const int e = g.V(i, j);
      v_first[j * g.columns + i] = static_cast<uint32_t>(params.size());
      const bool seam = s.periodic_u && i == g.pu;
      for (int k = 1; k < e; ++k)
        add(float(i) / g.pu, (j + float(k) / e) / g.pv, seam ? int(v_first[j * g.columns] + k - 1) : -1);
    }

  std::vector<uint32_t> indices;
  std::vector<uint32_t> local;
  for (int j = 0; j < g.pv; ++j)
    for (int i = 0; i < g.pu; ++i) {
      const int eb = g.H(i, j), et = g.H(i, j + 1), el = g.V(i, j), er = g.V(i + 1, j);
      const int nu = std::max(eb, et), nv = std::max(el, er);
      const uint32_t c00 = corner[j * g.columns + i], c10 = corner[j * g.columns + i + 1];
      const uint32_t c01 = corner[(j + 1) * g.columns + i], c11 = corner[(j + 1) * g.columns + i + 1];
      auto on_edge = [](uint32_t a, uint32_t b, uint32_t first, int k, int e) {
        return k == 0 ? a : (k == e ? b : first + k - 1);
      };
      const uint32_t interior_first = static_cast<uint32_t>(params.size());
      for (int b = 1; b < nv; ++b)
        for (int a = 1; a < nu; ++a) add((i + float(a) / nu) / g.pu, (j + float(b) / nv) / g.pv);
      auto vid = [&](int a, int b) -> uint32_t {
        if (b == 0) return on_edge(c00, c10, h_first[j * g.pu + i], snap(a, eb, nu), eb);
        if (b == nv) return on_edge(c01, c11, h_first[(j + 1) * g.pu + i], snap(a, et, nu), et);
        if (a == 0) return on_edge(c00, c01, v_first[j * g.columns + i], snap(b, el, nv), el);
        if (a == nu) return on_edge(c10, c11, v_first[j * g.columns + i + 1], snap(b, er, nv), er);
        return interior_first + (b - 1) * (nu - 1) + (a - 1);
      };
      auto tri = [&](uint32_t x, uint32_t y, uint32_t z) {
        if (x == y || y == z || x == z) return;  // collapsed by edge snapping
        indices.insert(indices.end(), {x, y, z});
      };
      for (int b = 0; b < nv; ++b)
        for (int a = 0; a < nu; ++a) {
          const uint32_t v00 = vid(a, b), v10 = vid(a + 1, b), v01 = vid(a, b + 1), v11 = vid(a + 1, b + 1);
          tri(v00, v10, v11);
          tri(v00, v11, v01);
        }
    }

  MeshData m;
  const size_t nv = params.size();
  m.positions.resize(nv);
  m.normals.resize(nv);
  m.uvs.resize(nv);
  m.displacement.resize(nv);
  if (s.keep_params) m.params.resize(nv);
  const float h = 1e-4f;
  auto evaluate = [&](size_t k) {
    const VertexParam& p = params[k];
    m.uvs[k] = s.texcoord(p.u, p.v);
    if (s.keep_params) m.params[k] = Vec4f(p.u, p.v, 0, 0);
    if (p.copy_from >= 0) return;
    m.positions[k] = s.position(p.u, p.v, &m.displacement[k]);
    // Normal of the displaced surface by central differences (one-sided at open borders).
    const float u0 = s.periodic_u ? p.u - h : std::max(0.0f, p.u - h);
    const float u1 = s.periodic_u ? p.u + h : std::min(1.0f, p.u + h);
    const float v0 = std::max(0.0f, p.v - h), v1 = std::min(1.0f, p.v + h);
    const Vec3f du = s.position(u1, p.v, nullptr) - s.position(u0, p.v, nullptr);
    const Vec3f dv = s.position(p.u, v1, nullptr) - s.position(p.u, v0, nullptr);
    Vec3f n = du.cross(dv);
    const float len = n.norm();
    m.normals[k] = len > 1e-20f ? Vec3f(n / len) : Vec3f(0, 1, 0);
  };
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t k = r.begin(); k < r.end(); ++k) evaluate(k);
  });
  for (size_t k = 0; k < nv; ++k)
    if (params[k].copy_from >= 0) {
      m.positions[k] = m.positions[params[k].copy_from];
      m.normals[k] = m.normals[params[k].copy_from];
      m.displacement[k] = m.displacement[params[k].copy_from];
    }
  m.indices = std::move(indices);
  compute_tangents(m);
  return m;
}

// ---------------------------------------------------------------- displaced triangle meshes

namespace {

struct EdgeTable {
  std::map<std::pair<uint32_t, uint32_t>, int> id;  // (min, max) vertex pair -> edge
  std::vector<std::pair<uint32_t, uint32_t>> ends;
  std::vector<int> rate;
};

Vec3f displaced(const MeshData& m, const SurfaceDisplacementFn& disp, uint32_t a, uint32_t b, uint32_t c, const Vec3f& bary,
                Vec4f* params = nullptr, float* offset = nullptr) {
  const Vec3f p = bary[0] * m.positions[a] + bary[1] * m.positions[b] + bary[2] * m.positions[c];
  const Vec3f n = (bary[0] * m.normals[a] + bary[1] * m.normals[b] + bary[2] * m.normals[c]).normalized();
  Vec2f uv = Vec2f::Zero();
  if (!m.uvs.empty()) uv = bary[0] * m.uvs[a] + bary[1] * m.uvs[b] + bary[2] * m.uvs[c];
  const float d = disp(uv, p, n, params);
  if (offset) *offset = d;
  return p + n * d;
}

EdgeTable edge_rates(const MeshData& m, const SurfaceDisplacementFn& disp, const DicingParams& d) {
  EdgeTable t;
  for (size_t f = 0; f + 2 < m.indices.size(); f += 3)
    for (int e = 0; e < 3; ++e) {
      uint32_t a = m.indices[f + e], b = m.indices[f + (e + 1) % 3];
      auto key = std::minmax(a, b);
      if (t.id.emplace(key, int(t.ends.size())).second) t.ends.push_back(key);
    }
  t.rate.assign(t.ends.size(), 1);
  tbb::parallel_for(size_t(0), t.ends.size(), [&](size_t e) {
    std::array<Vec3f, kEdgeSamples + 1> pts;
    const auto [a, b] = t.ends[e];
    if (d.refine_edge && !d.refine_edge(m.positions[a], m.positions[b])) return;  // rate stays 1
    for (int k = 0; k <= kEdgeSamples; ++k) {
      const float x = float(k) / kEdgeSamples;
      pts[k] = displaced(m, disp, a, b, b, Vec3f(1 - x, x, 0));
    }
    t.rate[e] = d.edge_rate(pts.data(), kEdgeSamples + 1);
  });
  return t;
}

}  // namespace

long long estimate_triangles(const MeshData& base, const SurfaceDisplacementFn& disp, const DicingParams& d) {
  const EdgeTable t = edge_rates(base, disp, d);
  long long n = 0;
  for (size_t f = 0; f + 2 < base.indices.size(); f += 3) {
    int level = 1;
    for (int e = 0; e < 3; ++e)
      level = std::max(level, t.rate[t.id.at(std::minmax(base.indices[f + e], base.indices[f + (e + 1) % 3]))]);
    n += (long long)level * level;
  }
  return n;
}

MeshData dice(const MeshData& base, const SurfaceDisplacementFn& disp, const DicingParams& d, bool keep_params) {
  const EdgeTable t = edge_rates(base, disp, d);
  struct Origin {
    uint32_t a, b, c;
    Vec3f bary;
  };
  std::vector<Origin> verts;
  for (uint32_t v = 0; v < base.positions.size(); ++v) verts.push_back({v, v, v, Vec3f(1, 0, 0)});
  std::vector<uint32_t> edge_first(t.ends.size());
  for (size_t e = 0; e < t.ends.size(); ++e) {
    edge_first[e] = static_cast<uint32_t>(verts.size());
    const auto [a, b] = t.ends[e];
    for (int k = 1; k < t.rate[e]; ++k) {
      const float x = float(k) / t.rate[e];
      verts.push_back({a, b, b, Vec3f(1 - x, x, 0)});
    }
  }
  std::vector<uint32_t> indices;
  for (size_t f = 0; f + 2 < base.indices.size(); f += 3) {
    const uint32_t c[3] = {base.indices[f], base.indices[f + 1], base.indices[f + 2]};
    int e_rate[3], e_id[3];
    int n = 1;
    for (int e = 0; e < 3; ++e) {
      e_id[e] = t.id.at(std::minmax(c[e], c[(e + 1) % 3]));
      e_rate[e] = t.rate[e_id[e]];
      n = std::max(n, e_rate[e]);
    }
    // Vertex k of edge e counted from c[e] towards c[e+1].
    auto edge_vertex = [&](int e, int k) -> uint32_t {
      const int r = e_rate[e];
      if (k == 0) return c[e];
      if (k == r) return c[(e + 1) % 3];
      const bool forward = t.ends[e_id[e]].first == c[e];
      return edge_first[e_id[e]] + (forward ? k - 1 : r - k - 1);
    };
    // Grid point (a, b): a steps from c0 towards c1, b steps from c0 towards c2.
    const uint32_t interior_first = static_cast<uint32_t>(verts.size());
    std::vector<int> row_start(n + 1, 0);
    int count = 0;
    for (int b = 1; b < n; ++b) {
      row_start[b] = count;
      for (int a = 1; a + b < n; ++a, ++count)
        verts.push_back({c[0], c[1], c[2], Vec3f(1 - float(a + b) / n, float(a) / n, float(b) / n)});
    }
    auto vid = [&](int a, int b) -> uint32_t {
      if (b == 0) return edge_vertex(0, snap(a, e_rate[0], n));
      if (a + b == n) return edge_vertex(1, snap(b, e_rate[1], n));
      if (a == 0) return edge_vertex(2, snap(n - b, e_rate[2], n));
      return interior_first + row_start[b] + (a - 1);
    };
    auto tri = [&](uint32_t x, uint32_t y, uint32_t z) {
      if (x == y || y == z || x == z) return;
      indices.insert(indices.end(), {x, y, z});
    };
    for (int b = 0; b < n; ++b)
      for (int a = 0; a + b < n; ++a) {
        tri(vid(a, b), vid(a + 1, b), vid(a, b + 1));
        if (a + b + 1 < n) tri(vid(a + 1, b), vid(a + 1, b + 1), vid(a, b + 1));
      }
  }
  MeshData m;
  m.material = base.material;
  m.positions.resize(verts.size());
  if (!base.uvs.empty()) m.uvs.resize(verts.size());
  if (!base.texture_levels.empty()) m.texture_levels.resize(verts.size());
  if (keep_params) m.params.resize(verts.size());
  m.displacement.resize(verts.size());
  std::vector<Vec3f> flat(verts.size()), smooth(verts.size());  // the grid undisplaced, for the normals below
  tbb::parallel_for(size_t(0), verts.size(), [&](size_t k) {
    const Origin& o = verts[k];
    m.positions[k] = displaced(base, disp, o.a, o.b, o.c, o.bary, keep_params ? &m.params[k] : nullptr, &m.displacement[k]);
    flat[k] = o.bary[0] * base.positions[o.a] + o.bary[1] * base.positions[o.b] + o.bary[2] * base.positions[o.c];
    smooth[k] = (o.bary[0] * base.normals[o.a] + o.bary[1] * base.normals[o.b] + o.bary[2] * base.normals[o.c]).normalized();
    if (!base.uvs.empty()) m.uvs[k] = o.bary[0] * base.uvs[o.a] + o.bary[1] * base.uvs[o.b] + o.bary[2] * base.uvs[o.c];
    if (!base.texture_levels.empty())
      m.texture_levels[k] = o.bary[0] * base.texture_levels[o.a] + o.bary[1] * base.texture_levels[o.b] +
                            o.bary[2] * base.texture_levels[o.c];
  });
  m.indices = std::move(indices);
  // Shading normals: the displaced grid's normal, carried from the flat base triangle onto the
  // base's smooth (interpolated) normal, N = normalize(N_displaced − N_flat + n_smooth). Where
  // nothing is displaced this is exactly the interpolated base normal, as on undiced triangles:
  // a coarse mesh shades smoothly, not as the facets its diced patches would otherwise show.
  compute_vertex_normals(m);
  const std::vector<Vec3f> flat_normals = vertex_normals(flat, m.indices);
  for (size_t k = 0; k < verts.size(); ++k) {
    const Vec3f n = m.normals[k] - flat_normals[k] + smooth[k];
    m.normals[k] = n.squaredNorm() > 1e-12f ? Vec3f(n.normalized()) : smooth[k];
  }
  compute_tangents(m);
  return m;
}

long long estimate_triangles(const MeshData& base, const DisplacementFn& disp, const DicingParams& d) {
  return estimate_triangles(
      base, SurfaceDisplacementFn([&disp](const Vec2f& uv, const Vec3f& p, const Vec3f&, Vec4f*) { return disp(uv, p); }), d);
}

MeshData dice(const MeshData& base, const DisplacementFn& disp, const DicingParams& d) {
  return dice(base, SurfaceDisplacementFn([&disp](const Vec2f& uv, const Vec3f& p, const Vec3f&, Vec4f*) { return disp(uv, p); }),
              d);
}

}  // namespace phellem
