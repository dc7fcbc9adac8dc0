// `phellem compare` as a user runs it: scores on synthetic bark with known answers, the JSON
// figures, and every documented error (exit 2, `phellem: error:`).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "tests/support/height_fields.h"
#include "tests/support/synthetic_render.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

// Fissured bark 60×60 cm at 10 px/cm (A) and the same bark at 5 px/cm (B), written once.
struct Inputs {
  std::string dir, a, b, noise, tiny;
};
const Inputs& inputs() {
  static const Inputs in = [] {
    Inputs i;
    i.dir = test::temp_dir("compare_cli");
    i.a = i.dir + "/bark_10.png";
    i.b = i.dir + "/bark_5.png";
    i.noise = i.dir + "/noise_10.png";
    i.tiny = i.dir + "/tiny.png";
    test::write_height_png16(i.a, test::fissured_bark(60, 60, 10, 5));
    test::write_height_png16(i.b, test::fissured_bark(60, 60, 5, 5));
    test::write_height_png16(i.noise, test::smooth_noise(60, 60, 10, 1.5, 9));
    test::write_height_png16(i.tiny, test::fissured_bark(10, 10, 10, 5));
    return i;
  }();
  return in;
}

nlohmann::json run_json(const std::string& args, const std::string& name) {
  const std::string json = inputs().dir + "/" + name + ".json";
  const auto r = test::run_phellem("compare " + args + " --json " + json + " --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return nlohmann::json::parse(test::read_text(json), nullptr, false);
}

TEST(CompareCli, TheSameBarkAtTwoScalesIsTheSameBark) {
  const auto& in = inputs();
  const auto j = run_json(in.a + " " + in.b + " --scale A=10 --scale B=5", "two_scales");
  ASSERT_TRUE(j.is_object());
  EXPECT_LE(j["score"].get<double>(), 0.08);
  EXPECT_EQ(j["verdict"], "same bark");
  EXPECT_NEAR(j["px_per_cm"].get<double>(), 5.0, 0.01);
  // Declaring the wrong scale makes the same bark look different: the scale matters.
  const auto wrong = run_json(in.a + " " + in.b + " --scale A=10 --scale B=10", "wrong_scale");
  EXPECT_GE(wrong["score"].get<double>(), 0.15);
}

TEST(CompareCli, FissuresAgainstNoiseAreDifferent) {
  const auto& in = inputs();
  const auto j = run_json(in.a + " " + in.noise + " --scale A=10 --scale B=10", "unrelated");
  EXPECT_GE(j["score"].get<double>(), 0.4);
  EXPECT_GE(j["orientation_emd_deg"].get<double>(), 20.0);
  EXPECT_EQ(j["verdict"], "different");
}

TEST(CompareCli, JsonNamesEveryStatisticOfBothInputs) {
  const auto& in = inputs();
  const auto j = run_json(in.a + " " + in.b + " --scale A=10 --scale B=5", "keys");
  for (const char* key : {"score", "orientation_emd_deg", "verdict", "differences", "parameters", "px_per_cm"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* input : {"A", "B"}) {
    const auto& s = j["inputs"][input]["statistics"];
    for (const char* name : {"fissure_fraction", "vertical_fraction", "orientation_mean_deg", "spacing_h_mean", "spacing_h_std",
                             "spacing_v_mean", "spacing_v_std", "width_mean", "width_std", "length_median", "depth_ratio"})
      EXPECT_TRUE(s.contains(name) && s[name].is_number()) << input << " " << name;
    EXPECT_EQ(j["inputs"][input]["orientation_histogram"].size(), 18u);
  }
  EXPECT_EQ(j["inputs"]["A"]["file"], in.a);
  EXPECT_EQ(j["differences"].size(), 7u);
}

TEST(CompareCli, PrintsTheVerdictAndScore) {
  const auto& in = inputs();
  const auto r = test::run_command(std::string(PHELLEM_BINARY) + " compare " + in.a + " " + in.b + " --scale A=10 --scale B=5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("phellem compare: same bark (score 0."), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("spacing_h_mean"), std::string::npos) << r.output;
}

struct BadCase {
  const char* name;
  std::string args;
  std::string expect;  // in the error message
};

TEST(CompareCli, EveryMistakeIsAClearErrorWithExitCode2) {
  const auto& in = inputs();
  const std::string ab = in.a + " " + in.b + " ";
  const std::string garbage = in.dir + "/garbage.png";
  test::write_text(garbage, "this is not a PNG file at all");
  const std::vector<BadCase> cases = {
      {"missing input", in.a + " " + in.dir + "/missing.png --scale A=10 --scale B=10", "missing.png"},
      {"unreadable input", in.a + " " + garbage + " --scale A=10 --scale B=10", "garbage.png"},
      {"zero scale", ab + "--scale A=0 --scale B=5", "--scale A: pixels per centimetre must lie in (0, 10000]"},
      {"negative scale", ab + "--scale A=-3 --scale B=5", "must lie in (0, 10000]"},
      {"nan scale", ab + "--scale A=nan --scale B=5", "must lie in (0, 10000]"},
      {"infinite scale", ab + "--scale A=inf --scale B=5", "must lie in (0, 10000]"},
      {"huge scale", ab + "--scale A=1e300 --scale B=5", "must lie in (0, 10000]"},
      {"text scale", ab + "--scale A=ten --scale B=5", "expected a number"},
      {"unknown input", ab + "--scale C=10", "unknown input \"C\""},
      {"no label", ab + "--scale 10", "expected A=VALUE or B=VALUE"},
      {"no scale", ab + "--scale A=10", "give --scale B=PX_PER_CM"},
      {"too small", in.a + " " + in.tiny + " --scale A=10 --scale B=10", "tiny.png"},
      {"one input", in.a + " --scale A=10", "expected two inputs"},
      {"unknown option", ab + "--scael A=10", "unknown option"},
      {"albedo size", ab + "--scale A=10 --scale B=5 --albedo A=" + in.b, "must cover the same pixels"},
      {"memory", ab + "--scale A=10 --scale B=5 --memory-limit 1M", "--memory-limit"},
      {"unwritable report", ab + "--scale A=10 --scale B=5 -o " + in.dir + "/no/such/dir/r.html", "r.html"},
  };
  for (const BadCase& c : cases) {
    const auto r = test::run_phellem_limited("compare " + c.args, 4096, 120);
    EXPECT_EQ(r.exit_code, 2) << c.name << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: ", 0), 0u) << c.name << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.name << ": wanted \"" << c.expect << "\"\n" << r.output;
  }
}

// Any ratio of the two scales is allowed (docs/compare.md, "Common scale"): the finer input is
// shrunk to the coarser scale and only the checks at that scale refuse. The shrunk size was
// rounded to the nearest pixel, so an input at 4.1 px/cm against one at 2 (the lowest scale
// allowed) was measured at 1.999 px/cm and refused as "the scale is 2 px/cm; compare needs at
// least 2 px/cm". Rounded up, the boundaries are where the documentation puts them.
TEST(CompareCli, AnyScaleRatioIsAllowedAndTheCommonScaleIsMeasuredAsDeclared) {
  const std::string dir = test::temp_dir("compare_ratio");
  const std::string wide = dir + "/wide.png", small = dir + "/small.png";
  test::write_height_png16(wide, test::fissured_bark(1001 / 4.1, 1001 / 4.1, 4.1, 5));  // 1001² px
  test::write_height_png16(small, test::fissured_bark(25.6, 25.6, 10, 5));              // 256² px
  auto compare = [](const std::string& a, const std::string& b, const std::string& scales) {
    return test::run_phellem_limited("compare " + a + " " + b + " " + scales, 4096, 120);
  };
  // The common scale at the 2 px/cm minimum: accepted, from a ratio of 2.05 or of 1.05.
  for (const char* scales : {"--scale A=4.1 --scale B=2", "--scale A=2.1 --scale B=2"}) {
    const auto r = compare(wide, wide, scales);
    EXPECT_EQ(r.exit_code, 0) << scales << "\n" << r.output;
  }
  // Just below it: refused, with the minimum.
  const auto coarse = compare(wide, wide, "--scale A=4.1 --scale B=1.99");
  EXPECT_EQ(coarse.exit_code, 2) << coarse.output;
  EXPECT_NE(coarse.output.find("compare needs at least 2 px/cm to see the fissures"), std::string::npos) << coarse.output;
  // A 256 px side at 10 px/cm halved keeps 128 px: accepted; at 4.96 px/cm it keeps 127: refused,
  // saying what the file was before it was shrunk.
  const auto halved = compare(small, small, "--scale A=10 --scale B=5");
  EXPECT_EQ(halved.exit_code, 0) << halved.output;
  const auto under = compare(small, small, "--scale A=10 --scale B=4.96");
  EXPECT_EQ(under.exit_code, 2) << under.output;
  EXPECT_NE(under.output.find("the image is 127×127 px"), std::string::npos) << under.output;
  EXPECT_NE(under.output.find("compare needs at least 128 px and 20 cm on each side (the file's 256×256 px at 10 px/cm shrunk "
                              "to the common scale, the coarser input's)"),
            std::string::npos)
      << under.output;
}

TEST(CompareCli, AFailedRunLeavesTheEarlierReportUntouched) {
  const auto& in = inputs();
  const std::string report = in.dir + "/kept.html", json = in.dir + "/kept.json";
  test::write_text(report, "earlier report");
  test::write_text(json, "{}");
  const auto r = test::run_phellem("compare " + in.a + " " + in.dir + "/missing.png --scale A=10 --scale B=10 -o " + report +
                                   " --json " + json + " --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(test::read_text(report), "earlier report");
  EXPECT_EQ(test::read_text(json), "{}");
  EXPECT_TRUE(test::leftover_temporaries(in.dir).empty());
}

// A render of `bark` (heights in its displacement layer, 1 mm apart in position: 10 px/cm) in a
// frame `margin` px wide of background, with a second object's strip on the right and a
// camera 2 m in front.
std::string write_render(const std::string& path, const test::Heights& bark, int margin) {
  test::SyntheticRender r(bark.width + 2 * margin + 20, bark.height + 2 * margin);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const size_t p = r.at(x, y);
      const int bx = x - margin, by = y - margin;
      const bool on_bark = bx >= 0 && by >= 0 && bx < bark.width && by < bark.height;
      const bool other = x >= r.width - 15;
      r.alpha[p] = on_bark || other ? 1.0f : 0.0f;
      r.object_id[p] = on_bark ? 1.0f : other ? 2.0f : 0.0f;
      r.set_position(x, y, 0.001f * float(x), -0.001f * float(y), 0);
      if (on_bark) r.displacement[p] = 0.01f * bark.z[size_t(by) * size_t(bark.width) + size_t(bx)];
    }
  r.camera_position = std::array<float, 3>{0.001f * float(r.width) / 2, -0.001f * float(r.height) / 2, 2.0f};
  test::write_synthetic_render(path, r);
  return path;
}

// A render with background is measured over its bark: the JSON says which pixels and scale.
TEST(CompareCli, ARenderIsMeasuredOverItsLargestRectangleOfBark) {
  const auto& in = inputs();
  const auto bark = test::fissured_bark(25, 22, 10, 5);  // 250×220 px
  const std::string exr = write_render(in.dir + "/render.exr", bark, 12);
  test::write_height_png16(in.dir + "/render_bark.png", bark);
  const auto j = run_json(exr + " " + in.dir + "/render_bark.png --scale B=10", "render");
  ASSERT_TRUE(j.is_object());
  const auto& a = j["inputs"]["A"];
  EXPECT_EQ(a["render"]["rect"], nlohmann::json({{"x", 12}, {"y", 12}, {"w", 250}, {"h", 220}})) << a.dump();
  EXPECT_EQ(a["render"]["object_id"], 1);
  EXPECT_EQ(a["render"]["object_from"], "most pixels");
  EXPECT_EQ(a["render"]["mask_pixels"], 250 * 220);
  EXPECT_EQ(a["render"]["facing_deg"], 30.0);
  EXPECT_EQ(a["source_px_per_cm_from"], "position layer");
  EXPECT_NEAR(a["source_px_per_cm"][0].get<double>(), 10.0, 1e-3);
  EXPECT_NEAR(a["source_px_per_cm"][1].get<double>(), 10.0, 1e-3);
  EXPECT_EQ(a["albedo"], "albedo layer");
  EXPECT_EQ(a["size_px"], nlohmann::json({250, 220}));
  EXPECT_LE(j["score"].get<double>(), 0.02);  // the same heights
  EXPECT_EQ(j["inputs"]["B"]["source_px_per_cm_from"], "--scale");
  // The HTML says it too.
  const std::string html = in.dir + "/render.html";
  const auto r = test::run_phellem("compare " + exr + " " + in.dir + "/render_bark.png --scale B=10 -o " + html + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string page = test::read_text(html);
  EXPECT_NE(page.find("measured: the rectangle x 12, y 12, 250×220 px, the largest of the 55000 pixels fully covered by object 1"),
            std::string::npos);
  EXPECT_NE(page.find("from the position layer"), std::string::npos);
  // The other object, chosen: 15 px wide, refused naming the rectangle and what to do.
  const auto other = test::run_phellem("compare " + exr + " " + in.dir + "/render_bark.png --scale B=10 --object A=2");
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_EQ(other.output.rfind("phellem: error: " + exr + ": render: the largest rectangle of bark pixels (fully covered by "
                               "object 2, facing the camera within 30°) is 15×244 px at (279, 0)", 0),
            0u)
      << other.output;
  EXPECT_NE(other.output.find("compare needs at least 128 px and 20 cm on each side"), std::string::npos) << other.output;
}

TEST(CompareCli, RenderOptionMistakes) {
  const auto& in = inputs();
  const std::string ab = in.a + " " + in.b + " --scale A=10 --scale B=5 ";
  const std::vector<BadCase> cases = {
      {"object zero", ab + "--object A=0", "--object A: expected an object id"},
      {"object text", ab + "--object B=bark", "--object B: expected an object id"},
      {"facing zero", ab + "--facing-deg A=0", "--facing-deg A: expected an angle in degrees in (0, 180]"},
      {"facing over", ab + "--facing-deg A=181", "in (0, 180]"},
      {"facing twice", ab + "--facing-deg A=20 --facing-deg A=30", "--facing-deg A: given twice"},
  };
  for (const BadCase& c : cases) {
    const auto r = test::run_phellem("compare " + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.name << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.name << ": wanted \"" << c.expect << "\"\n" << r.output;
  }
}

// The Poly Haven photos in ../shared/reference (outside the repository: skipped where absent):
// the colour photos are refused as height maps, naming --albedo; their scans are measured.
TEST(CompareCli, AColourPhotoIsNoHeightMap) {
  // The CC0 scans the repository carries (data/photos, copies of ../shared/reference/photos).
  const std::string photos = std::string(PHELLEM_SOURCE_DIR) + "/data/photos";
  ASSERT_TRUE(std::ifstream(photos + "/pine_bark_polyhaven.jpg")) << "no scans in " << photos;
  const std::string brown = photos + "/bark_brown_01_polyhaven", pine = photos + "/pine_bark_polyhaven";
  for (const std::string& photo : {brown + ".jpg", pine + ".jpg"}) {
    const auto r = test::run_phellem("compare " + photo + " " + brown + "_disp.jpg --scale A=10 --scale B=10");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: " + photo + ": is a colour photograph (chroma 0.", 0), 0u) << r.output;
    EXPECT_NE(r.output.find("--albedo A=" + photo), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("no --height option"), std::string::npos) << r.output;
  }
  const auto ok = test::run_phellem("compare " + brown + "_disp.jpg " + pine + "_disp.png --scale A=10 --scale B=10 --albedo A=" +
                                    brown + ".jpg --quiet");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

// The common-scale panels are drawn to scale: each figure's share of the row is its share of
// the two physical widths, and the sizes in cm are written under them.
TEST(CompareCli, CommonScalePanelsAreDrawnToScale) {
  const auto& in = inputs();
  const std::string narrow = in.dir + "/narrow.png";
  test::write_height_png16(narrow, test::fissured_bark(21, 40, 10, 6));  // 21 cm against A's 60
  const std::string html = in.dir + "/scaled.html";
  const auto r = test::run_phellem("compare " + in.a + " " + narrow + " --scale A=10 --scale B=10 -o " + html + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string page = test::read_text(html);
  const std::regex fig("<figure class=\"to-scale\" data-width-cm=\"([0-9.]+)\" style=\"flex:0 0 calc\\(\\(100% - 16px\\) \\* ([0-9.]+)\\)\">");
  std::vector<double> cm, share;
  for (auto it = std::sregex_iterator(page.begin(), page.end(), fig); it != std::sregex_iterator(); ++it) {
    cm.push_back(std::stod((*it)[1]));
    share.push_back(std::stod((*it)[2]));
  }
  ASSERT_EQ(cm.size(), 4u) << "heights and masks, A and B";
  for (size_t i = 0; i < 4; i += 2) {
    EXPECT_NEAR(cm[i], 60.0, 0.1);
    EXPECT_NEAR(cm[i + 1], 21.0, 0.1);
    EXPECT_NEAR(share[i] / share[i + 1], cm[i] / cm[i + 1], 1e-4);
    EXPECT_NEAR(share[i] + share[i + 1], 1.0, 1e-5);
  }
  EXPECT_NE(page.find("60.0 cm wide × 60.0 cm high"), std::string::npos);
  EXPECT_NE(page.find("21.0 cm wide × 40.0 cm high"), std::string::npos);
}

}  // namespace
}  // namespace phellem
