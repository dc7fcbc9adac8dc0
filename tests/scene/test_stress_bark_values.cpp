// Stress bark values that cannot mean anything are refused at their JSON paths: a crack
// whose minimum half-width exceeds its maximum, a negative stress magnitude (also a stroke's).
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parser.h"
#include "util/errors.h"

namespace phellem {
namespace {

std::string error_of(const std::string& bark) {
  try {
    parse_scene(R"({"objects": [{"type": "mesh", "procedural": {"shape": "sheet"}, "bark": )" + bark + "}]}", "scene.json", ".");
  } catch (const UserError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(StressBarkValues, MinWidthAboveMaxWidthIsRefused) {
  const auto msg = error_of(R"({"model": "stress", "crack": {"min_width": 0.01, "max_width": 0.002}})");
  EXPECT_NE(msg.find("scene.json: /objects/0/bark/crack/min_width: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("max_width"), std::string::npos) << msg;
  // Against the default max_width (0.006 m) too.
  const auto dflt = error_of(R"({"model": "stress", "crack": {"min_width": 0.01}})");
  EXPECT_NE(dflt.find("scene.json: /objects/0/bark/crack/min_width: "), std::string::npos) << dflt;
  EXPECT_EQ(error_of(R"({"model": "stress", "crack": {"min_width": 0.002, "max_width": 0.002}})"), "<no error>");
}

TEST(StressBarkValues, NegativeMagnitudeIsRefused) {
  const auto msg = error_of(R"({"model": "stress", "magnitude": -1})");
  EXPECT_NE(msg.find("scene.json: /objects/0/bark/magnitude: "), std::string::npos) << msg;
  EXPECT_EQ(error_of(R"({"model": "stress", "magnitude": 0})"), "<no error>");
  EXPECT_EQ(error_of(R"({"model": "stress", "magnitude": 2.5})"), "<no error>");
  // A stroke's magnitude too.
  const auto stroke = error_of(R"({"model": "stress", "strokes": [{"uv": [[0.1, 0.1], [0.9, 0.9]], "magnitude": -2}]})");
  EXPECT_NE(stroke.find("scene.json: /objects/0/bark/strokes/0/magnitude: "), std::string::npos) << stroke;
  EXPECT_EQ(error_of(R"({"model": "stress", "strokes": [{"uv": [[0.1, 0.1], [0.9, 0.9]], "magnitude": 3}]})"), "<no error>");
}

}  // namespace
}  // namespace phellem
