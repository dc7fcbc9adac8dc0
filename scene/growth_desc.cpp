#include "scene/growth_desc.h"

#include <cmath>

#include "scene/json_reader.h"
#include "scene/scene_image.h"

namespace phellem {

namespace {

float in_range(const JsonValue& v, float lo, float hi, const std::string& what) {
  const float x = v.number();
  if (!(x >= lo && x <= hi)) v.fail(what);
  return x;
}

bark::GrowthStroke parse_stroke(JsonObject o) {
  bark::GrowthStroke s;
  s.point = o.vec3("point");
  if (auto v = o.get("radius")) s.radius = v->positive();
  if (auto v = o.get("value")) s.value = in_range(*v, -1, 1000, "value must lie in [-1, 1000] (added to the speed factor; -1 stops growth at the point)");
  if (auto v = o.get("direction")) {
    const Vec3f d = v->vec3();
    if (!(d.norm() > 1e-6f) || !d.allFinite()) v->fail("direction must be a non-zero vector (where the stroke turns the growth to)");
    s.direction = d.normalized();
  }
  o.finish();
  return s;
}

// Bilinear between texel centres of a width × height map, repeating: the coordinates wrapped
// into [0, 1) first, so huge or non-finite UVs of a mesh file never reach the integer
// conversions. `texel(a, b)` is the value at column a, row b.
template <class Value, class Texel>
Value bilinear_repeat(int width, int height, double u, double v, Texel texel) {
  if (!std::isfinite(u)) u = 0;
  if (!std::isfinite(v)) v = 0;
  u -= std::floor(u);
  v -= std::floor(v);
  const double x = u * width - 0.5, y = v * height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  auto at = [&](double i, double j) -> Value {
    const long w = long(width), h = long(height);
    const long a = ((long(i) % w) + w) % w, b = ((long(j) % h) + h) % h;
    return texel(size_t(a), size_t(b));
  };
  return Value((1 - ty) * ((1 - tx) * at(fx, fy) + tx * at(fx + 1, fy)) + ty * ((1 - tx) * at(fx, fy + 1) + tx * at(fx + 1, fy + 1)));
}

}  // namespace

float GrowthSpeedMap::at(double u, double v) const {
  return float(bilinear_repeat<double>(width, height, u, v, [&](size_t a, size_t b) { return double(values[b * size_t(width) + a]); }));
}

Eigen::Vector2d GrowthDirectionMap::at(double u, double v) const {
  return bilinear_repeat<Eigen::Vector2d>(width, height, u, v,
                         [&](size_t a, size_t b) { return Eigen::Vector2d(values[b * size_t(width) + a].cast<double>()); });
}

namespace {

std::shared_ptr<GrowthDirectionMap> parse_direction_map(JsonObject m, const std::string& base_dir) {
  auto map = std::make_shared<GrowthDirectionMap>();
  if (auto a = m.get("attribute")) {
    if (m.get("file")) a->fail("a direction map is an image \"file\" or a vertex \"attribute\", not both");
    if (m.get("scale")) a->fail("scale belongs to an image \"file\"; a vertex attribute's length is its own");
    map->attribute = a->string();
    if (map->attribute.empty() || map->attribute.size() > 64)
      a->fail("attribute must name a VEC3 glTF vertex attribute (e.g. \"_GROWTH_DIRECTION\")");
  } else {
    if (!m.get("file")) m.fail("file", "a direction map needs an image \"file\" (a flow map) or a vertex \"attribute\"");
    auto file = m.at("file");
    const SceneImage img = read_scene_image(file, base_dir);
    if (img.channels < 2)
      file.fail("image " + img.path + " has " + std::to_string(img.channels) +
                " channel; a flow map needs two (red: along u, green: along v)");
    map->width = img.width;
    map->height = img.height;
    map->values.resize(size_t(img.width) * size_t(img.height));
    for (size_t i = 0; i < map->values.size(); ++i) {
      const float* p = &img.pixels[i * size_t(img.channels)];
      // Integer pixels cannot be negative: flow maps store 0.5 + 0.5·d.
      const Eigen::Vector2f d = img.encoded ? Eigen::Vector2f(2 * p[0] - 1, 2 * p[1] - 1) : Eigen::Vector2f(p[0], p[1]);
      if (!(d.allFinite() && d.norm() <= 1e6f))
        file.fail("image " + img.path + " holds a direction longer than 1e6 or not finite at pixel " +
                  std::to_string(i % size_t(img.width)) + ", " + std::to_string(i / size_t(img.width)));
      map->values[i] = d;
    }
    if (auto w = m.get("scale")) map->scale = in_range(*w, 0, 1000, "scale must lie in [0, 1000] (multiplies the painted directions)");
  }
  m.finish();
  return map;
}

}  // namespace

GrowthDesc parse_growth(JsonObject o, const std::string& base_dir) {
  GrowthDesc d;
  d.where = {o.file(), o.path()};
  bark::CambialGrowthSettings& s = d.settings;
  bark::GrowthFunction& f = s.function;
  if (auto v = o.get("steps")) s.steps = v->integer(1, 100000);
  double years = 20, age_start = 0;
  if (auto v = o.get("years")) years = in_range(*v, 1e-6f, 1e6f, "years must lie in (0, 1e6] (the span of ages simulated)");
  if (auto v = o.get("age_start")) age_start = in_range(*v, 0, 1e6f, "age_start must lie in [0, 1e6] years");
  s.age_start = age_start;
  s.age_end = age_start + years;
  f.age_scale = 30;
  if (auto v = o.get("age_scale")) f.age_scale = in_range(*v, 1e-6f, 1e6f, "age_scale must lie in (0, 1e6] years (years per unit of the Weibull age t)");
  if (auto v = o.get("weibull_c")) f.weibull_c = in_range(*v, 1e-3f, 20, "weibull_c must lie in [0.001, 20] (the shape c of Eq. 2)");
  if (auto v = o.get("thickness")) f.thickness = in_range(*v, 0, 100, "thickness must lie in [0, 100] m (the total thickening S(inf) = 1 maps to)");
  if (auto v = o.get("eccentricity"))
    f.eccentricity = in_range(*v, -0.99f, 0.99f, "eccentricity must lie in [-0.99, 0.99] (e of Eq. 3)");
  if (auto v = o.get("eccentricity_direction")) {
    const Vec3f dir = v->vec3();
    if (!(dir.norm() > 1e-6f)) v->fail("eccentricity_direction must be a non-zero vector");
    f.eccentricity_direction = dir.normalized();
  }
  if (auto v = o.get("strokes"))
    for (auto& e : v->array()) f.strokes.push_back(parse_stroke(e.object()));
  if (auto v = o.get("speed_map")) {
    JsonObject m = v->object();
    auto map = std::make_shared<GrowthSpeedMap>();
    if (auto a = m.get("attribute")) {
      if (m.get("file")) a->fail("a speed map is an image \"file\" or a vertex \"attribute\", not both");
      map->attribute = a->string();
      if (map->attribute.empty() || map->attribute.size() > 64)
        a->fail("attribute must name a glTF vertex attribute (e.g. \"COLOR_0\" or \"_GROWTH_SPEED\")");
    } else {
      auto file = m.at("file");
      const SceneImage img = read_scene_image(file, base_dir);
      map->width = img.width;
      map->height = img.height;
      map->values.resize(size_t(img.width) * size_t(img.height));
      for (size_t i = 0; i < map->values.size(); ++i) {
        map->values[i] = img.pixels[i * size_t(img.channels)];
        if (!(map->values[i] >= 0 && map->values[i] <= 1e6f))
          file.fail("image " + img.path + " holds a value outside [0, 1e6] (a speed factor: non-negative and finite)");
      }
    }
    if (auto w = m.get("scale")) map->scale = in_range(*w, 0, 1000, "scale must lie in [0, 1000] (multiplies the map's values)");
    m.finish();
    d.speed_map = std::move(map);
  }
  if (auto v = o.get("direction_map")) d.direction_map = parse_direction_map(v->object(), base_dir);
  if (auto v = o.get("obstacles")) {
    for (auto& e : v->array()) d.obstacle_names.push_back(e.string());
  }
  if (auto v = o.get("ring_interval")) s.ring_interval = v->integer(0, 100000);
  if (auto v = o.get("cracks")) d.cracks = v->boolean();
  if (auto v = o.get("texture_cells")) d.texture_cells = v->boolean();
  if (auto v = o.get("crack_iterations")) d.crack_iterations = v->integer(0, 10000);
  if (auto v = o.get("stretch_stress"))
    d.stretch_stress = in_range(*v, 0, 1e6f, "stretch_stress must lie in [0, 1e6] (stress per unit strain, in units of the bark's magnitude)");
  if (auto v = o.get("edge_length")) {
    const Vec2f band = v->vec2();
    if (!(band.x() > 0 && band.y() <= 100 && band.x() * 2 < band.y()))
      v->fail("edge_length must be [min, max] in metres with 0 < 2 min < max <= 100 (a split edge's halves must stay above min)");
    s.edge_min = band.x();
    s.edge_max = band.y();
  }
  if (auto v = o.get("tetrahedra")) {
    JsonObject t = v->object();
    if (auto w = t.get("quality")) s.tet.quality = in_range(*w, 1.1f, 10, "quality must lie in [1.1, 10] (TetGen's radius-edge bound; lower is better shaped, 1.1 is its limit)");
    if (auto w = t.get("max_volume")) s.tet.max_volume = w->non_negative();
    if (auto w = t.get("padding")) s.tet.padding = in_range(*w, 0.05f, 10, "padding must lie in [0.05, 10] (the room around the mesh, in its largest extents)");
    if (auto w = t.get("lattice")) s.tet.lattice = in_range(*w, 0, 10, "lattice must lie in [0, 10] (where TetGen's graded starting points begin, in paddings; 0: none)");
    if (auto w = t.get("time_limit"))
      s.tet.time_limit = in_range(*w, 1, 86400, "time_limit must lie in [1, 86400] (seconds TetGen may take for one tetrahedralization)");
    if (auto w = t.get("remesh_blocked"))
      s.remesh_blocked = in_range(*w, 0, 1, "remesh_blocked must lie in [0, 1] (the share of blocked moves that has the volume made again; 0: never)");
    if (auto w = t.get("upkeep_reach"))
      s.upkeep_reach = in_range(*w, 0, 4, "upkeep_reach must lie in [0, 4] (how far ahead of the front its free rings are carried, in the band's lower bound; 0: every step)");
    t.finish();
  }
  if (auto v = o.get("reverse")) s.reverse = v->boolean();
  o.finish();
  return d;
}

GrowthSize estimate_growth_size(const GrowthDesc& g, size_t input_vertices, double input_area, double mean_edge) {
  const auto& s = g.settings;
  const double edge_max = s.edge_max > 0 ? s.edge_max : 1.5 * mean_edge;
  const double edge_min = s.edge_min > 0 ? s.edge_min : 0.4 * edge_max;
  // The area at the end: the surface offset by the whole thickening (a sphere's area ratio
  // from its own radius, the worst case for a given area), in vertices at the mean of the band.
  const double r = std::sqrt(std::max(input_area, 1e-12) / (4 * 3.14159265358979));
  const double grown = r + double(g.settings.function.thickness) * (1 + std::abs(double(s.function.eccentricity)));
  const double area_end = input_area * (grown / r) * (grown / r);
  const double edge = 0.5 * (edge_min + edge_max);
  const double vertices_end = std::max(double(input_vertices), area_end / (0.433 * edge * edge) / 2);
  // Measured on growth_tree_closeup: about 12 tetrahedra per interface vertex and 350 bytes per
  // tetrahedron with its adjacency, plus the rings (a copy of the interface each).
  const double rings = s.ring_interval > 0 ? double(s.steps) / s.ring_interval + 1 : 0;
  // TetGen's child (bark/growth/tetgen_process.h) at a re-tetrahedralization of the close-up
  // making 455k tetrahedra held 227 MB of private memory: about 500 bytes per tetrahedron.
  // The parent's copies while a re-tetrahedralization is taken in: over the close-up's seven,
  // its peak RSS rose by 79 to 176 bytes per tetrahedron (VmHWM over VmRSS, the peak reset
  // through /proc/self/clear_refs before each). None without re-tetrahedralizing.
  const double remesh = s.remesh_blocked > 0 ? vertices_end * 12 * 180.0 : 0.0;
  return {vertices_end, vertices_end * (12 * 350.0 + rings * 80.0), vertices_end * 12 * 500.0, remesh};
}

}  // namespace phellem
