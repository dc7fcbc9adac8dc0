#include "cli/slice.h"

#include <OpenImageIO/imageio.h>

#include "bark/growth/ring_section.h"
#include "cli/memory_check.h"
#include "cli/outputs.h"
#include "io/image_file.h"
#include "scene/growth_run.h"
#include "scene/mesh_source.h"
#include "scene/scene_parser.h"
#include "util/errors.h"
#include "util/output_set.h"

namespace phellem {

namespace {

size_t growth_object(const cli::Options& o, const SceneDesc& desc) {
  std::vector<size_t> growing;
  std::string names;
  for (size_t i = 0; i < desc.objects.size(); ++i)
    if (desc.objects[i].growth) {
      growing.push_back(i);
      names += (names.empty() ? "" : ", ") + (desc.objects[i].name.empty() ? "(unnamed)" : desc.objects[i].name);
    }
  if (growing.empty()) throw UserError(o.scene, "/objects", "no mesh object has a \"growth\" to slice");
  if (o.object.empty()) {
    if (growing.size() > 1) throw UserError("<command line>", "--object", "the scene grows several objects (" + names + "); name one");
    return growing.front();
  }
  for (size_t i : growing)
    if (desc.objects[i].name == o.object) return i;
  throw UserError("<command line>", "--object", "no growing object named \"" + o.object + "\" (growing: " + names + ")");
}

}  // namespace

int run_slice(const cli::Options& o) {
  OutputSet out;
  expect_outputs(o, out);
  const SceneDesc desc = load_scene_file(o.scene);
  expect_scene_inputs(desc, out);
  const size_t oi = growth_object(o, desc);
  const int width = o.width.value_or(kSliceDefaultSize), height = o.height.value_or(kSliceDefaultSize);
  check_scene_memory(o, desc, width, height);
  const GrowthRun run = run_growth_object(desc, oi, !o.quiet);
  bark::SectionPlane plane;
  if (o.plane_axis >= 0) {
    plane.axis = o.plane_axis;
    plane.value = o.plane_value;
  } else {
    double lo = 1e300, hi = -1e300;
    for (const auto& p : run.surface->positions) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
    plane.value = 0.5 * (lo + hi);
  }
  std::vector<bark::TriMesh> obstacles;
  for (size_t k : desc.objects[oi].growth->obstacles) {
    const ObjectDesc& ob = desc.objects[k];
    if (ob.type == ObjectType::Mesh) obstacles.push_back(object_trimesh(ob));
  }
  const bark::SectionImage img = bark::draw_ring_section(run.rings, obstacles, plane, width, height);
  if (img.segments == 0)
    throw UserError("<command line>", "--plane",
                    std::string("the plane ") + char('x' + plane.axis) + "=" + std::to_string(plane.value) +
                        " does not cut the grown surface");
  out.write("-o", o.exr, [&](const std::string& tmp) {
    OIIO::ImageSpec spec(img.width, img.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("ImageDescription", "phellem slice: growth rings, " + std::to_string(img.metres_per_pixel * 1000) + " mm per pixel");
    write_image_file(o.exr, tmp, spec, OIIO::TypeDesc::UINT8, img.rgb.data());
  });
  out.commit();
  if (!o.quiet)
    std::fprintf(stderr, "phellem: slice %c=%.4g m: %zu rings, %.3g mm per pixel -> %s\n", char('x' + plane.axis), plane.value,
                 run.rings.size(), img.metres_per_pixel * 1000, o.exr.c_str());
  return 0;
}

}  // namespace phellem
