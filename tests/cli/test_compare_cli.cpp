// `phellem compare` as a user runs it: scores on synthetic bark with known answers, the JSON
// figures, and every documented error (exit 2, `phellem: error:`).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/height_fields.h"
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

}  // namespace
}  // namespace phellem
