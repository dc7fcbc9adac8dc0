#include "lookdev/lit_rig.h"

#include <OpenImageIO/imageio.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>

#include "io/image_file.h"
#include "renderer/integrator.h"
#include "renderer/render_scene.h"
#include "scene/displacement_map.h"
#include "util/cache_dir.h"
#include "util/errors.h"
#include "util/hash.h"

namespace phellem {

namespace {

// The camera stands far enough that the patch is seen almost orthographically: at a 2° field of
// view a ray at the picture's edge leans 1° from the normal, so a 3 cm relief shifts by 0.5 mm.
constexpr float kFovDeg = 2.0f;

// The albedo as a float EXR (linear, three channels) for the texture system, kept in the
// texture cache under a name made from its content: a given albedo is written and converted
// once, and runs that render it at the same time write the same bytes (util/cache_dir.h).
std::string albedo_texture(const AlbedoField& a, const std::string& label) {
  uint32_t h = hash_u32(uint32_t(a.width)) ^ hash_u32(uint32_t(a.height) * 7919u);
  for (float v : a.rgb) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    h = hash_combine(h, bits);
  }
  char name[64];
  std::snprintf(name, sizeof name, "lit-albedo-%08x-%dx%d.exr", h, a.width, a.height);
  OIIO::ImageSpec spec(a.width, a.height, 3, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  const std::vector<unsigned char> bytes = encode_image(name, spec, OIIO::TypeDesc::FLOAT, a.rgb.data());
  return cache_entry_with_bytes(name, bytes, {label, "albedo"});
}

// The albedo's one colour when every pixel has it (no texture needed).
std::optional<Color> uniform_colour(const AlbedoField& a) {
  for (size_t p = 3; p < a.rgb.size(); ++p)
    if (a.rgb[p] != a.rgb[p % 3]) return std::nullopt;
  return Color(a.rgb[0], a.rgb[1], a.rgb[2]);
}

SceneDesc rig_scene(const LitSubject& s, const LitRig& rig, const std::string& albedo_file, const Color& base_colour) {
  const HeightField& f = s.height;
  const double metres_per_px = 0.01 / f.px_per_cm;
  const int w = f.width - 2 * kLitMargin, h = f.height - 2 * kLitMargin;
  SceneDesc d;
  d.file = "<lit rig>";
  d.render.width = w;
  d.render.height = h;
  d.render.spp = rig.spp;
  d.render.max_depth = rig.max_depth;
  d.render.seed = rig.seed;
  d.render.filter.type = FilterType::Box;  // every sample inside its pixel: the picture is not blurred
  d.render.filter.radius = 0.5f;
  const float half_height = float(0.5 * h * metres_per_px);
  const float distance = half_height / std::tan(radians(kFovDeg) * 0.5f);
  const Vec3f n = rig.facing.normalized();
  const Vec3f up_hint = std::abs(rig.up.normalized().dot(n)) < 0.999f ? rig.up : Frame(n).t;  // a camera looking straight down
  const Vec3f up = (up_hint - up_hint.dot(n) * n).normalized(), right = up.cross(n);
  d.camera.position = n * distance;
  d.camera.look_at = Vec3f(0, 0, 0);
  d.camera.up = up;
  d.camera.fov_deg = kFovDeg;

  const double e = rig.sun_elevation_deg * M_PI / 180.0;
  LightDesc sun;
  sun.type = LightType::Sun;
  sun.direction = float(std::cos(e)) * right + float(std::sin(e)) * n;  // from the patch's right, across the fissures
  sun.has_direction = true;
  sun.irradiance = float(rig.sun_irradiance);
  sun.angle_deg = 0.53f;
  if (!rig.lights.empty()) {
    d.lights = rig.lights;
  } else {
    d.lights.push_back(sun);
  }
  if (rig.lights.empty() && rig.sky) {
    LightDesc sky;
    sky.type = LightType::Sky;
    sky.direction = sun.direction;
    sky.has_direction = true;
    sky.sky_intensity = float(rig.sun_irradiance);
    d.lights.push_back(sky);
  }

  MaterialDesc bark;
  bark.name = "bark";
  bark.type = MaterialType::Bark;
  bark.base_color = albedo_file.empty() ? base_colour : Color::Ones();
  if (!albedo_file.empty()) {
    bark.base_color_texture.file = albedo_file;
    bark.base_color_texture.srgb = false;
  }
  bark.roughness = 0.75f;
  bark.specular = 0.3f;
  d.materials.push_back(bark);

  // The heights about their mean, so the patch's middle plane is the camera's plane of focus.
  double mean = 0;
  for (float z : f.z) mean += z;
  mean /= double(f.z.size());
  auto map = std::make_shared<DisplacementMap>();
  map->width = f.width;
  map->height = f.height;
  map->value = f.z;
  ObjectDesc patch;
  patch.type = ObjectType::Patch;
  patch.name = "bark";
  patch.material = "bark";
  patch.where = {d.file, "/objects/0"};
  patch.point = Vec3f::Zero();
  patch.normal = n;
  patch.up = up;
  patch.size = Vec2f(float(f.width * metres_per_px), float(f.height * metres_per_px));
  patch.displacement.type = DisplacementDesc::Type::Image;
  patch.displacement.map = map;
  patch.displacement.scale = 1.0f;
  patch.displacement.midlevel = float(mean);
  patch.displacement.clamp = true;
  d.objects.push_back(patch);
  return d;
}

}  // namespace

LitRender render_lit(const LitSubject& s, const LitRig& rig, int threads) {
  const HeightField& f = s.height;
  if (f.width < 8 + 2 * kLitMargin || f.height < 8 + 2 * kLitMargin || !(f.px_per_cm > 0))
    throw UserError(s.label, "", "too small to light: " + std::to_string(f.width) + "×" + std::to_string(f.height) + " px");
  const auto t0 = std::chrono::steady_clock::now();
  std::string albedo_file;
  Color base_colour = Color::Constant(kLitDefaultAlbedo);
  if (s.albedo) {
    if (const std::optional<Color> one = uniform_colour(*s.albedo))
      base_colour = *one;
    else
      albedo_file = albedo_texture(*s.albedo, s.label);
  }
  const SceneDesc d = rig_scene(s, rig, albedo_file, base_colour);
  const auto scene = build_render_scene(d, BarkResults{}, d.camera, d.render.width, d.render.height);
  RenderSettings rs = render_settings(d.render);
  rs.threads = threads;
  RenderResult r = render_image(*scene, Camera(d.camera, d.render.width, d.render.height), d.render.width, d.render.height, rs);

  LitRender out;
  out.triangles = scene->stats().triangles;
  out.image.width = d.render.width;
  out.image.height = d.render.height;
  out.image.px_per_cm = f.px_per_cm;
  out.image.rgb.resize(size_t(out.image.width) * size_t(out.image.height) * 3);
  for (size_t p = 0; p < size_t(out.image.width) * size_t(out.image.height); ++p)
    for (int c = 0; c < 3; ++c) out.image.rgb[p * 3 + size_t(c)] = r.film.beauty[p * 4 + size_t(c)];
  out.film = std::move(r.film);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace phellem
