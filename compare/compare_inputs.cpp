#include "compare/compare_inputs.h"

#include <algorithm>
#include <cstdio>
#include <tbb/parallel_invoke.h>

#include "compare/common_scale.h"
#include "util/errors.h"

namespace phellem {

namespace {

std::string size_text(int w, int h) { return std::to_string(w) + "×" + std::to_string(h); }

const char* kind_name(HeightImage::Kind k) {
  switch (k) {
    case HeightImage::Kind::plain: return "a plain height image";
    case HeightImage::Kind::fracture_field: return "a FractureField";
    case HeightImage::Kind::render: return "a render";
    case HeightImage::Kind::patch: return "a fit patch";
  }
  return "an image";
}

}  // namespace

LoadedInput load_input(const CompareSource& source) { return load_input(source, read_height_image(source.path)); }

LoadedInput load_input(const CompareSource& source, HeightImage image) {
  LoadedInput in;
  in.source = source;
  in.image = std::move(image);
  if (source.px_per_cm) {
    in.px_per_cm_x = in.px_per_cm_y = *source.px_per_cm;
  } else if (in.image.px_per_cm_x > 0 && in.image.px_per_cm_y > 0) {
    in.px_per_cm_x = in.image.px_per_cm_x;
    in.px_per_cm_y = in.image.px_per_cm_y;
  } else {
    throw UserError(source.path, "--scale " + source.label,
                    std::string("is ") + kind_name(in.image.kind) + ", which states no physical scale: give --scale " +
                        source.label + "=PX_PER_CM (pixels per centimetre of bark)");
  }
  if (!source.albedo_path.empty()) {
    in.albedo = read_albedo_image(source.albedo_path);
    if (in.albedo->width != in.image.width || in.albedo->height != in.image.height)
      throw UserError(source.albedo_path, "--albedo " + source.label,
                      "the albedo is " + size_text(in.albedo->width, in.albedo->height) + " pixels but its height map " +
                          source.path + " is " + size_text(in.image.width, in.image.height) + ": they must cover the same pixels");
  }
  return in;
}

double common_scale(const LoadedInput& a, const LoadedInput& b) {
  return std::min({a.px_per_cm_x, a.px_per_cm_y, b.px_per_cm_x, b.px_per_cm_y});
}

PreparedInput at_scale(const LoadedInput& input, double px_per_cm) {
  PreparedInput p;
  p.source = input.source;
  p.source_px_per_cm_x = input.px_per_cm_x;
  p.source_px_per_cm_y = input.px_per_cm_y;
  HeightField own;
  own.width = input.image.width;
  own.height = input.image.height;
  own.z = input.image.z;
  p.field = resample(own, input.px_per_cm_x, input.px_per_cm_y, px_per_cm);
  if (input.albedo) {
    AlbedoField a;
    a.width = input.albedo->width;
    a.height = input.albedo->height;
    a.rgb = input.albedo->rgb;
    p.albedo = resample(a, p.field.width, p.field.height);
  }
  return p;
}

namespace {

// analyse_fissures, whose refusals of a shrunk input also say what it was before: the sizes they
// quote are at the common scale, not the file's.
FissureAnalysis analyse_prepared(const PreparedInput& p, const LoadedInput& in) {
  try {
    return analyse_fissures(p.field, p.albedo ? &*p.albedo : nullptr, p.source.path);
  } catch (const UserError& e) {
    if (p.field.width == in.image.width && p.field.height == in.image.height) throw;
    char scale[64];
    std::snprintf(scale, sizeof scale, "%.3g px/cm", std::max(in.px_per_cm_x, in.px_per_cm_y));
    throw UserError(e.file(), e.where(),
                    e.detail() + " (the file's " + size_text(in.image.width, in.image.height) + " px at " + scale +
                        " shrunk to the common scale, the coarser input's)");
  }
}

}  // namespace

CompareReport compare_inputs(const LoadedInput& a, const LoadedInput& b) {
  CompareReport r;
  r.px_per_cm = common_scale(a, b);
  r.a = at_scale(a, r.px_per_cm);
  r.b = at_scale(b, r.px_per_cm);
  tbb::parallel_invoke([&] { r.analysis_a = analyse_prepared(r.a, a); }, [&] { r.analysis_b = analyse_prepared(r.b, b); });
  r.comparison = compare_fissures(r.analysis_a.stats, r.analysis_b.stats);
  return r;
}

}  // namespace phellem
