#include "compare/compare_inputs.h"

#include <algorithm>
#include <cstdio>
#include <tbb/parallel_invoke.h>

#include "compare/common_scale.h"
#include "io/image_chroma.h"
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

LoadedInput load_input(const CompareSource& source, const RenderChoice& render) {
  return load_input(source, read_height_image(source.path), render);
}

LoadedInput load_input(const CompareSource& source, HeightImage image, const RenderChoice& render) {
  LoadedInput in;
  in.source = source;
  if (image.kind == HeightImage::Kind::plain && image.chroma > kColourPhotoChroma) {
    char measured[96];
    std::snprintf(measured, sizeof measured, "chroma %.3f, over the %.2f that grey height maps stay under", image.chroma,
                  kColourPhotoChroma);
    throw UserError(source.path, "",
                    std::string("is a colour photograph (") + measured +
                        "), not a height map: compare measures relief, white = high. Give the bark's height map "
                        "(a displacement scan) as input " + source.label + ", and this photo as its colour with --albedo " +
                        source.label + "=" + source.path + " (there is no --height option: the height map is the input itself)");
  }
  std::optional<SelectedRender> selected;
  if (image.render) {
    selected = select_render_pixels(image, render, source.path, source.label, source.px_per_cm);
    in.image = std::move(selected->image);
    in.render = selected->selection;
  } else {
    in.image = std::move(image);
  }
  if (source.px_per_cm) {
    in.px_per_cm_x = in.px_per_cm_y = *source.px_per_cm;
    in.scale_origin = ScaleOrigin::option;
  } else if (in.image.px_per_cm_x > 0 && in.image.px_per_cm_y > 0) {
    in.px_per_cm_x = in.image.px_per_cm_x;
    in.px_per_cm_y = in.image.px_per_cm_y;
    in.scale_origin = in.render ? ScaleOrigin::render_positions : ScaleOrigin::header;
  } else {
    throw UserError(source.path, "--scale " + source.label,
                    std::string("is ") + kind_name(in.image.kind) + ", which states no physical scale: give --scale " +
                        source.label + "=PX_PER_CM (pixels per centimetre of bark)");
  }
  if (!source.albedo_path.empty()) {
    in.albedo = read_albedo_image(source.albedo_path);
    // A render's albedo covers the whole render, and is cropped as its heights are.
    const int w = in.render ? in.render->render_width : in.image.width, h = in.render ? in.render->render_height : in.image.height;
    if (in.albedo->width != w || in.albedo->height != h)
      throw UserError(source.albedo_path, "--albedo " + source.label,
                      "the albedo is " + size_text(in.albedo->width, in.albedo->height) + " pixels but its height map " +
                          source.path + " is " + size_text(w, h) + ": they must cover the same pixels");
    if (in.render) {
      const PixelRect& q = in.render->rect;
      std::vector<float> crop;
      crop.reserve(size_t(q.area()) * 3);
      for (int y = q.y; y < q.y + q.height; ++y)
        for (int x = q.x; x < q.x + q.width; ++x)
          for (int c = 0; c < 3; ++c) crop.push_back(in.albedo->rgb[3 * (size_t(y) * size_t(w) + size_t(x)) + size_t(c)]);
      in.albedo->rgb = std::move(crop);
      in.albedo->width = q.width;
      in.albedo->height = q.height;
    }
  } else if (selected && selected->albedo) {
    in.albedo = std::move(selected->albedo);
    in.albedo_from_render = true;
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
  p.scale_origin = input.scale_origin;
  p.albedo_from_render = input.albedo_from_render;
  p.render = input.render;
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
