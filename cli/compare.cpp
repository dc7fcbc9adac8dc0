#include "cli/compare.h"

#include <OpenImageIO/imageio.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <set>

#include "cli/compare_lit.h"
#include "cli/outputs.h"
#include "compare/compare_inputs.h"
#include "compare/report_html.h"
#include "compare/report_json.h"
#include "compare/statistic_names.h"
#include "scene/memory_budget.h"
#include "util/errors.h"
#include "util/output_set.h"
#include "util/thread_probe.h"

namespace phellem {

namespace {

constexpr double kMaxPxPerCm = 10000;

[[noreturn]] void bad(const std::string& opt, const std::string& what) { throw UserError("", opt, what); }

struct CompareOptions {
  CompareSource a{"A", "", std::nullopt, ""}, b{"B", "", std::nullopt, ""};
  RenderChoice render_a, render_b;  // --object, --facing-deg
  RenderChoice& render(const CompareSource* s) { return s == &a ? render_a : render_b; }
  std::string html, json;
  std::optional<int> threads;
  std::string memory_limit;
  bool quiet = false;
  LitOptions lit;
};

// Peak memory of measuring one pixel at the common scale (the statistics' working images:
// high-pass, smoothed, tensor, mask, labels, skeleton, distances), measured: two 4096² fields
// measured side by side peaked at 3.39 GB RSS, 101 bytes a pixel each.
constexpr double kAnalysisBytesPerPixel = 110;

// Refuses the comparison before the statistics run when their working images would not fit.
// compare --lit renders each side, one after the other, at one pixel per pixel: the diced patch
// (about 2 triangles a pixel at 129 bytes each with the BVH, scene/memory_estimate.cpp), the film
// (72 bytes) and the lit statistics' working images (about 110 bytes) for the side being
// rendered, and the film and picture (84 bytes) of the side already done.
constexpr double kLitRenderBytesPerPixel = 2 * 129 + 72 + 110;
constexpr double kLitKeptBytesPerPixel = 84;

void check_compare_memory(const LoadedInput& a, const LoadedInput& b, const std::string& memory_limit, bool lit) {
  const double s = common_scale(a, b);
  MemoryMoment m;
  m.stage = lit ? "comparing under light" : "comparing";
  double kept = 0, largest_render = 0;
  const LoadedInput* largest = &a;
  for (const LoadedInput* in : {&a, &b}) {
    const double w = in->image.width * s / in->px_per_cm_x, h = in->image.height * s / in->px_per_cm_y;
    const double source = double(in->image.z.size()) * 4 + (in->albedo ? double(in->albedo->rgb.size()) * 4 : 0.0);
    m.items.push_back({"the statistics of " + in->source.label + " (" + std::to_string(long(w)) + "×" + std::to_string(long(h)) +
                           " px at " + std::to_string(s).substr(0, 5) + " px/cm) and its image",
                       w * h * kAnalysisBytesPerPixel * (in->albedo ? 1.1 : 1.0) + source, in->source.path,
                       "--scale " + in->source.label, "measure a smaller crop of the image"});
    kept += w * h * kLitKeptBytesPerPixel;
    if (w * h * kLitRenderBytesPerPixel > largest_render) largest_render = w * h * kLitRenderBytesPerPixel, largest = in;
  }
  if (lit)
    m.items.push_back({"rendering the larger side (" + largest->source.label + ") under the light rig, and both pictures",
                       largest_render + kept, largest->source.path, "--scale " + largest->source.label,
                       "light a smaller crop of the image"});
  MemoryEstimate e;
  e.moments.push_back(m);
  check_memory(e, memory_budget(memory_limit));
}

// "A=value" -> the input it names and the value.
std::pair<CompareSource*, std::string> labelled(CompareOptions& o, const std::string& opt, const std::string& v) {
  const auto eq = v.find('=');
  if (eq == std::string::npos) bad(opt, "expected A=VALUE or B=VALUE, got \"" + printable(v) + "\"");
  const std::string label = v.substr(0, eq), value = v.substr(eq + 1);
  CompareSource* s = label == "A" ? &o.a : label == "B" ? &o.b : nullptr;
  if (!s) bad(opt, "unknown input \"" + printable(label) + "\": the inputs are A (first) and B (second)");
  if (value.empty()) bad(opt, "the value for " + label + " is empty");
  return {s, value};
}

double scale_value(const std::string& opt, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0') bad(opt, "expected a number of pixels per centimetre, got \"" + printable(v) + "\"");
  if (!std::isfinite(x) || x <= 0 || x > kMaxPxPerCm)
    bad(opt, "pixels per centimetre must lie in (0, " + std::to_string(int(kMaxPxPerCm)) + "], got " + printable(v));
  return x;
}

// --object A=ID: a positive whole number.
int object_value(const std::string& opt, const std::string& v) {
  char* end = nullptr;
  const long id = std::strtol(v.c_str(), &end, 10);
  if (end == v.c_str() || *end != '\0' || id < 1 || id > (1L << 24))
    bad(opt, "expected an object id (a whole number from 1, as the render's object_id layer counts), got \"" + printable(v) + "\"");
  return int(id);
}

// --facing-deg A=DEG: (0, 180].
double facing_value(const std::string& opt, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0' || !std::isfinite(x) || x <= 0 || x > 180)
    bad(opt, "expected an angle in degrees in (0, 180] (180 keeps every pixel whatever way it faces), got \"" + printable(v) + "\"");
  return x;
}

CompareOptions parse(const std::vector<std::string>& args) {
  CompareOptions o;
  std::vector<std::string> files;
  std::set<std::string> given;  // options with a value (per input for --scale and --albedo)
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) bad(a, "missing value");
      const std::string& v = args[i + 1];
      const bool labelled = a == "--scale" || a == "--albedo" || a == "--object" || a == "--facing-deg" || a == "--relief";
      const std::string key = a == "--output" ? "-o" : labelled ? a + " " + v.substr(0, v.find('=')) : a;
      if (!given.insert(key).second) bad(key, "given twice; give each option once");
      if (args[i + 1].empty()) bad(a, "the value is empty");
      return args[++i];
    };
    if (a == "--scale") {
      auto [s, v] = labelled(o, a, value());
      s->px_per_cm = scale_value("--scale " + s->label, v);
    } else if (a == "--albedo") {
      auto [s, v] = labelled(o, a, value());
      s->albedo_path = v;
    } else if (a == "--object") {
      auto [s, v] = labelled(o, a, value());
      o.render(s).object_id = object_value("--object " + s->label, v);
    } else if (a == "--facing-deg") {
      auto [s, v] = labelled(o, a, value());
      o.render(s).facing_deg = facing_value("--facing-deg " + s->label, v);
    } else if (a == "--relief") {
      auto [s, v] = labelled(o, a, value());
      char* end = nullptr;
      const double x = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || !std::isfinite(x) || x <= 0 || x > kMaxRelief)
        bad(a + " " + s->label, "expected metres per unit of the heights in (0, " + std::to_string(int(kMaxRelief)) + "], got \"" +
                                    printable(v) + "\"");
      (s == &o.a ? o.lit.relief_a : o.lit.relief_b) = x;
    } else if (a == "--lit") {
      o.lit.on = true;
    } else if (a == "--no-sky") {
      o.lit.no_sky = true;
    } else if (a == "--lights") {
      o.lit.lights = value();
    } else if (a == "--spp") {
      const std::string v = value();
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (end == v.c_str() || *end != '\0' || n < 1 || n > kMaxLitSpp)
        bad(a, "must be an integer in [1, " + std::to_string(kMaxLitSpp) + "], got \"" + printable(v) + "\"");
      o.lit.spp = int(n);
    } else if (a == "-o" || a == "--output") {
      o.html = value();
    } else if (a == "--json") {
      o.json = value();
    } else if (a == "--threads") {
      const std::string v = value();
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (end == v.c_str() || *end != '\0' || n < 1 || n > 1024) bad(a, "must be an integer in [1, 1024], got \"" + printable(v) + "\"");
      o.threads = int(n);
    } else if (a == "--memory-limit") {
      o.memory_limit = value();
    } else if (a == "--quiet" || a == "-q") {
      o.quiet = true;
    } else if (a.size() > 1 && a[0] == '-') {
      bad(a, "unknown option for `compare`\n" + compare_usage());
    } else if (a.empty()) {
      bad(files.empty() ? "A" : "B", "the file name is empty");
    } else {
      files.push_back(a);
    }
  }
  if (!o.lit.on)
    for (const char* lit_only : {"--relief A", "--relief B", "--spp", "--lights"})
      if (given.count(lit_only)) bad(lit_only, "is an option of the lit comparison: add --lit");
  if (!o.lit.on && o.lit.no_sky) bad("--no-sky", "is an option of the lit comparison: add --lit");
  if (o.lit.no_sky && !o.lit.lights.empty()) bad("--no-sky", "takes the rig's sky away; with --lights the scene's lights are used as they are");
  if (files.size() != 2)
    bad("compare", "expected two inputs A and B, got " + std::to_string(files.size()) + "\n" + compare_usage());
  o.a.path = files[0];
  o.b.path = files[1];
  return o;
}

void print_summary(const CompareReport& r) {
  const Comparison& c = r.comparison;
  std::printf("phellem compare: %s (score %.3f; same bark <= %.2f), orientation distance %.1f deg, at %.2f px/cm\n",
              c.verdict.c_str(), c.score, kSameBarkScore, c.orientation_emd_deg, r.px_per_cm);
  std::printf("  %-22s %12s %12s %11s\n", "statistic", "A", "B", "difference");
  const auto sa = named_statistics(r.analysis_a.stats), sb = named_statistics(r.analysis_b.stats);
  for (size_t i = 0; i < sa.size() && i < sb.size(); ++i) {
    std::string diff;
    for (const StatisticDifference& d : c.core)
      if (d.name == sa[i].name) diff = std::to_string(d.difference).substr(0, 5);
    std::printf("  %-22s %12.4g %12.4g %11s\n", sa[i].name.c_str(), sa[i].value, sb[i].value, diff.c_str());
  }
}

}  // namespace

std::string compare_usage() {
  return "usage: phellem compare A B [--scale A=PX_PER_CM] [--scale B=PX_PER_CM] [--albedo A=FILE] [--albedo B=FILE]\n"
         "                      [--object A=ID] [--facing-deg A=DEG] (and B=)\n"
         "                      [-o REPORT.html] [--json OUT.json] [--threads N] [--memory-limit SIZE] [--quiet]\n"
         "                      [--lit [--relief A=METRES] [--relief B=METRES] [--spp N] [--no-sky | --lights SCENE.json]]\n"
         "  A and B: a height map (8/16-bit PNG, JPEG, TIFF, EXR; white = high; not a colour photo: give that\n"
         "  as --albedo), a FractureField EXR from `phellem simulate`, a render EXR (its displacement over the\n"
         "  largest rectangle of one object's pixels facing the camera within --facing-deg, default 30; the\n"
         "  object covering most pixels unless --object), or a patch.exr from `phellem fit`.\n"
         "  --scale is required for plain images (a render's comes from its positions); see docs/compare.md.\n"
         "  --lit renders both as flat patches under one light rig (a raking 0.53° sun at 30°, a sky) and compares\n"
         "  the pictures (A: the reference, B: the candidate); --relief gives a plain image's height range in metres;\n"
         "  --lights takes a scene's lights instead, the patch facing that scene's camera.\n";
}

int run_compare(const std::vector<std::string>& args) {
  const CompareOptions o = parse(args);
  std::unique_ptr<tbb::global_control> limit;
  if (o.threads) require_startable_threads("--threads", *o.threads);
  if (o.threads) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(*o.threads));
  OutputSet out;
  if (!o.html.empty()) out.expect_file("-o", o.html);
  if (!o.json.empty()) out.expect_file("--json", o.json);
  out.expect_input("A", o.a.path);
  out.expect_input("B", o.b.path);
  if (!o.a.albedo_path.empty()) out.expect_input("--albedo A", o.a.albedo_path);
  if (!o.b.albedo_path.empty()) out.expect_input("--albedo B", o.b.albedo_path);
  const LoadedInput a = load_input(o.a, o.render_a);
  const LoadedInput b = load_input(o.b, o.render_b);
  check_compare_memory(a, b, o.memory_limit, o.lit.on);
  if (o.lit.on) return run_compare_lit(a, b, o.lit, out, o.html, o.json, o.quiet, o.threads.value_or(0));
  const CompareReport report = compare_inputs(a, b);
  if (!o.html.empty())
    out.write_bytes("-o", o.html, report_html(report));
  if (!o.json.empty()) write_json_output(out, "--json", o.json, report_json(report));
  out.commit();
  if (!o.quiet) print_summary(report);
  return 0;
}

}  // namespace phellem
