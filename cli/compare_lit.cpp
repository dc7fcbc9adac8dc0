#include "cli/compare_lit.h"

#include <cstdio>

#include "lookdev/lit_rig.h"
#include "scene/scene_parser.h"
#include "cli/outputs.h"
#include "compare/lit_report_html.h"
#include "compare/lit_report_json.h"
#include "compare/lit_score.h"
#include "util/errors.h"

namespace phellem {

namespace {

const char* kind_name(HeightImage::Kind k) {
  switch (k) {
    case HeightImage::Kind::plain: return "a height image";
    case HeightImage::Kind::fracture_field: return "a FractureField";
    case HeightImage::Kind::render: return "a render's displacement";
    case HeightImage::Kind::patch: return "a patch.exr";
  }
  return "";
}

// The side's heights in metres: a plain image's code values need --relief; the other kinds are
// metres already, which --relief multiplies.
LitSubject subject(const PreparedInput& in, HeightImage::Kind kind, const std::optional<double>& relief, std::string* note) {
  const std::string& label = in.source.label;
  if (kind == HeightImage::Kind::plain && !relief)
    throw UserError("", "--relief " + label,
                    label + " (" + printable(in.source.path) +
                        ") is a plain height image, whose values (0 to 1) state no physical height: give --relief " + label +
                        "=METRES, the height of its full range in metres (e.g. 0.02 for bark with fissures about 2 cm deep)");
  const double k = relief.value_or(1.0);
  LitSubject s;
  s.label = label;
  s.height = in.field;
  for (float& z : s.height.z) z = float(z * k);
  s.albedo = in.albedo;
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s, heights × %g m; %s.", kind_name(kind), k,
                in.albedo ? "its albedo" : "no albedo: a neutral grey 0.3");
  *note = buf;
  return s;
}

}  // namespace

int run_compare_lit(const LoadedInput& a, const LoadedInput& b, const LitOptions& lit, OutputSet& out, const std::string& html,
                    const std::string& json, bool quiet, int threads) {
  const double s = common_scale(a, b);
  const PreparedInput pa = at_scale(a, s), pb = at_scale(b, s);
  std::string note_a, note_b;
  const LitSubject sa = subject(pa, a.image.kind, lit.relief_a, &note_a);
  const LitSubject sb = subject(pb, b.image.kind, lit.relief_b, &note_b);
  LitRig rig;
  rig.spp = lit.spp;
  rig.sky = !lit.no_sky;
  if (!lit.lights.empty()) {
    out.expect_input("--lights", lit.lights);
    const SceneDesc scene = load_scene_file(lit.lights);
    for (const std::string& f : scene.files) out.expect_input("--lights", f);
    if (scene.lights.empty())
      throw UserError(lit.lights, "/lights", "the scene has no lights to light the comparison with (the rig's own: leave out --lights)");
    rig.lights = scene.lights;
    rig.facing = (scene.camera.position - scene.camera.look_at).normalized();
    rig.up = scene.camera.up;
  }
  auto render = [&](const LitSubject& side) {
    if (!quiet)
      std::fprintf(stderr, "phellem: compare --lit: rendering %s (%d×%d px at %.2f px/cm, %d spp)\n", side.label.c_str(),
                   side.height.width - 2 * kLitMargin, side.height.height - 2 * kLitMargin, s, rig.spp);
    return render_lit(side, rig, threads);
  };
  const LitRender ra = render(sa), rb = render(sb);
  const LitStatistics st_a = lit_statistics(ra.image, a.source.path), st_b = lit_statistics(rb.image, b.source.path);
  const LitComparison c = compare_lit(st_a, st_b);
  char rig_text[512];
  if (rig.lights.empty())
    std::snprintf(rig_text, sizeof rig_text,
                  "Light rig: a flat patch seen straight on; a 0.53° sun at %.0f° elevation raking across the fissures "
                  "(from the right)%s; %d samples per pixel.",
                  rig.sun_elevation_deg, rig.sky ? " and a Preetham sky" : ", no sky", rig.spp);
  else
    std::snprintf(rig_text, sizeof rig_text,
                  "Lights of %s: a flat patch facing that scene's camera, seen straight on, under the scene's %zu light(s); "
                  "%d samples per pixel.",
                  lit.lights.c_str(), rig.lights.size(), rig.spp);
  if (!html.empty()) {
    const LitReportSide ref{"A", a.source.path, note_a, &ra.image, &st_a}, cand{"B", b.source.path, note_b, &rb.image, &st_b};
    out.write_bytes("-o", html, lit_report_html(ref, cand, c, rig_text));
  }
  if (!json.empty()) {
    nlohmann::json j = lit_comparison_json(st_a, st_b, c);
    j["rig"] = {{"text", rig_text},          {"sun_elevation_deg", rig.sun_elevation_deg}, {"sky", rig.sky}, {"lights", lit.lights},
                {"spp", rig.spp},            {"px_per_cm", s},
                {"render_seconds", {ra.seconds, rb.seconds}}};
    j["inputs"] = {{"A", {{"path", a.source.path}, {"note", note_a}, {"width", ra.image.width}, {"height", ra.image.height}}},
                   {"B", {{"path", b.source.path}, {"note", note_b}, {"width", rb.image.width}, {"height", rb.image.height}}}};
    write_json_output(out, "--json", json, j);
  }
  out.commit();
  if (!quiet) {
    std::printf("phellem compare --lit: %s (score %.3f), at %.2f px/cm\n", c.verdict.c_str(), c.score, s);
    for (const std::string& w : c.words) std::printf("  %s\n", w.c_str());
    for (const LitGroupScore& g : c.groups) std::printf("  %-12s %.3f\n", g.group.c_str(), g.score);
  }
  return 0;
}

}  // namespace phellem
