#include "scene/scene_parser.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/builtin_files.h"
#include "scene/displacement_map.h"
#include "scene/json_reader.h"
#include "scene/procedural_mesh_desc.h"
#include "util/input_file.h"
#include "util/output_set.h"

namespace phellem {

namespace {

// The largest emission colour component and strength: a float sample of their product (at
// most 1e12), times a path's throughput and summed over a pixel's samples, stays far inside
// a float, where 3e38 × 10 did not (every sample that saw it was discarded as non-finite).
constexpr float kMaxEmission = 1e6f;

namespace fs = std::filesystem;

struct Ctx {
  std::string file;
  fs::path base_dir;
  std::vector<std::string>* files;  // every file resolved: SceneDesc::files

  // A file name against the scene's folder. `builtin`: a "builtin:<name>" file
  // (io/builtin_files.h) may stand for it, as it may wherever OpenImageIO reads the image.
  std::string resolve(const JsonValue& v, bool must_exist = true, bool builtin = false) const {
    const std::string s = v.string();
    if (s.empty()) v.fail("file name is empty");
    if (is_builtin_path(s)) {
      if (!builtin) v.fail("builtin files (" + builtin_names() + ") are for environment maps and bark images only");
      if (auto why = builtin_problem(s); !why.empty()) v.fail(why);
      return s;
    }
    fs::path p(s);
    if (p.is_relative()) p = base_dir / p;
    p = p.lexically_normal();
    files->push_back(p.string());
    if (!must_exist) return p.string();
    if (auto why = input_file_message(p.string(), "a file a scene names")) v.fail(*why);
    return p.string();
  }
};

Location loc(const Ctx& c, const std::string& path) { return {c.file, path}; }

CameraDesc parse_camera(JsonObject o) {
  CameraDesc c;
  c.position = o.vec3("position", c.position);
  c.look_at = o.vec3("look_at", c.look_at);
  c.up = o.vec3("up", c.up);
  if (auto v = o.get("fov_deg")) {
    c.fov_deg = v->number();
    if (!(c.fov_deg > 0.5f && c.fov_deg < 179.0f)) v->fail("must lie in (0.5, 179) degrees");
  }
  if (auto v = o.get("aperture_radius")) c.aperture_radius = v->non_negative();
  if (auto v = o.get("focus_distance")) c.focus_distance = v->non_negative();
  if ((c.look_at - c.position).norm() < 1e-6f) o.fail("look_at", "must differ from position");
  if (c.up.norm() < 1e-6f || (c.look_at - c.position).normalized().cross(c.up.normalized()).norm() < 1e-4f)
    o.fail("up", "must be non-zero and not parallel to the viewing direction");
  o.finish();
  return c;
}

FilterDesc parse_filter(const JsonValue& v) {
  FilterDesc f;
  // A filter's type and its default radius; false for an unknown name.
  auto set_type = [&f](const std::string& t) {
    if (t == "blackman-harris")
      f.type = FilterType::BlackmanHarris;
    else if (t == "gaussian")
      f.type = FilterType::Gaussian;
    else if (t == "box") {
      f.type = FilterType::Box;
      f.radius = 0.5f;
    } else
      return false;
    return true;
  };
  const std::string allowed = "; allowed: blackman-harris, gaussian, box";
  if (v.is_string()) {
    const std::string t = v.string();
    if (!set_type(t)) v.fail("unknown filter \"" + t + "\"" + allowed);
    return f;
  }
  JsonObject o = v.object();
  const std::string t = o.string("type", "blackman-harris");
  if (!set_type(t)) o.fail("type", "unknown filter \"" + t + "\"" + allowed);
  if (auto r = o.get("radius")) {
    f.radius = r->positive();
    if (f.radius > 8.0f) r->fail("filter radius must be <= 8 pixels");
  }
  o.finish();
  return f;
}

TessellationDesc parse_tessellation(JsonObject o) {
  TessellationDesc t;
  const std::string mode = o.string("mode", "screen");
  if (mode == "screen")
    t.mode = TessellationDesc::Mode::Screen;
  else if (mode == "object")
    t.mode = TessellationDesc::Mode::Object;
  else
    o.fail("mode", "unknown mode \"" + mode + "\"; allowed: screen, object");
  if (auto v = o.get("pixels_per_edge")) t.pixels_per_edge = v->positive();
  if (auto v = o.get("edge_length")) t.edge_length = v->positive();
  if (auto v = o.get("edge_length_scale")) t.edge_length_scale = v->positive();
  if (auto v = o.get("max_triangles")) {
    const int n = v->integer();
    if (n < 1000) v->fail("must be >= 1000");
    t.max_triangles = n;
  }
  if (auto v = o.get("dicing_camera")) t.dicing_camera = parse_camera(v->object());
  t.crack_aware = o.boolean("crack_aware", true);
  o.finish();
  return t;
}

RenderDesc parse_render(JsonObject o) {
  RenderDesc r;
  if (auto v = o.get("resolution")) {
    const auto a = v->array();
    if (a.size() != 2) v->fail("expected [width, height]");
    r.width = a[0].integer();
    r.height = a[1].integer();
    if (r.width < 1 || r.height < 1 || r.width > 32768 || r.height > 32768) v->fail("width and height must lie in [1, 32768]");
  }
  if (auto v = o.get("spp")) r.spp = v->integer(1, 1 << 20);
  if (auto v = o.get("max_depth")) r.max_depth = v->integer(1, 1024);
  if (auto v = o.get("seed")) r.seed = v->seed();
  if (auto v = o.get("filter")) r.filter = parse_filter(*v);
  if (auto v = o.get("tessellation")) r.tessellation = parse_tessellation(v->object());
  o.finish();
  return r;
}

LightDesc parse_light(const Ctx& c, JsonObject o) {
  LightDesc l;
  l.where = loc(c, o.path());
  const std::string type = o.string("type");
  if (type == "environment") {
    if (auto f = o.get("file")) {
      l.type = LightType::EnvironmentMap;
      l.file = c.resolve(*f, true, true);
      if (auto v = o.get("intensity")) l.intensity = v->non_negative();
      l.rotation_deg = o.number("rotation_deg", 0.0f);
      if (auto v = o.get("clamp")) {
        l.clamp = v->number();
        if (!(l.clamp > 0)) v->fail("clamp must be > 0 (the largest radiance kept, before intensity)");
      }
    } else {
      l.type = LightType::EnvironmentUniform;
      l.color = o.color("color", l.color);
      if (auto v = o.get("intensity")) l.intensity = v->non_negative();
    }
  } else if (type == "sun") {
    l.type = LightType::Sun;
    auto d = o.at("direction");
    l.direction = d.vec3();
    if (l.direction.norm() < 1e-6f) d.fail("direction must be non-zero");
    l.direction.normalize();
    l.has_direction = true;
    if (auto v = o.get("irradiance")) l.irradiance = v->non_negative();
    if (auto v = o.get("angle_deg")) {
      l.angle_deg = v->non_negative();
      if (l.angle_deg > 20.0f) v->fail("sun angular diameter must lie in [0, 20] degrees");
    }
    l.color = o.color("color", l.color);
  } else if (type == "sky") {
    l.type = LightType::Sky;
    if (auto d = o.get("sun_direction")) {
      l.direction = d->vec3();
      if (l.direction.norm() < 1e-6f) d->fail("sun_direction must be non-zero");
      l.direction.normalize();
      l.has_direction = true;
    }
    if (auto v = o.get("turbidity")) {
      l.turbidity = v->number();
      if (l.turbidity < 1.7f || l.turbidity > 10.0f) v->fail("turbidity must lie in [1.7, 10] (Preetham model)");
    }
    if (auto v = o.get("intensity")) l.sky_intensity = v->non_negative();
    if (auto v = o.get("ground_albedo")) {
      l.ground_albedo = v->non_negative();
      if (l.ground_albedo > 1.0f) v->fail("must lie in [0, 1]");
    }
  } else {
    o.fail("type", "unknown light type \"" + type +
                       "\"; allowed: environment, sun, sky (emissive meshes are lights through an emissive material)");
  }
  o.finish();
  return l;
}

TextureDesc parse_texture(const Ctx& c, const JsonValue& v, bool srgb_default) {
  TextureDesc t;
  t.srgb = srgb_default;
  if (v.is_string()) {
    t.file = c.resolve(v);
    return t;
  }
  JsonObject o = v.object();
  if (auto f = o.get("file")) t.file = c.resolve(*f);
  if (auto p = o.get("procedural")) {
    t.procedural = p->string();
    if (t.procedural != "bark") p->fail("unknown procedural texture \"" + t.procedural + "\"; allowed: bark");
    t.color_a = o.color("color_a", t.color_a);
    t.color_b = o.color("color_b", t.color_b);
  }
  if (auto s = o.get("scale")) {
    t.scale = s->vec2();
    if ((t.scale.array() <= 0.0f).any()) s->fail("scale must be > 0");
  }
  t.srgb = o.boolean("srgb", srgb_default);
  if (t.file.empty() == t.procedural.empty()) o.fail("", "a texture needs exactly one of \"file\" or \"procedural\"");
  o.finish();
  return t;
}

MaterialDesc parse_material(const Ctx& c, const std::string& name, JsonObject o) {
  MaterialDesc m;
  m.name = name;
  m.where = loc(c, o.path());
  const std::string type = o.string("type");
  if (type == "diffuse")
    m.type = MaterialType::Diffuse;
  else if (type == "bark")
    m.type = MaterialType::Bark;
  else if (type == "conductor")
    m.type = MaterialType::Conductor;
  else if (type == "dielectric")
    m.type = MaterialType::Dielectric;
  else if (type == "emissive")
    m.type = MaterialType::Emissive;
  else
    o.fail("type", "unknown material type \"" + type + "\"; allowed: diffuse, bark, conductor, dielectric, emissive");

  auto unit_color = [&](const std::string& key, Color fallback) {
    auto v = o.get(key);
    if (!v) return fallback;
    Color col = v->color();
    if ((col > 1.0f).any()) v->fail("reflectance components must lie in [0, 1]");
    return col;
  };
  auto unit = [&](const std::string& key, float fallback) {
    auto v = o.get(key);
    if (!v) return fallback;
    const float x = v->number();
    if (x < 0.0f || x > 1.0f) v->fail("must lie in [0, 1]");
    return x;
  };

  if (m.type == MaterialType::Emissive) {
    // Radiance = color × strength, each at most kMaxEmission.
    if (auto v = o.get("color")) {
      m.emission = v->color();
      if ((m.emission > kMaxEmission).any()) v->fail("colour components must lie in [0, 1e6] (radiance = color × strength)");
    }
    if (auto v = o.get("strength")) {
      m.strength = v->non_negative();
      if (m.strength > kMaxEmission) v->fail("must lie in [0, 1e6] (radiance = color × strength)");
    }
  } else {
    m.base_color = unit_color("base_color", m.base_color);
    if (auto v = o.get("base_color_texture")) m.base_color_texture = parse_texture(c, *v, true);
  }
  if (m.type == MaterialType::Bark || m.type == MaterialType::Conductor || m.type == MaterialType::Dielectric) {
    m.roughness = unit("roughness", m.roughness);
    if (auto v = o.get("roughness_texture")) m.roughness_texture = parse_texture(c, *v, false);
    if (auto v = o.get("normal_texture")) m.normal_texture = parse_texture(c, *v, false);
  }
  if (m.type == MaterialType::Bark) m.specular = unit("specular", m.specular);
  if (m.type == MaterialType::Dielectric) {
    if (auto v = o.get("ior")) {
      m.ior = v->number();
      if (m.ior < 1.0f || m.ior > 4.0f) v->fail("ior must lie in [1, 4]");
    }
  }
  o.finish();
  return m;
}

Mat4f parse_transform(JsonObject o) {
  if (auto m = o.get("matrix")) {
    const auto v = m->numbers();
    if (v.size() != 16) m->fail("matrix must have 16 numbers (row-major 4x4)");
    Mat4f mat;
    for (int r = 0; r < 4; ++r)
      for (int cc = 0; cc < 4; ++cc) mat(r, cc) = v[r * 4 + cc];
    if (std::abs(mat.topLeftCorner<3, 3>().determinant()) < 1e-12f) m->fail("matrix is singular");
    if (o.has("translate") || o.has("rotate_deg") || o.has("scale"))
      o.fail("matrix", "give either \"matrix\" or translate/rotate_deg/scale, not both");
    o.finish();
    return mat;
  }
  Vec3f t = o.vec3("translate", Vec3f::Zero());
  Vec3f r = o.vec3("rotate_deg", Vec3f::Zero());
  Vec3f s(1, 1, 1);
  if (auto sv = o.get("scale")) {
    if (sv->is_number())
      s = Vec3f::Constant(sv->positive());
    else
      s = sv->vec3();
    if ((s.array() == 0.0f).any()) sv->fail("scale components must be non-zero");
  }
  o.finish();
  // Rotations about X, then Y, then Z (degrees), applied after scaling.
  Eigen::Affine3f a = Eigen::Affine3f::Identity();
  a.translate(t);
  a.rotate(Eigen::AngleAxisf(radians(r.z()), Vec3f::UnitZ()));
  a.rotate(Eigen::AngleAxisf(radians(r.y()), Vec3f::UnitY()));
  a.rotate(Eigen::AngleAxisf(radians(r.x()), Vec3f::UnitX()));
  a.scale(s);
  return a.matrix();
}

// Bounds of an image displacement: a scale beyond metres, or a map repeated more often than a
// float texture coordinate can resolve, is a typing mistake, not bark.
constexpr float kMaxDisplacementScale = 10.0f;  // metres per unit of the map's value
constexpr float kMaxUvRepeat = 10000.0f;
constexpr float kMaxPatchSize = 1000.0f;  // metres: a patch is a piece of bark, not a landscape

void parse_image_displacement(const Ctx& c, JsonObject& o, DisplacementDesc& d) {
  auto file = o.at("file");
  d.file = c.resolve(file);
  if (auto v = o.get("scale")) {
    d.scale = v->number();
    if (std::abs(d.scale) > kMaxDisplacementScale)
      v->fail("scale must lie in [-" + std::to_string(int(kMaxDisplacementScale)) + ", " +
              std::to_string(int(kMaxDisplacementScale)) + "] metres per unit of the map's value, found " + std::to_string(d.scale));
  }
  if (auto v = o.get("midlevel")) d.midlevel = v->number();
  if (auto v = o.get("uv_repeat")) {
    d.uv_repeat = v->positive();
    if (d.uv_repeat > kMaxUvRepeat)
      v->fail("uv_repeat must lie in (0, " + std::to_string(int(kMaxUvRepeat)) + "], found " + std::to_string(d.uv_repeat));
  }
  if (auto v = o.get("wrap")) {
    const std::string w = v->string();
    if (w != "repeat" && w != "clamp") v->fail("unknown wrap \"" + printable(w) + "\"; allowed: repeat, clamp");
    d.clamp = w == "clamp";
  }
  d.map = std::make_shared<const DisplacementMap>(read_displacement_map(d.file));
}

DisplacementDesc parse_displacement(const Ctx& c, JsonObject o) {
  DisplacementDesc d;
  const std::string type = o.string("type");
  if (type == "grooves")
    d.type = DisplacementDesc::Type::Grooves;
  else if (type == "noise")
    d.type = DisplacementDesc::Type::Noise;
  else if (type == "image")
    d.type = DisplacementDesc::Type::Image;
  else if (type == "none")
    d.type = DisplacementDesc::Type::None;
  else
    o.fail("type", "unknown displacement \"" + type + "\"; allowed: none, grooves, noise, image");
  if (d.type == DisplacementDesc::Type::Image) {
    parse_image_displacement(c, o, d);
  } else {
    if (auto v = o.get("amplitude")) d.amplitude = v->non_negative();
    if (auto v = o.get("frequency")) d.frequency = v->positive();
    if (auto v = o.get("sharpness")) d.sharpness = v->positive();
    if (auto v = o.get("waviness")) d.waviness = v->non_negative();
    if (auto v = o.get("seed")) d.seed = v->seed();
  }
  o.finish();
  return d;
}

std::vector<float> parse_radius_profile(const JsonValue& v) {
  std::vector<float> r;
  if (v.is_number()) {
    r = {v.positive()};
  } else {
    r = v.numbers();
    if (r.empty()) v.fail("radius profile must not be empty");
    for (size_t i = 0; i < r.size(); ++i)
      if (!(r[i] > 0.0f))
        throw UserError(v.file(), v.path() + "/" + std::to_string(i), "radius must be > 0, found " + std::to_string(r[i]));
  }
  if (r.size() == 1) r.push_back(r[0]);
  return r;
}

BranchDesc parse_branch(const Ctx& c, JsonObject o, int depth) {
  BranchDesc b;
  b.where = loc(c, o.path());
  if (auto v = o.get("attach")) {
    b.attach = v->number();
    if (b.attach < 0.0f || b.attach > 1.0f) v->fail("attach must lie in [0, 1] (fraction of the parent's length)");
  }
  b.azimuth_deg = o.number("azimuth_deg", 0.0f);
  if (auto v = o.get("angle_deg")) {
    b.angle_deg = v->number();
    if (b.angle_deg < 5.0f || b.angle_deg > 120.0f) v->fail("angle_deg must lie in [5, 120]");
  }
  b.length = o.at("length").positive();
  b.radius = parse_radius_profile(o.at("radius"));
  if (auto v = o.get("curvature")) b.curvature = v->number();
  if (auto v = o.get("branches")) {
    if (depth >= 4) v->fail("branches nest at most 4 levels deep");
    for (auto& e : v->array()) b.branches.push_back(parse_branch(c, e.object(), depth + 1));
  }
  o.finish();
  return b;
}

TreeDesc parse_tree(const Ctx& c, JsonObject& o, uint64_t seed, std::shared_ptr<const StressBarkDesc>* stress) {
  TreeDesc t;
  auto axis = o.at("axis");
  for (auto& p : axis.array()) t.axis.push_back(p.vec3());
  if (t.axis.size() < 2) axis.fail("axis needs at least 2 points");
  for (size_t i = 1; i < t.axis.size(); ++i)
    if ((t.axis[i] - t.axis[i - 1]).norm() < 1e-5f)
      throw UserError(axis.file(), axis.path() + "/" + std::to_string(i), "axis points must be distinct");
  t.radius = parse_radius_profile(o.at("radius"));
  if (auto v = o.get("branches"))
    for (auto& e : v->array()) t.branches.push_back(parse_branch(c, e.object(), 1));
  if (auto v = o.get("uv_repeat")) t.uv_repeat = v->positive();
  if (auto v = o.get("bark")) {
    JsonObject bo = v->object();
    if (bo.string("model", "") == "stress")
      *stress = std::make_shared<StressBarkDesc>(parse_stress_bark(v->object(), c.base_dir.string(), seed));
    else
      t.strip_bark = std::make_shared<StripBarkDesc>(parse_strip_bark(v->object(), c.base_dir.string(), seed));
  }
  return t;
}

ObjectDesc parse_object(const Ctx& c, JsonObject o, const SceneDesc& scene) {
  ObjectDesc d;
  d.where = loc(c, o.path());
  if (auto v = o.get("name")) {
    d.name = v->string();
    // `phellem simulate` names its output files after objects: a name must stay in its folder.
    if (const std::string why = d.name.empty() ? "" : file_name_problem(d.name); !why.empty())
      v->fail("the name \"" + printable(d.name) + "\" " + why +
              "; names are used as file names in the output folder (no '/', no control character, no leading '.', 1 to " +
              std::to_string(kMaxDerivedNameBytes) + " bytes)");
  }
  const std::string type = o.string("type");
  if (auto m = o.get("material")) {
    d.material = m->string();
    if (scene.find_material(d.material) < 0) {
      std::string names;
      for (auto& mm : scene.materials) names += (names.empty() ? "" : ", ") + mm.name;
      m->fail("no material named \"" + d.material + "\" (defined: " + (names.empty() ? "none" : names) + ")");
    }
  }
  if (type == "sphere") {
    d.type = ObjectType::Sphere;
    d.center = o.vec3("center", d.center);
    d.radius = o.at("radius").positive();
  } else if (type == "plane") {
    d.type = ObjectType::Plane;
    d.point = o.vec3("point", d.point);
    auto n = o.get("normal");
    if (n) {
      d.normal = n->vec3();
      if (d.normal.norm() < 1e-6f) n->fail("normal must be non-zero");
    }
    d.normal.normalize();
    if (auto s = o.get("size")) {
      if (s->is_number())
        d.size = Vec2f::Constant(s->positive());
      else {
        d.size = s->vec2();
        if ((d.size.array() <= 0.0f).any()) s->fail("size must be > 0");
      }
    }
    if (auto v = o.get("uv_scale")) d.uv_scale = v->positive();
  } else if (type == "patch") {
    d.type = ObjectType::Patch;
    d.point = o.vec3("center", Vec3f::Zero());
    d.normal = Vec3f(0, 0, 1);
    if (auto n = o.get("normal")) {
      d.normal = n->vec3();
      if (d.normal.norm() < 1e-6f) n->fail("normal must be non-zero");
    }
    d.normal.normalize();
    if (auto u = o.get("up")) {
      d.up = u->vec3();
      if (d.up.norm() < 1e-6f) u->fail("up must be non-zero");
    }
    d.up.normalize();
    if (std::abs(d.up.dot(d.normal)) > 0.999f)
      o.fail(o.has("up") ? "up" : "normal", "up and normal must not be parallel (up gives the patch's v direction within its plane)");
    auto s = o.at("size");
    d.size = s.is_number() ? Vec2f::Constant(s.positive()) : s.vec2();
    if ((d.size.array() <= 0.0f).any() || (d.size.array() > kMaxPatchSize).any())
      s.fail("size must lie in (0, " + std::to_string(int(kMaxPatchSize)) + "] metres, found " + std::to_string(d.size.x()) + " × " +
             std::to_string(d.size.y()));
  } else if (type == "mesh") {
    d.type = ObjectType::Mesh;
    if (o.has("file") == o.has("procedural"))
      o.fail(o.has("file") ? "procedural" : "", "a mesh has either \"file\" or \"procedural\"");
    if (auto f = o.get("file")) {
      d.file = c.resolve(*f);
      const std::string ext = fs::path(d.file).extension().string();
      if (ext != ".gltf" && ext != ".glb" && ext != ".obj")
        f->fail("unsupported mesh format \"" + ext + "\"; allowed: .gltf, .glb, .obj");
    } else {
      d.procedural = parse_procedural(o.at("procedural").object());
    }
    if (auto t = o.get("transform")) d.transform.matrix = parse_transform(t->object());
    if (auto b = o.get("bark")) {
      JsonObject bo = b->object();
      if (bo.string("model", "") == "strips")
        bo.fail("model", "the strip model needs a tree object (generalized cylinders); on meshes use \"stress\"");
      d.stress_bark = std::make_shared<StressBarkDesc>(parse_stress_bark(b->object(), c.base_dir.string(), scene.render.seed));
    }
    if (auto g = o.get("growth")) {
      d.growth = std::make_shared<GrowthDesc>(parse_growth(g->object(), c.base_dir.string()));
      if (d.procedural && d.growth->speed_map && !d.growth->speed_map->attribute.empty())
        throw UserError(c.file, d.growth->where.path + "/speed_map/attribute",
                        "a vertex attribute comes from a mesh file; a procedural mesh has none (paint an image \"file\")");
      if (d.procedural && d.growth->direction_map && !d.growth->direction_map->attribute.empty())
        throw UserError(c.file, d.growth->where.path + "/direction_map/attribute",
                        "a vertex attribute comes from a mesh file; a procedural mesh has none (paint an image \"file\", or use strokes with a \"direction\")");
      if (d.procedural)
        if (const std::string problem = growth_problem(*d.procedural); !problem.empty())
          throw UserError(c.file, o.path() + "/procedural/tube", problem);
    }
  } else if (type == "tree") {
    d.type = ObjectType::Tree;
    d.tree = parse_tree(c, o, scene.render.seed, &d.stress_bark);
    // A growing tree grows its trunk and branches joined into one closed surface (mesh_source.h).
    if (auto g = o.get("growth")) {
      if (d.tree.strip_bark)
        g->fail(
            "a growing tree takes stress bark (\"model\": \"stress\") or none; the strip model's bark lives on the "
            "tree's cylinders, which do not grow");
      d.growth = std::make_shared<GrowthDesc>(parse_growth(g->object(), c.base_dir.string()));
      if (d.growth->speed_map && !d.growth->speed_map->attribute.empty())
        throw UserError(c.file, d.growth->where.path + "/speed_map/attribute",
                        "a vertex attribute comes from a mesh file; a tree has none (paint an image \"file\")");
      if (d.growth->direction_map && !d.growth->direction_map->attribute.empty())
        throw UserError(c.file, d.growth->where.path + "/direction_map/attribute",
                        "a vertex attribute comes from a mesh file; a tree has none (paint an image \"file\", or use strokes with a \"direction\")");
    }
  } else {
    o.fail("type", "unknown object type \"" + type + "\"; allowed: sphere, plane, patch, mesh, tree");
  }
  if (auto v = o.get("displacement")) {
    if (d.type == ObjectType::Sphere || d.type == ObjectType::Plane)
      v->fail("displacement is supported on mesh, tree and patch objects (a flat square of bark: \"type\": \"patch\")");
    d.displacement = parse_displacement(c, v->object());
  }
  o.finish();
  if (d.type == ObjectType::Tree) {
    if (d.displacement.type == DisplacementDesc::Type::Image)
      d.tree.texture_displacement = d.displacement;
    else
      d.tree.displacement = d.displacement;
  }
  return d;
}

// Growth obstacles name other objects, which may come later in the file.
void resolve_growth_obstacles(SceneDesc& s) {
  for (size_t oi = 0; oi < s.objects.size(); ++oi) {
    ObjectDesc& o = s.objects[oi];
    if (!o.growth) continue;
    auto g = std::make_shared<GrowthDesc>(*o.growth);
    for (size_t k = 0; k < g->obstacle_names.size(); ++k) {
      const std::string& name = g->obstacle_names[k];
      const std::string where = g->where.path + "/obstacles/" + std::to_string(k);
      std::string names;
      long found = -1;
      for (size_t j = 0; j < s.objects.size(); ++j) {
        if (s.objects[j].name.empty()) continue;
        if (s.objects[j].name == name) found = long(j);
        names += (names.empty() ? "" : ", ") + s.objects[j].name;
      }
      if (found < 0)
        throw UserError(s.file, where,
                        "no object named \"" + name + "\" (named objects: " + (names.empty() ? "none" : names) + ")");
      const ObjectDesc& ob = s.objects[size_t(found)];
      if (size_t(found) == oi) throw UserError(s.file, where, "an object cannot be its own obstacle");
      if (ob.type != ObjectType::Mesh && ob.type != ObjectType::Sphere)
        throw UserError(s.file, where, "obstacle \"" + name + "\" must be a mesh or sphere object (a closed surface)");
      if (ob.growth) throw UserError(s.file, where, "obstacle \"" + name + "\" grows itself; obstacles do not grow");
      for (size_t prior : g->obstacles)
        if (prior == size_t(found)) throw UserError(s.file, where, "obstacle \"" + name + "\" is listed twice");
      g->obstacles.push_back(size_t(found));
    }
    o.growth = std::move(g);
  }
}

}  // namespace

SceneDesc parse_scene(const std::string& text, const std::string& file, const fs::path& base_dir) {
  const nlohmann::json j = parse_json_text(text, file);
  SceneDesc s;
  Ctx c{file, base_dir, &s.files};
  s.file = file;
  s.base_dir = base_dir;
  JsonObject root(j, file, "");
  if (auto v = root.get("camera")) s.camera = parse_camera(v->object());
  if (auto v = root.get("render")) s.render = parse_render(v->object());
  if (auto v = root.get("materials")) {
    JsonObject mats = v->object();
    for (auto it = v->raw().begin(); it != v->raw().end(); ++it) {
      auto mv = mats.at(it.key());
      s.materials.push_back(parse_material(c, it.key(), mv.object()));
    }
    mats.finish();
  }
  if (auto v = root.get("lights"))
    for (auto& e : v->array()) s.lights.push_back(parse_light(c, e.object()));
  if (auto v = root.get("objects"))
    for (auto& e : v->array()) s.objects.push_back(parse_object(c, e.object(), s));
  root.finish();
  resolve_growth_obstacles(s);
  // A sky without its own sun direction follows the scene's sun.
  for (auto& l : s.lights) {
    if (l.type != LightType::Sky) continue;
    for (const auto& sun : s.lights)
      if (sun.type == LightType::Sun) {
        if (!l.has_direction) l.direction = sun.direction;
        if (!l.sky_intensity) l.sky_intensity = sun.irradiance;
        l.has_direction = true;
        break;
      }
    if (!l.has_direction)
      throw UserError(file, l.where.path + "/sun_direction", "a sky needs a sun_direction or a sun light in the scene");
  }
  return s;
}

SceneDesc load_scene_file(const std::string& path) {
  // Only a regular file of at most kMaxSceneFileBytes is read: /dev/zero, a FIFO or a folder
  // would never end (or end in an allocation failure) otherwise. stat follows symbolic links.
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
    throw UserError(path, "open", std::string("cannot open scene file: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw UserError(path, "open", "is a folder, not a scene file");
  require_input_file(path, path, "open", "a scene");  // a FIFO, a device, a socket
  if (uint64_t(st.st_size) > kMaxSceneFileBytes)
    throw UserError(path, "size",
                    "the scene file is " + std::to_string(uint64_t(st.st_size)) + " bytes; at most " +
                        std::to_string(kMaxSceneFileBytes) + " (64 MiB) are read (meshes and images belong in their own files)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UserError(path, "open", std::string("cannot open scene file: ") + std::strerror(errno));
  // Read at most one byte past the limit: a file that grew since stat is refused too.
  std::string text(size_t(st.st_size), '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(size_t(in.gcount()));
  if (in.bad()) throw UserError(path, "read", "cannot read scene file");
  if (text.size() == size_t(st.st_size) && in.peek() != std::char_traits<char>::eof()) {
    std::string more(kMaxSceneFileBytes + 1 - text.size(), '\0');
    in.read(more.data(), std::streamsize(more.size()));
    text.append(more.data(), size_t(in.gcount()));
    if (text.size() > kMaxSceneFileBytes)
      throw UserError(path, "read",
                      "the scene file grew past " + std::to_string(kMaxSceneFileBytes) + " bytes while it was read");
  }
  fs::path base = fs::absolute(fs::path(path)).parent_path();
  return parse_scene(text, path, base);
}

SceneDesc default_scene() { return parse_scene(default_scene_text(), "<default scene>", fs::current_path()); }

}  // namespace phellem
