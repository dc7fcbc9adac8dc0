// The bark look keys of issue 22 (scene/bark_look_keys.h, scene/bark_photo.h): every new key
// refused at its JSON path with its range, and a photo's colours split by its height map.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

using test::error_of;

std::string tree(const std::string& bark) {
  return R"({"objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 1, 0]], "radius": [0.1], "bark": )" + bark + "}]}";
}
std::string strips(const std::string& dressing) {
  return tree(R"({"model": "strips", "preset": "furrowed", "dressing": )" + dressing + "}");
}
std::string stress(const std::string& crack) {
  return tree(R"({"model": "stress", "crack": )" + crack + "}");
}

void expect_error(const std::string& json, const std::string& where, const std::string& what) {
  const std::string msg = error_of(json);
  EXPECT_NE(msg.find(where), std::string::npos) << msg;
  EXPECT_NE(msg.find(what), std::string::npos) << msg;
}

TEST(BarkLookKeys, StripReliefValuesAreCheckedAtTheirPath) {
  const std::string at = "/objects/0/bark/dressing/relief/";
  expect_error(strips(R"({"relief": {"depth_ratio": 0.1}})"), at + "depth_ratio", "[0.25, 20]");
  expect_error(strips(R"({"relief": {"depth_ratio": -1}})"), at + "depth_ratio", "must be > 0");
  expect_error(strips(R"({"relief": {"shoulder_width": 0}})"), at + "shoulder_width", "must be > 0");
  expect_error(strips(R"({"relief": {"detail": 1.5}})"), at + "detail", "must lie in [0, 1]");
  expect_error(strips(R"({"relief": {"detail_size": -0.1}})"), at + "detail_size", "must be > 0");
  expect_error(strips(R"({"relief": {"wall_noise": 2}})"), at + "wall_noise", "must lie in [0, 1]");
  expect_error(strips(R"({"relief": {"wall_size": 0}})"), at + "wall_size", "must be > 0");
  expect_error(strips(R"({"relief": {"walls": 0.1}})"), at + "walls", "unknown key");
  EXPECT_EQ(error_of(strips(R"({"relief": {}})")), "<no error>");
}

TEST(BarkLookKeys, RoughnessValuesAreCheckedAtTheirPath) {
  for (const std::string& json : {strips(R"({"roughness": %})"), stress(R"({"roughness": %})")}) {
    const std::string at = json.find("strips") != std::string::npos ? "/objects/0/bark/dressing/roughness/"
                                                                     : "/objects/0/bark/crack/roughness/";
    auto with = [&](const std::string& v) { return std::string(json).replace(json.find('%'), 1, v); };
    expect_error(with(R"({"ridge": 1.2})"), at + "ridge", "must lie in [0, 1]");
    expect_error(with(R"({"fissure": -0.2})"), at + "fissure", "must be >= 0");
    expect_error(with(R"({"noise": 3})"), at + "noise", "must lie in [0, 1]");
    // Stress bark's roughness noise follows its plates and cracks: no size of its own.
    expect_error(with(R"({"noise_size": 0})"), at + "noise_size",
                 json.find("strips") != std::string::npos ? "must be > 0" : "its size is crack.variation.size");
    expect_error(with(R"({"rough": 0.5})"), at + "rough", "unknown key");
    EXPECT_EQ(error_of(with("{}")), "<no error>");
  }
}

TEST(BarkLookKeys, StressReliefValuesAreCheckedAtTheirPath) {
  const std::string at = "/objects/0/bark/crack/relief/";
  expect_error(stress(R"({"relief": {"shoulder": 3}})"), at + "shoulder", "[0, 2]");
  expect_error(stress(R"({"relief": {"shoulder_width": -1}})"), at + "shoulder_width", "must be > 0");
  expect_error(stress(R"({"relief": {"detail": 2}})"), at + "detail", "must lie in [0, 1]");
  expect_error(stress(R"({"relief": {"detail_size": 0}})"), at + "detail_size", "must be > 0");
  expect_error(stress(R"({"relief": {"wall_noise": 1.5}})"), at + "wall_noise", "must lie in [0, 1]");
  expect_error(stress(R"({"relief": {"wall_size": 0}})"), at + "wall_size", "must be > 0");
  expect_error(stress(R"({"relief": {"depth_ratio": 1}})"), at + "depth_ratio", "unknown key");
  EXPECT_EQ(error_of(stress(R"({"relief": {}})")), "<no error>");
}

TEST(BarkLookKeys, StressVariationValuesAreCheckedAtTheirPath) {
  const std::string at = "/objects/0/bark/crack/variation/";
  expect_error(stress(R"({"variation": {"ridge": 1.5}})"), at + "ridge", "must lie in [0, 1]");
  expect_error(stress(R"({"variation": {"fissure": -0.1}})"), at + "fissure", "must be >= 0");
  expect_error(stress(R"({"variation": {"size": 0}})"), at + "size", "must be > 0");
  expect_error(stress(R"({"variation": {"size": 50}})"), at + "size", "[0.0001, 10] m");
  expect_error(stress(R"({"variation": {"plates": 1}})"), at + "plates", "unknown key");
  expect_error(stress(R"({"variation": 0.2})"), "/objects/0/bark/crack/variation", "object");
  EXPECT_EQ(error_of(stress(R"({"variation": {"ridge": 0.2, "fissure": 0, "size": 0.05}})")), "<no error>");
}

// An 8-bit sRGB albedo whose left half is red, right half blue, and a height map white on the
// left (ridges) and black on the right (fissures).
void write_photo(const std::string& dir, int w_albedo = 16) {
  auto write = [](const std::string& path, int w, int h, const std::vector<unsigned char>& px, int nc) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, nc, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
  };
  std::vector<unsigned char> albedo, height;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < w_albedo; ++x) {
      const bool high = x < w_albedo / 2;
      albedo.insert(albedo.end(), {static_cast<unsigned char>(high ? 200 : 0), 0, static_cast<unsigned char>(high ? 0 : 200)});
    }
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) height.push_back(x < 8 ? 255 : 0);
  write(dir + "/albedo.png", w_albedo, 16, albedo, 3);
  write(dir + "/height.png", 16, 16, height, 1);
}

TEST(BarkLookKeys, PhotoErrorsNameTheFileAndPath) {
  const std::string dir = test::temp_dir("bark_photo_errors");
  write_photo(dir, 12);
  auto error_in = [&](const std::string& json) {
    try {
      parse_scene(json, "scene.json", dir);
    } catch (const UserError& e) {
      return std::string(e.what());
    }
    return std::string("<no error>");
  };
  const std::string at = "/objects/0/bark/dressing/photo/";
  auto photo = [](const std::string& body) { return strips(R"({"photo": {)" + body + "}}"); };
  std::string msg = error_in(photo(R"("albedo": "albedo.png", "height": "height.png", "px_per_cm": 10)"));
  EXPECT_NE(msg.find(at + "height: the height map is 16×16, the albedo 12×16"), std::string::npos) << msg;
  msg = error_in(photo(R"("albedo": "nope.png", "height": "height.png", "px_per_cm": 10)"));
  EXPECT_NE(msg.find(at + "albedo: file not found"), std::string::npos) << msg;
  msg = error_in(photo(R"("albedo": "albedo.png", "height": "height.png")"));
  EXPECT_NE(msg.find(at), std::string::npos) << msg;
  EXPECT_NE(msg.find("px_per_cm"), std::string::npos) << msg;
  msg = error_in(photo(R"("albedo": "albedo.png", "height": "height.png", "px_per_cm": 0)"));
  EXPECT_NE(msg.find(at + "px_per_cm: must be > 0"), std::string::npos) << msg;
  msg = error_in(photo(R"("albedo": "albedo.png", "height": "height.png", "px_per_cm": 10, "ridge_above": 1.5)"));
  EXPECT_NE(msg.find(at + "ridge_above"), std::string::npos) << msg;
  msg = error_in(photo(R"("albedo": "albedo.png", "height": "height.png", "px_per_cm": 10, "fissure_below": 0.7)"));
  EXPECT_NE(msg.find(at + "fissure_below: fissure_below must be below ridge_above"), std::string::npos) << msg;
  msg = error_in(photo(R"("albedo": "albedo.png", "height": "height.png", "px_per_cm": 10, "tints": 5)"));
  EXPECT_NE(msg.find(at + "tints"), std::string::npos) << msg;
  msg = error_in(photo(R"("albedo": "albedo.png", "height": "height.png", "px_per_cm": 10, "hue": 1)"));
  EXPECT_NE(msg.find(at + "hue: unknown key"), std::string::npos) << msg;
  msg = error_in(stress(R"({"photo": {"albedo": "albedo.png", "height": "nope.png", "px_per_cm": 10}})"));
  EXPECT_NE(msg.find("/objects/0/bark/crack/photo/height: file not found"), std::string::npos) << msg;
}

TEST(BarkLookKeys, PhotoRidgesTakeTheHighPixelsAndFissuresTheLowOnes) {
  const std::string dir = test::temp_dir("bark_photo_colours");
  write_photo(dir);
  const SceneDesc s = parse_scene(
      strips(R"({"photo": {"albedo": "albedo.png", "height": "height.png", "px_per_cm": 4}})"), "scene.json", dir);
  const auto& c = s.objects.at(0).tree.strip_bark->colors;
  // sRGB 200/255 through OpenColorIO's sRGB texture transform: linear 0.578.
  EXPECT_NEAR(c.epidermis.base.x(), 0.578f, 5e-3f);
  EXPECT_NEAR(c.epidermis.base.z(), 0.0f, 1e-4f);
  EXPECT_NEAR(c.fracture.base.z(), 0.578f, 5e-3f);
  EXPECT_NEAR(c.fracture.base.x(), 0.0f, 1e-4f);
  EXPECT_FALSE(c.ridge_tints.empty());
  EXPECT_FALSE(c.fissure_tints.empty());
  const SceneDesc t = parse_scene(
      stress(R"({"photo": {"albedo": "albedo.png", "height": "height.png", "px_per_cm": 4}})"), "scene.json", dir);
  const CrackLook& l = t.objects.at(0).stress_bark->look;
  EXPECT_TRUE(l.colored);
  EXPECT_GT(l.ridge_color.x(), 0.5f);
  EXPECT_GT(l.fissure_color.z(), 0.5f);
  // Its patches' tints reach stress bark too; an explicit variation replaces them.
  EXPECT_EQ(l.ridge_tints.size(), c.ridge_tints.size());
  EXPECT_EQ(l.fissure_tints.size(), c.fissure_tints.size());
  const SceneDesc u = parse_scene(stress(R"({"photo": {"albedo": "albedo.png", "height": "height.png", "px_per_cm": 4},
                                            "variation": {"ridge": 0.25, "fissure": 0}})"),
                                  "scene.json", dir);
  const CrackLook& v = u.objects.at(0).stress_bark->look;
  ASSERT_EQ(v.ridge_tints.size(), 9u);  // a grey ramp 1 ± 0.25
  EXPECT_FLOAT_EQ(v.ridge_tints[0].x(), 0.75f);
  EXPECT_FLOAT_EQ(v.ridge_tints[4].y(), 1.0f);
  EXPECT_FLOAT_EQ(v.ridge_tints[8].z(), 1.25f);
  EXPECT_TRUE(v.fissure_tints.empty());
}

}  // namespace
}  // namespace phellem
