#include "cli/options.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <set>

#include "preview/edge_length.h"
#include "scene/memory_budget.h"
#include "util/errors.h"

namespace phellem::cli {

namespace {

[[noreturn]] void bad(const std::string& opt, const std::string& what) { throw UserError("", opt, what); }

long long integer(const std::string& opt, const std::string& v, long long lo, long long hi) {
  long long x = 0;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (ec != std::errc() || p != v.data() + v.size()) bad(opt, "expected an integer, got \"" + v + "\"");
  if (x < lo || x > hi) bad(opt, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + v);
  return x;
}

// A seed: any unsigned 64-bit integer, in decimal, read exactly (as in the scene).
uint64_t seed(const std::string& opt, const std::string& v) {
  uint64_t x = 0;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || ec != std::errc() || p != v.data() + v.size())
    bad(opt, "must be an integer in [0, 18446744073709551615], got \"" + v + "\"");
  return x;
}

// An angle in degrees: a finite number in [-kMaxDegrees, kMaxDegrees]. NaN and infinities
// would reach the camera, and from it Embree's ray validity assertion.
constexpr double kMaxDegrees = 1e6;
float degrees(const std::string& opt, const std::string& v) {
  const std::string range = "must be a number in [-1000000, 1000000]";
  double x = 0;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || p != v.data() + v.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
    bad(opt, range + ", got \"" + v + "\"");
  if (ec == std::errc::result_out_of_range || !std::isfinite(x) || std::abs(x) > kMaxDegrees) bad(opt, range + ", got " + v);
  return float(x);
}

// A positive finite number at most `hi`.
double positive(const std::string& opt, const std::string& v, double hi, const std::string& what) {
  const std::string range = "must be " + what + ", a number in (0, " + std::to_string(int64_t(hi)) + "]";
  double x = 0;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || p != v.data() + v.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
    bad(opt, range + ", got \"" + v + "\"");
  if (ec == std::errc::result_out_of_range || !std::isfinite(x) || !(x > 0) || x > hi) bad(opt, range + ", got " + v);
  return x;
}

// A finite number in [-hi, hi].
double finite_number(const std::string& opt, const std::string& v, double hi, const std::string& what) {
  const std::string range = "must be " + what + ", a number in [-" + std::to_string(int64_t(hi)) + ", " + std::to_string(int64_t(hi)) + "]";
  double x = 0;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || p != v.data() + v.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
    bad(opt, range + ", got \"" + v + "\"");
  if (ec == std::errc::result_out_of_range || !std::isfinite(x) || std::abs(x) > hi) bad(opt, range + ", got " + v);
  return x;
}

// A duration: a positive number of seconds, or of minutes, hours or days with the suffix m, h
// or d (90m, 6h, 2d), at most a year.
double duration(const std::string& opt, const std::string& v) {
  const std::string range = "must be a duration such as 3600, 90m, 6h or 2d (at most 365d)";
  std::string digits = v;
  double unit = 1;
  if (!v.empty() && (v.back() == 's' || v.back() == 'm' || v.back() == 'h' || v.back() == 'd')) {
    unit = v.back() == 'm' ? 60 : v.back() == 'h' ? 3600 : v.back() == 'd' ? 86400 : 1;
    digits.pop_back();
  }
  double x = 0;
  auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), x);
  if (digits.empty() || p != digits.data() + digits.size() || ec != std::errc() || !std::isfinite(x) || !(x > 0) ||
      x * unit > 365 * 86400.0)
    bad(opt, range + ", got \"" + v + "\"");
  return x * unit;
}

// Output names are checked before any work: a wrong extension found only when the file is
// written would cost the whole render.
void need_extension(const std::string& opt, const std::string& file, const std::string& ext) {
  std::string tail = file.size() >= ext.size() ? file.substr(file.size() - ext.size()) : std::string();
  for (char& c : tail) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (tail != ext) bad(opt, "expected a " + ext + " file name, got \"" + file + "\"");
}

}  // namespace

std::string usage() {
  return "usage:\n"
         "  phellem render [SCENE.json] [-o OUT.exr] [--png OUT.png] [--spp N] [--res WxH] [--threads N]\n"
         "                 [--seed S] [--stats STATS.json] [--view NAME] [--quiet]\n"
         "  phellem turntable SCENE.json --frames N -o DIR/frame_%04d.exr [--png] [--mp4 OUT.mp4]\n"
         "                 [--degrees D] [--spp N] [--res WxH] [--threads N] [--seed S] [--view NAME] [--quiet]\n"
         "  phellem growth SCENE.json --frames N -o DIR/frame_%04d.exr [--png] [--mp4 OUT.mp4]\n"
         "                 [--spp N] [--res WxH] [--threads N] [--seed S] [--view NAME] [--quiet]\n"
         "  phellem simulate SCENE.json -o DIR [--res WxH] [--seed S] [--stats STATS.json] [--no-mesh] [--threads N] [--quiet]\n"
         "  phellem compare A B [--scale A=PX_PER_CM] [--scale B=PX_PER_CM] [--albedo A=FILE] [-o REPORT.html]\n"
         "                 [--json OUT.json] [--threads N] [--memory-limit SIZE] [--quiet]\n"
         "                 [--lit [--relief A=METRES] [--spp N] [--no-sky]] (docs/compare.md)\n"
         "  phellem fit HEIGHT_IMAGE --scale PX_PER_CM --model strips|stress -o DIR [--albedo IMAGE]\n"
         "                 [--objective height|lit|both [--relief METRES]] [--time-budget S] [--max-evals N]\n"
         "                 [--seed S] [--threads N] [--quiet]\n"
         "  phellem slice SCENE.json -o SECTION.png [--object NAME] [--plane x|y|z=VALUE] [--res WxH] [--quiet]\n"
         "  phellem preview [SCENE.json] [--snapshot OUT.png [-o AOVS.exr]] [--res WxH] [--max-level N]\n"
         "                 [--edge-px P] [--frames N] [--quiet]\n"
         "  render, turntable, growth, simulate, slice and fit also take [--memory-limit SIZE] (default: PHELLEM_MEMORY_LIMIT, else 75% of\n"
         "  physical memory; never above the address space `ulimit -v` leaves), and all but fit [--memory-estimate] (print the\n"
         "  memory each stage needs, and stop).\n"
         "  They and preview print how long each cambial growth will take, and refuse growth estimated to\n"
         "  take longer than [--time-limit DURATION] (default 1h; e.g. 90m, 12h, 2d).\n"
         "  phellem --help | --version\n"
         "Ranges: --spp N in [1, 1048576] (render.spp), --seed S in [0, 18446744073709551615]\n"
         "(render.seed), --res WxH each in [1, 32768], --threads N in [1, 1024], --frames N in\n"
         "[1, 100000], --degrees D in [-1000000, 1000000] (default 360), --edge-px P in [0.5, 1000]\n"
         "(default 6 in the window, 2 in a snapshot). render.max_depth, only in the scene, lies in\n"
         "[1, 1024].\n"
         "Without SCENE.json, `render` renders the embedded default scene. See README.md and\n"
         "docs/scene-format.md.\n";
}

Options parse(const std::vector<std::string>& args) {
  Options o;
  if (args.empty()) bad("command", "no command given\n" + usage());
  o.command = args[0];
  if (o.command != "render" && o.command != "turntable" && o.command != "growth" && o.command != "simulate" &&
      o.command != "fit" && o.command != "preview" && o.command != "slice")
    bad(o.command, "unknown command; allowed: render, turntable, growth, simulate, slice, compare, fit, preview\n" + usage());
  const bool fit = o.command == "fit";
  const bool frames = o.command == "turntable" || o.command == "growth";
  std::set<std::string> given;  // options with a value: a second one would silently win
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (!given.insert(a == "--output" ? "-o" : a).second) bad(a, "given twice; give each option once");
      if (i + 1 >= args.size()) bad(a, "missing value");
      // An empty value is a mistake (an unset shell variable), not "option not given".
      if (args[i + 1].empty()) bad(a, "the value is empty");
      return args[++i];
    };
    if (a == "-o" || a == "--output")
      o.exr = value();
    else if (a == "--snapshot" && o.command == "preview")
      o.png = value();
    else if (a == "--max-level" && o.command == "preview")
      o.max_level = int(integer(a, value(), 1, 64));
    else if (a == "--edge-px" && o.command == "preview") {
      const std::string v = value();
      o.edge_px = positive(a, v, preview::kMaxEdgePx, "the micro-edge length near cracks in pixels");
      if (*o.edge_px < preview::kMinEdgePx)
        bad(a, "must be at least 0.5 (pixels; at most 1000): shorter micro-edges show nothing more at one sample a pixel, "
               "and cost 1/P² the triangles, got " + v);
    }
    else if (a == "--frames" && o.command == "preview")
      o.frames = int(integer(a, value(), 1, 100000));
    else if (a == "--object" && o.command == "slice")
      o.object = value();
    else if (a == "--plane" && o.command == "slice") {
      const std::string v = value();
      const auto eq = v.find('=');
      if (v.size() < 3 || eq != 1 || (v[0] != 'x' && v[0] != 'y' && v[0] != 'z'))
        bad(a, "expected AXIS=VALUE with AXIS x, y or z and VALUE in metres, e.g. y=0.3; got \"" + v + "\"");
      o.plane_axis = v[0] - 'x';
      o.plane_value = finite_number(a, v.substr(2), 1e6, "a coordinate in metres");
    } else if (a == "--png" && o.command != "preview" && o.command != "slice") {
      if (frames)
        o.png_frames = true;
      else
        o.png = value();
    } else if (a == "--mp4" && frames)
      o.mp4 = value();
    else if (a == "--stats")
      o.stats = value();
    else if (a == "--spp")
      o.spp = int(integer(a, value(), 1, 1 << 20));
    else if (a == "--threads")
      o.threads = int(integer(a, value(), 1, 1024));
    else if (a == "--frames" && frames)
      o.frames = int(integer(a, value(), 1, 100000));
    else if (a == "--seed")
      o.seed = seed(a, value());
    else if (a == "--degrees" && o.command == "turntable")
      o.degrees = degrees(a, value());
    else if (a == "--res") {
      const std::string v = value();
      const auto x = v.find('x');
      if (x == std::string::npos) bad(a, "expected WxH, e.g. 1920x1080, got \"" + v + "\"");
      o.width = int(integer(a, v.substr(0, x), 1, 32768));
      o.height = int(integer(a, v.substr(x + 1), 1, 32768));
    } else if (a == "--view")
      o.view = value();
    else if (a == "--quiet" || a == "-q")
      o.quiet = true;
    else if (a == "--no-mesh" && o.command == "simulate")
      o.no_mesh = true;
    else if (a == "--memory-limit") {
      o.memory_limit = value();
      try {
        parse_memory_size(o.memory_limit);
      } catch (const std::invalid_argument&) {
        bad(a, "expected a memory size such as 6G, 512M, 1.5T or 50% (of physical memory), got \"" + o.memory_limit + "\"");
      }
    } else if (a == "--time-limit" && !fit)
      o.time_limit = duration(a, value());
    else if (a == "--scale" && fit)
      o.scale = positive(a, value(), 10000, "the photo's scale in pixels per cm");
    else if (a == "--albedo" && fit)
      o.albedo = value();
    else if (a == "--model" && fit) {
      o.model = value();
      if (o.model != "strips" && o.model != "stress") bad(a, "unknown model \"" + o.model + "\"; allowed: strips, stress");
    } else if (a == "--objective" && fit) {
      o.objective = value();
      if (o.objective != "height" && o.objective != "lit" && o.objective != "both")
        bad(a, "unknown objective \"" + printable(o.objective) + "\"; allowed: height, lit, both");
    } else if (a == "--relief" && fit)
      o.relief = positive(a, value(), 10, "the photo's full height range in metres");
    else if (a == "--time-budget" && fit)
      o.time_budget = positive(a, value(), 1e6, "a time in seconds");
    else if (a == "--max-evals" && fit)
      o.max_evals = integer(a, value(), 1, 1000000000);
    else if (a == "--memory-estimate")
      o.memory_estimate = true;
    else if (!a.empty() && a[0] == '-')
      bad(a, "unknown option for `" + o.command + "`\n" + usage());
    else if (a.empty())
      bad(fit ? "HEIGHT_IMAGE" : "SCENE", fit ? "the image file name is empty" : "the scene file name is empty");
    else if (o.scene.empty())
      o.scene = a;
    else
      bad(a, fit ? "more than one height image given" : "more than one scene file given");
  }
  if (o.command == "simulate") {
    if (o.scene.empty()) bad("simulate", "a scene file is required");
    if (o.exr.empty()) bad("-o", "required for simulate: the output folder");
    if (o.spp || !o.png.empty()) bad(o.spp ? "--spp" : "--png", "not an option of simulate");
  }
  if (fit) {
    if (o.scene.empty()) bad("fit", "a height image is required");
    if (o.exr.empty()) bad("-o", "required for fit: the output folder");
    if (o.model.empty()) bad("--model", "required for fit: strips or stress");
    if (o.objective != "height" && !o.relief)
      bad("--relief", "required with --objective " + o.objective +
                          ": the photo's full height range in metres (e.g. 0.02), so that its relief can be lit");
    if (o.objective == "height" && o.relief) bad("--relief", "only with --objective lit or both (the height objective needs no relief)");
    if (o.spp || !o.png.empty() || !o.stats.empty() || o.width || o.memory_estimate)
      bad(o.spp ? "--spp" : !o.png.empty() ? "--png" : !o.stats.empty() ? "--stats" : o.width ? "--res" : "--memory-estimate",
          "not an option of fit");
  }
  if (o.command == "preview") {
    if (o.spp || o.seed || o.threads || !o.stats.empty() || !o.view.empty() || o.memory_estimate)
      bad(o.spp ? "--spp" : o.seed ? "--seed" : o.threads ? "--threads" : !o.stats.empty() ? "--stats" : !o.view.empty() ? "--view" : "--memory-estimate",
          "not an option of preview");
    if (!o.exr.empty() && o.png.empty()) bad("-o", "only with --snapshot: the AOVs of the snapshot");
    if (!o.exr.empty()) need_extension("-o", o.exr, ".exr");
    if (!o.png.empty()) need_extension("--snapshot", o.png, ".png");
  }
  if (o.command == "slice") {
    if (o.scene.empty()) bad("slice", "a scene file is required");
    if (o.exr.empty()) bad("-o", "required for slice: the section image (.png)");
    need_extension("-o", o.exr, ".png");
    if (o.spp || !o.stats.empty() || !o.view.empty())
      bad(o.spp ? "--spp" : !o.stats.empty() ? "--stats" : "--view", "not an option of slice");
  }
  if (o.command == "render") {
    if (!o.exr.empty()) need_extension("-o", o.exr, ".exr");
    if (!o.png.empty()) need_extension("--png", o.png, ".png");
  }
  if (frames) {
    if (o.scene.empty()) bad(o.command, "a scene file is required");
    if (!o.frames) bad("--frames", "required for " + o.command);
    if (o.exr.empty()) bad("-o", "required for " + o.command + ": a pattern such as out/frame_%04d.exr");
    if (o.exr.find('%') == std::string::npos) bad("-o", "the output pattern needs a frame number field such as %04d");
    need_extension("-o", o.exr, ".exr");
    if (!o.mp4.empty()) need_extension("--mp4", o.mp4, ".mp4");
  }
  return o;
}

}  // namespace phellem::cli
