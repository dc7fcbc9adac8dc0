// `phellem compare --lit` as a user runs it: a plain height map needs its relief, lit-only
// options need --lit, the same bark at two scales looks the same, bark against noise differs,
// and the HTML report shows both renders at their true relative size, in a real browser.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "tests/support/height_fields.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

struct Inputs {
  std::string dir, a, b, noise, half;
};
const Inputs& inputs() {
  static const Inputs in = [] {
    Inputs i;
    i.dir = test::temp_dir("compare_lit_cli");
    i.a = i.dir + "/bark_a.png";
    i.b = i.dir + "/bark_b.png";
    i.noise = i.dir + "/noise.png";
    i.half = i.dir + "/bark_half.png";
    test::write_height_png16(i.a, test::fissured_bark(40, 40, 4, 5));
    test::write_height_png16(i.b, test::fissured_bark(40, 40, 4, 6));  // another piece of the same kind of bark
    test::write_height_png16(i.noise, test::smooth_noise(40, 40, 4, 3.0, 9));
    test::write_height_png16(i.half, test::fissured_bark(40, 20, 4, 7));  // half as high
    return i;
  }();
  return in;
}

const char* kRelief = " --relief A=0.01 --relief B=0.01 --spp 4";

TEST(CompareLitCli, APlainHeightMapNeedsItsRelief) {
  const auto& in = inputs();
  const auto r = test::run_phellem("compare --lit " + in.a + " " + in.b + " --scale A=4 --scale B=4 --relief B=0.01");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("phellem: error: <command line>: --relief A: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--relief A=METRES"), std::string::npos) << r.output;
}

TEST(CompareLitCli, LitOptionsNeedLit) {
  const auto& in = inputs();
  for (const std::string opt : {"--relief A=0.01", "--spp 4", "--no-sky"}) {
    const auto r = test::run_phellem("compare " + in.a + " " + in.b + " --scale A=4 --scale B=4 " + opt);
    EXPECT_EQ(r.exit_code, 2) << opt << ": " << r.output;
    EXPECT_NE(r.output.find("add --lit"), std::string::npos) << r.output;
  }
  for (const std::string bad : {"--relief A=0", "--relief A=nan", "--relief A=11", "--relief C=0.1", "--spp 0", "--spp 5000"}) {
    const auto r = test::run_phellem("compare --lit " + in.a + " " + in.b + " --scale A=4 --scale B=4 " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("phellem: error: <command line>: --"), std::string::npos) << bad << ": " << r.output;
  }
}

nlohmann::json lit_json(const std::string& a, const std::string& b, const std::string& name, const std::string& extra = "") {
  const std::string json = inputs().dir + "/" + name + ".json";
  const auto r = test::run_phellem("compare --lit " + a + " " + b + " --scale A=4 --scale B=4" + kRelief + " --json " + json +
                                   extra + " --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return nlohmann::json::parse(test::read_text(json), nullptr, false);
}

TEST(CompareLitCli, TwoPiecesOfOneBarkLookTheSameAndNoiseDiffers) {
  const auto& in = inputs();
  const auto same = lit_json(in.a, in.b, "same");
  ASSERT_TRUE(same.is_object());
  EXPECT_EQ(same["verdict"], "same look") << same["score"];
  const auto other = lit_json(in.a, in.noise, "other");
  ASSERT_TRUE(other.is_object());
  EXPECT_EQ(other["verdict"], "different") << other["score"];
  EXPECT_GT(other["score"].get<double>(), same["score"].get<double>() + 0.1);
  // Both renders are at the common scale, the patch's border pixel left out.
  EXPECT_EQ(same["inputs"]["A"]["width"], 158);
  EXPECT_EQ(same["rig"]["px_per_cm"], 4.0);
}

// The HTML shows each render at a width proportional to its size in centimetres, and a browser
// decodes both (and the difference view).
TEST(CompareLitCli, ReportShowsRendersAtTheirTrueRelativeSize) {
  const auto& in = inputs();
  const std::string html = in.dir + "/lit.html";
  const auto r = test::run_phellem("compare --lit " + in.a + " " + in.half + " --scale A=4 --scale B=4" + std::string(kRelief) +
                                   " -o " + html + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string text = test::read_text(html);
  std::regex size_re("class=\"render\"[^>]*|style=\"width:([0-9.]+)px;height:([0-9.]+)px\" class=\"render\"");
  std::vector<std::pair<double, double>> sizes;
  for (std::sregex_iterator it(text.begin(), text.end(), size_re), end; it != end; ++it)
    if ((*it)[1].matched) sizes.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  ASSERT_EQ(sizes.size(), 2u) << "two renders";
  EXPECT_DOUBLE_EQ(sizes[0].first, sizes[1].first);          // both 40 cm wide
  EXPECT_NEAR(sizes[1].second / sizes[0].second, 78.0 / 158.0, 1e-3);  // 20 cm against 40 cm high (minus the border)
  EXPECT_NE(text.find("id=\"verdict\""), std::string::npos);

  if (test::run_command("command -v chromium >/dev/null 2>&1").exit_code != 0) {
    if (std::getenv("CI")) FAIL() << "chromium is not installed but CI is set";
    GTEST_SKIP() << "chromium is not installed";
  }
  // Count the images that decoded, once the page has loaded, into the page's title.
  const std::string probe = in.dir + "/lit_probe.html";
  test::write_text(probe, text + "<script>window.addEventListener('load',()=>{let n=0;for(const i of document.images)"
                                 "if(i.complete&&i.naturalWidth>0)n++;document.title='decoded '+n+' of '+document.images.length;});</script>");
  const auto dom = test::run_command("timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run "
                                     "--user-data-dir=" + in.dir + "/profile --virtual-time-budget=5000 --dump-dom file://" + probe +
                                     " 2>/dev/null");
  EXPECT_NE(dom.output.find("<title>decoded 3 of 3</title>"), std::string::npos) << dom.output.substr(0, 400);
}

}  // namespace
}  // namespace phellem

namespace phellem {
namespace {

// --lights SCENE: the scene's own lights, the patch facing the scene's camera. A sun straight
// along the camera's axis casts no shadow the camera sees, so the darkest pixels are far less
// dark than under the rig's raking sun; a scene without lights, or with --no-sky, is refused.
TEST(CompareLitCli, TheScenesOwnLightsAndCamera) {
  const auto& in = inputs();
  const std::string head_on = in.dir + "/head_on.json", dark = in.dir + "/dark.json";
  test::write_text(head_on, R"({"camera": {"position": [3, 1, 0], "look_at": [0, 1, 0]},
    "lights": [{"type": "sun", "direction": [1, 0, 0], "irradiance": 3}]})");
  test::write_text(dark, R"({"camera": {"position": [0, 1, 3], "look_at": [0, 1, 0]}, "lights": []})");
  const auto rig = lit_json(in.a, in.a, "rig");
  const auto scene = lit_json(in.a, in.a, "scene", " --lights " + head_on);
  ASSERT_TRUE(rig.is_object() && scene.is_object());
  EXPECT_EQ(scene["rig"]["lights"], head_on);
  // P1 of ln Y − ln median: the darkest shadows, relative to the median.
  const double raking = rig["reference"]["statistics"]["log_luminance_p01"].get<double>();
  const double straight = scene["reference"]["statistics"]["log_luminance_p01"].get<double>();
  EXPECT_LT(raking, -0.5);
  EXPECT_GT(straight, 0.5 * raking) << "raking " << raking << ", straight " << straight;
  auto r = test::run_phellem("compare --lit " + in.a + " " + in.b + " --scale A=4 --scale B=4" + kRelief + " --lights " + dark);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("phellem: error: " + dark + ": /lights: the scene has no lights"), std::string::npos) << r.output;
  r = test::run_phellem("compare --lit " + in.a + " " + in.b + " --scale A=4 --scale B=4" + kRelief + " --lights " + head_on +
                        " --no-sky");
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

}  // namespace
}  // namespace phellem
